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
    test::StageFixture page;
    test::buildBookScene(page.core, page.random);
    page.frame();
    test::checkBorderCornersFound(page.core.physics().collisions());
}
