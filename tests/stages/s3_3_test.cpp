// Stage 3.3: rectangles collide with rectangles; with circles not yet.
#include <catch2/catch.hpp>

#include <optional>

#include "book_scene.h"
#include "circle.h"
#include "my_game.h"
#include "physics.h"
#include "rectangle.h"
#include "expect.h"
#include "near.h"
#include "stage_fixture.h"
#include "walkthrough.h"

namespace s3_3_test {

TEST_CASE("s3_3: a rectangle and a circle still report no collision") {
    const engine::Rectangle box({100, 100}, 40, 20);
    const engine::Circle ball({100, 100}, 10);
    // A circle at the rectangle's centre: 3.4 finds it, 3.3 must not yet.
    test::expectEqual("a collision of the rectangle with the circle (rectangle.collisionTest(circle)): none until 3.4",
                      false, box.collisionTest(ball).has_value());
    test::expectEqual("a collision of the circle with the rectangle (circle.collisionTest(rectangle)): none until 3.4",
                      false, ball.collisionTest(box).has_value());
    test::expectEqual("a collision the pass finds for the circle and the rectangle: none until 3.4", false,
                      engine::findCollision(ball, box).has_value());
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
    test::requireEqual("a collision of the two new rectangles (objects 5 and 6, 10 px apart, centre to centre)", true,
                       before.has_value());
    // Axis-aligned boxes side by side on one line: the normal is +x.
    CHECK_THAT(before->normal(), test::near(engine::Vec2{1, 0}, 1e-12));
    test::playScript(page, "6 e*3", 30);
    const auto after = info_of();
    test::requireEqual("a collision of the two rectangles once the second is turned by 0.3 rad", true,
                       after.has_value());
    // Turned by 0.3 rad, the second box reaches into the first with a corner: the line
    // (its start, its depth) is no longer the one before.
    INFO("the collision line before the turn: start "
         << Catch::Detail::stringify(before->start()) << ", depth " << before->depth() << "; after: start "
         << Catch::Detail::stringify(after->start()) << ", depth " << after->depth());
    test::expectEqual("the collision line (its start or its depth) changed by turning the second rectangle", true,
                      after->start() != before->start() || after->depth() != before->depth());
}

}  // namespace s3_3_test
