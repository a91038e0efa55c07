// Stage 4.4: the book's scene turns its platform and gains a second one; collisions
// turn shapes.
#include <catch2/catch.hpp>

#include "book_scene.h"
#include "circle.h"
#include "my_game.h"
#include "platform_check.h"
#include "rectangle.h"
#include "world_fixture.h"

using engine::Vec2;

TEST_CASE("s4_4: the scene has two turned static platforms, kept by a reset") {
    // The book's MyGame.js order: the cursor, the two platforms, then the four borders.
    test::WorldFixture page(test::world(true));
    test::buildBookScene(page.core, page.random);
    REQUIRE(page.core.objectCount() == 7);
    REQUIRE(engine::UserControl::kKeptOnReset == 7);
    CHECK(page.core.object(0).center() == Vec2{400, 225});
    test::checkPlatform(page.core.object(1), {.center = {500, 200}, .angle = 3.0});
    test::checkPlatform(page.core.object(2), {.center = {200, 400}, .angle = 0.785, .friction = 1, .restitution = 0});
    test::checkBorders(page.core, 3);
}

TEST_CASE("s4_4: a circle dropped on the steep platform rolls down it") {
    test::WorldFixture page(test::world(true));
    test::buildBookScene(page.core, page.random);
    engine::Circle& ball = page.core.add(engine::Circle({150, 300}, 15));  // 21 px above it
    page.steps(600);
    // Down the slope is to the right and down on screen, and rolling that way turns the
    // circle clockwise on screen: a positive angular velocity.
    CHECK(ball.center().x > 160);
    CHECK(ball.velocity().x > 0);
    CHECK(ball.velocity().y > 0);
    CHECK(ball.angularVelocity() > 0);
}
