// Rectangle and Circle as built, against corners and normals worked out by hand
// (every stage from 2.1 on).
#include <catch2/catch.hpp>

#include "circle.h"
#include "near.h"
#include "rectangle.h"
#include "shape_text.h"

namespace rigid_shape_test {

using engine::Vec2;

namespace {
void requireNear(Vec2 actual, Vec2 expected) { CHECK_THAT(actual, test::near(expected, 1e-12)); }
}  // namespace

TEST_CASE("rigid shape: a rectangle's corners run clockwise on screen from the top-left") {
    const engine::Rectangle box({100, 50}, 40, 20);
    CHECK(box.type() == engine::ShapeType::Rectangle);
    CHECK(box.center() == Vec2{100, 50});
    CHECK(box.width() == 40);
    CHECK(box.height() == 20);
    CHECK(box.angle() == 0);
    // Half sizes 20 x 10 about (100, 50); y grows downwards, so "top" is the smaller y.
    requireNear(box.vertices()[0], {80, 40});
    requireNear(box.vertices()[1], {120, 40});
    requireNear(box.vertices()[2], {120, 60});
    requireNear(box.vertices()[3], {80, 60});
}

TEST_CASE("rigid shape: a rectangle's face normals point out of top, right, bottom, left") {
    const engine::Rectangle box({-7.5, 3}, 2, 300);
    requireNear(box.faceNormals()[0], {0, -1});
    requireNear(box.faceNormals()[1], {1, 0});
    requireNear(box.faceNormals()[2], {0, 1});
    requireNear(box.faceNormals()[3], {-1, 0});
}

TEST_CASE("rigid shape: a circle's reference point starts straight above its centre") {
    const engine::Circle ball({10, 20}, 5);
    CHECK(ball.type() == engine::ShapeType::Circle);
    CHECK(ball.radius() == 5);
    requireNear(ball.center(), {10, 20});
    requireNear(ball.startpoint(), {10, 15});
}

TEST_CASE("rigid shape: a failing check prints shapes and vectors by their numbers, never {?}") {
    CHECK(Catch::Detail::stringify(Vec2{-0.6, -0.8}) == "(-0.6, -0.8)");
    const engine::Rectangle box({100, 50}, 40, 20);
    CHECK(Catch::Detail::stringify(box) == "rectangle 40 x 20 at (100, 50)");
    const engine::Circle ball({10, 20}, 5);
    CHECK(Catch::Detail::stringify(ball) == "circle of radius 5 at (10, 20)");
    // Through the base class too, as a test holding a scene's shapes sees them.
    const engine::RigidShape& shape = ball;
    CHECK(Catch::Detail::stringify(shape) == "circle of radius 5 at (10, 20)");
}

}  // namespace rigid_shape_test
