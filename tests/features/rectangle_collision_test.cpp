// The rectangle-rectangle test, support-point SAT (every stage from 3.3 on), against
// cases worked out by hand and against the projection SAT of collision_oracle.h on
// random pairs of turned rectangles of very different sizes.
//
// In the hand-worked cases rectangle A's faces are tried first, then B's. For two
// rectangles turned alike both give the same depth, and on a tie B's answer wins: the
// normal is B's face normal turned round, the segment runs from B's face to A's corner.
#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>

#include "collision_checks.h"
#include "physics.h"
#include "rectangle.h"

namespace rectangle_collision_test {

using engine::Vec2;
using test::requireInfo;

namespace {

constexpr double kPi = std::numbers::pi;
const double kRoot2 = std::sqrt(2.0);
engine::Rectangle turned(Vec2 center, double width, double height, double angle) {
    engine::Rectangle box(center, width, height);
    box.rotate(angle);
    return box;
}

}  // namespace

TEST_CASE("rectangle collision: rectangles apart, or only touching, report nothing") {
    const engine::Rectangle a({0, 0}, 20, 10);
    CHECK_FALSE(a.collisionTest(engine::Rectangle({30, 0}, 20, 10)).has_value());  // 10 px gap
    // Side by side with x = 10 shared: every corner of B is on or in front of A's right
    // face, none behind it, so that face has no support point.
    const engine::Rectangle touching({20, 0}, 20, 10);
    CHECK_FALSE(a.collisionTest(touching).has_value());
    CHECK_FALSE(touching.collisionTest(a).has_value());
}

TEST_CASE("rectangle collision: a face of the second rectangle alone can separate them") {
    // A: corners (+-10, +-10). B: a 10 x 10 square turned by pi/4 about (16, 16), a
    // diamond with corners 5 sqrt 2 = 7.07 from its centre: (16, 8.93), (23.07, 16),
    // (16, 23.07), (8.93, 16). Its top and left corners poke behind A's bottom and right
    // faces, so all of A's faces have support points; but A's corner (10, 10) lies
    // (16 + 8.93 - 20) / sqrt 2 = 3.49 in front of B's upper-left face.
    const engine::Rectangle a({0, 0}, 20, 20);
    const engine::Rectangle b = turned({16, 16}, 10, 10, kPi / 4);
    CHECK_FALSE(a.collisionTest(b).has_value());
    CHECK_FALSE(b.collisionTest(a).has_value());
}

TEST_CASE("rectangle collision: axis-aligned overlap, from either side") {
    // A: x -10..10, y -5..5. B: 10 x 10 about (12, 3), so x 7..17, y -2..8.
    // Pushes that part them: right 10 - 7 = 3, down 5 + 2 = 7, up 8 + 5 = 13, left
    // 17 + 10 = 27. Least: 3 to the right, found on A's right face and on B's left face.
    // Tie: B's left face wins. Its normal (-1, 0), turned: (1, 0). Its support point is
    // A's first corner with x = 10, (10, -5); the segment runs from B's face, 3 to the
    // left, (7, -5), to that corner.
    const engine::Rectangle a({0, 0}, 20, 10), b({12, 3}, 10, 10);
    requireInfo("side by side, asked by A", a.collisionTest(b), {3, {1, 0}, {7, -5}, {10, -5}});
    // From B: A's right face wins the tie, support point B's first corner with x = 7,
    // (7, -2); normal (1, 0) turned to (-1, 0); from (10, -2) on A's face to (7, -2).
    requireInfo("side by side, asked by B", b.collisionTest(a), {3, {-1, 0}, {10, -2}, {7, -2}});
    requireInfo("side by side, the pass from B", engine::findCollision(b, a), {3, {-1, 0}, {10, -2}, {7, -2}});
}

TEST_CASE("rectangle collision: a turned square poking into a face") {
    // A: corners (+-10, +-10). B: a 10 x 10 square turned by pi/4 about (0, -14), a
    // diamond whose bottom corner is (0, -14 + 5 sqrt 2) = (0, -6.93): 5 sqrt 2 - 4 =
    // 3.07 behind A's top face (y = -10, normal (0, -1)). B's faces are all deeper: A's
    // corners lie 6 / sqrt 2 + 5 = 9.24 behind B's lower faces.
    const double depth = 5 * kRoot2 - 4;
    const Vec2 tip{0, -14 + 5 * kRoot2};
    const engine::Rectangle a({0, 0}, 20, 20);
    const engine::Rectangle b = turned({0, -14}, 10, 10, kPi / 4);
    // A's face wins: normal (0, -1) from A towards B, segment from B's corner up to A's face.
    requireInfo("the diamond poking in, asked by A", a.collisionTest(b), {depth, {0, -1}, tip, {0, -10}});
    // From B the same face is the other's, so its normal is turned: (0, 1), from B to A,
    // and the segment runs from A's face down to B's corner.
    requireInfo("the diamond poking in, asked by B", b.collisionTest(a), {depth, {0, 1}, {0, -10}, tip});
}

TEST_CASE("rectangle collision: one rectangle inside the other") {
    // A: corners (+-20, +-20). B: 10 x 6 about (5, 2), so x 0..10, y -1..5, inside A.
    // Pushes that part them: right 20 - 0 = 20, down 20 + 1 = 21, up 5 + 20 = 25, left
    // 10 + 20 = 30. Least: 20 to the right, a tie between A's right face and B's left.
    // B's left face wins, with A's first corner 20 behind it, (20, -20): the segment
    // runs from B's face line x = 0 to that corner.
    const engine::Rectangle a({0, 0}, 40, 40), b({5, 2}, 10, 6);
    requireInfo("one inside the other", a.collisionTest(b), {20, {1, 0}, {0, -20}, {20, -20}});
}

TEST_CASE("rectangle collision: two identical rectangles") {
    // 20 x 10 about (0, 0), twice. Every face of each has the other's far corners behind
    // it: 10 for top and bottom, 20 for left and right. The first least is the top face,
    // (0, -1), with the corner (10, 5) 10 behind it, and B's answer wins the tie: normal
    // (0, 1), from (10, 5) - 10 (0, 1) = (10, -5) to (10, 5). The centres are the same,
    // so the pass leaves it as it is.
    const engine::Rectangle a({0, 0}, 20, 10), b({0, 0}, 20, 10);
    requireInfo("two identical rectangles", a.collisionTest(b), {10, {0, 1}, {10, -5}, {10, 5}});
    requireInfo("two identical rectangles, the pass", engine::findCollision(a, b), {10, {0, 1}, {10, -5}, {10, 5}});
}

TEST_CASE("rectangle collision: 40,000 random turned pairs agree with the projection SAT") {
    const test::VerdictCount count = test::checkRandomPairs(34, 20'000, true, true);
    INFO("overlapping " << count.overlap << ", apart " << count.apart << ", borderline " << count.borderline);
    CHECK(count.overlap > 4'000);
    CHECK(count.apart > 4'000);
    CHECK(count.borderline < 10);
}

}  // namespace rectangle_collision_test
