// Stage 3.3: rectangles collide with rectangles; with circles not yet.
#include <catch2/catch.hpp>

#include "book_scene.h"
#include "circle.h"
#include "my_game.h"
#include "physics.h"
#include "rectangle.h"
#include "stage_fixture.h"

TEST_CASE("s3_3: a rectangle and a circle still report no collision") {
    const engine::Rectangle box({100, 100}, 40, 20);
    const engine::Circle ball({100, 100}, 10);
    CHECK_FALSE(box.collisionTest(ball).has_value());
    CHECK_FALSE(ball.collisionTest(box).has_value());
    CHECK_FALSE(engine::findCollision(ball, box).has_value());
}

TEST_CASE("s3_3: the borders of the book's scene overlap at the four corners of the canvas") {
    // Top and bottom run 800 x 3 along y = 0 and 450, left and right 3 x 450 along x = 0
    // and 800: each corner is a 1.5 x 1.5 overlap, parted by 1.5 px either way.
    test::StageFixture page;
    test::buildBookScene(page.core, page.random);
    page.frame();
    const auto& found = page.core.physics().collisions();
    REQUIRE(found.size() == 4);
    const std::pair<std::size_t, std::size_t> corners[] = {{1, 3}, {1, 4}, {2, 3}, {2, 4}};
    for (std::size_t k = 0; k < 4; ++k) {
        CHECK(found[k].first == corners[k].first);
        CHECK(found[k].second == corners[k].second);
        CHECK(found[k].info.depth() == Approx(1.5));
    }
}
