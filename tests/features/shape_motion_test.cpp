// move() and rotate() on both shapes, against positions worked out by hand
// (every stage from 2.2 on).
#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>

#include "circle.h"
#include "near.h"
#include "rectangle.h"

namespace shape_motion_test {

using engine::Vec2;

namespace {
constexpr double kPi = std::numbers::pi;
const double kRoot3 = std::sqrt(3.0);

void requireNear(Vec2 actual, Vec2 expected, double tolerance = 1e-12) {
    CHECK_THAT(actual, test::near(expected, tolerance));
}
}  // namespace

TEST_CASE("shape motion: a 40 x 20 rectangle turned by pi/6 about its centre") {
    engine::Rectangle box({100, 50}, 40, 20);
    box.rotate(kPi / 6);
    CHECK(box.angle() == kPi / 6);  // one turn, stored as given
    CHECK(box.center() == Vec2{100, 50});
    // Corner offsets (+-20, +-10) turned by 30 degrees: (x cos - y sin, x sin + y cos)
    // with cos = sqrt(3)/2 and sin = 1/2.
    requireNear(box.vertices()[0], {100 - 10 * kRoot3 + 5, 50 - 10 - 5 * kRoot3});
    requireNear(box.vertices()[1], {100 + 10 * kRoot3 + 5, 50 + 10 - 5 * kRoot3});
    requireNear(box.vertices()[2], {100 + 10 * kRoot3 - 5, 50 + 10 + 5 * kRoot3});
    requireNear(box.vertices()[3], {100 - 10 * kRoot3 - 5, 50 - 10 + 5 * kRoot3});
    // The normals (0,-1), (1,0), (0,1), (-1,0) turned by the same 30 degrees.
    requireNear(box.faceNormals()[0], {0.5, -kRoot3 / 2});
    requireNear(box.faceNormals()[1], {kRoot3 / 2, 0.5});
    requireNear(box.faceNormals()[2], {-0.5, kRoot3 / 2});
    requireNear(box.faceNormals()[3], {-kRoot3 / 2, -0.5});
}

TEST_CASE("shape motion: move shifts centre and corners and leaves the normals alone") {
    engine::Rectangle box({100, 50}, 40, 20);
    box.rotate(kPi / 6);
    const auto normals = box.faceNormals();
    box.move({3, -4});
    CHECK(box.center() == Vec2{103, 46});
    requireNear(box.vertices()[0], {103 - 10 * kRoot3 + 5, 46 - 10 - 5 * kRoot3});
    requireNear(box.vertices()[2], {103 + 10 * kRoot3 - 5, 46 + 10 + 5 * kRoot3});
    CHECK(box.faceNormals() == normals);
}

TEST_CASE("shape motion: normals stay unit length and square to their sides over 10,000 turns") {
    engine::Rectangle box({400, 225}, 120, 30);
    constexpr int kTurns = 10'000;
    constexpr double kStep = 0.001;
    for (int i = 0; i < kTurns; ++i) box.rotate(kStep);
    double worst_length = 0, worst_square = 0, worst_drift = 0;
    const engine::Rectangle once = [] {
        engine::Rectangle r({400, 225}, 120, 30);
        r.rotate(kTurns * kStep);
        return r;
    }();
    for (int i = 0; i < 4; ++i) {
        const Vec2 normal = box.faceNormals()[i];
        const Vec2 side = box.vertices()[(i + 1) % 4] - box.vertices()[i];
        worst_length = std::max(worst_length, std::abs(normal.length() - 1));
        worst_square = std::max(worst_square, std::abs(normal.dot(side.normalize())));
        worst_drift = std::max(worst_drift, box.vertices()[i].distance(once.vertices()[i]));
    }
    CHECK(worst_length < 1e-12);
    CHECK(worst_square < 1e-9);
    // 10,000 small turns land where one turn of 10 rad does, to well under a nanopixel.
    CHECK(worst_drift < 1e-9);
}

TEST_CASE("shape motion: a circle's reference point goes round its centre") {
    engine::Circle ball({10, 20}, 5);
    ball.rotate(kPi / 2);  // from straight above to the right: clockwise on screen
    requireNear(ball.startpoint(), {15, 20});
    ball.rotate(kPi / 2);  // pi in all: straight below
    requireNear(ball.startpoint(), {10, 25});
    CHECK(ball.angle() == kPi / 2 + kPi / 2);  // the two turns, added up
    CHECK(ball.center() == Vec2{10, 20});
    ball.move({-10, 5});
    requireNear(ball.startpoint(), {0, 30});
    CHECK(ball.center() == Vec2{0, 25});
}

}  // namespace shape_motion_test
