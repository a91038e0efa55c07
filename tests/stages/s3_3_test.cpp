// Stage 3.3: rectangles collide with rectangles; with circles not yet.
#include <catch2/catch.hpp>

#include <optional>

#include "book_scene.h"
#include "circle.h"
#include "my_game.h"
#include "physics.h"
#include "rectangle.h"
#include "near.h"
#include "stage_fixture.h"
#include "walkthrough.h"

namespace s3_3_test {

TEST_CASE("s3_3: a rectangle and a circle still report no collision") {
    const engine::Rectangle box({100, 100}, 40, 20);
    const engine::Circle ball({100, 100}, 10);
    CHECK_FALSE(box.collisionTest(ball).has_value());
    CHECK_FALSE(ball.collisionTest(box).has_value());
    CHECK_FALSE(engine::findCollision(ball, box).has_value());
}

TEST_CASE("s3_3: the borders of the book's scene overlap at the four corners of the canvas") {
    test::StageFixture page;
    test::buildBookScene(page.core, page.random);
    page.frame();
    test::checkBorderCornersFound(page.core.physics().collisions());
}

// The README's walkthrough ("Play it live"): two rectangles 10 px apart, then the
// second turned by 0.3 rad at frame 30.
TEST_CASE("s3_3: README walkthrough: the collision line of two rectangles follows a turn") {
    test::StageFixture page;
    test::buildBookScene(page.core, page.random);
    const auto info_of = [&page]() -> std::optional<engine::CollisionInfo> {
        for (const engine::Collision& pair : page.core.physics().collisions()) {
            if (pair.first == 5 && pair.second == 6) return pair.info;
        }
        return std::nullopt;
    };
    test::playScript(page, "f d f", 30);
    const auto before = info_of();
    REQUIRE(before.has_value());
    // Axis-aligned boxes side by side on one line: the normal is +x.
    CHECK_THAT(before->normal(), test::near(engine::Vec2{1, 0}, 1e-12));
    test::playScript(page, "6 e*3", 30);
    const auto after = info_of();
    REQUIRE(after.has_value());
    // Turned by 0.3 rad, the second box reaches into the first with a corner: the line
    // (its start, its depth) is no longer the one before.
    CHECK((after->start() != before->start() || after->depth() != before->depth()));
}

}  // namespace s3_3_test
