// The rectangle-circle test (every stage from 3.4 on): every region of Figure 3-17
// worked out by hand, random pairs against the point-to-polygon distance of
// collision_oracle.h, and, now that every pair of kinds has its exact test, a random
// scene on which the broad phase must pass every pair the narrow phase finds.
//
// The hand-worked cases use one rectangle: 20 x 10 about (0, 0), so
//   v0 (-10, -5)  face 0 top, normal (0, -1)      v1 (10, -5)
//   v3 (-10, 5)   face 2 bottom, normal (0, 1)    v2 (10, 5)
// with face 1 (right, normal (1, 0)) from v1 to v2 and face 3 (left, (-1, 0)) from v3
// to v0. A face's "distance" below is (centre - its first vertex) . its normal.
#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>
#include <vector>

#include "circle.h"
#include "collision_checks.h"
#include "physics.h"
#include "expect.h"
#include "rectangle.h"

namespace rectangle_circle_collision_test {

using engine::Vec2;
using test::requireInfo;

namespace {

// The rectangle's answer; the circle asked first must give the same.
std::optional<engine::CollisionInfo> collide(const engine::Rectangle& box, const engine::Circle& ball) {
    const auto from_box = box.collisionTest(ball);
    const auto from_ball = ball.collisionTest(box);
    INFO("the " << Catch::Detail::stringify(box) << " and the " << Catch::Detail::stringify(ball)
                << ": the circle's collisionTest hands the pair to the rectangle's, so both answer alike");
    test::expectEqual("a collision found by the circle's test: as by the rectangle's", from_box.has_value(),
                      from_ball.has_value());
    if (from_box && from_ball) {
        test::expectEqual("the depth by the circle's test, px: as by the rectangle's", from_box->depth(),
                          from_ball->depth());
        test::expectEqual("the normal by the circle's test: as by the rectangle's (from the rectangle to the circle)",
                          from_box->normal(), from_ball->normal());
        test::expectEqual("the start by the circle's test, px: as by the rectangle's", from_box->start(),
                          from_ball->start());
    }
    return from_box;
}

const engine::Rectangle kBox({0, 0}, 20, 10);

}  // namespace

TEST_CASE("rectangle circle collision: R3, straight in front of a face") {
    // Centre (2, -8): face 0's distance is -(-8 + 5) = 3 > 0, so face 0, outside.
    // Along the face, (12, -3) . (20, 0) > 0 and (-8, -3) . (-20, 0) > 0: neither end,
    // so R3. Radius 4 > 3: depth 1, normal (0, -1); from the rim (2, -8) + (0, 4) =
    // (2, -4) to the face, (2, -5).
    requireInfo("R3, in front of the top face (radius 4)", collide(kBox, engine::Circle({2, -8}, 4)),
                {1, {0, -1}, {2, -4}, {2, -5}});
    // Radius exactly 3: touching the face, and in R3 that is no collision (3 < 3 fails).
    CHECK_FALSE(collide(kBox, engine::Circle({2, -8}, 3)).has_value());
    CHECK_FALSE(collide(kBox, engine::Circle({2, -8}, 2)).has_value());
    // Centre (14, 2): face 0: -(2 + 5) = -7; face 1: 14 - 10 = 4 > 0, R3 of the right
    // face. Radius 5: depth 1, normal (1, 0), from (9, 2) to (10, 2).
    requireInfo("R3, in front of the right face", collide(kBox, engine::Circle({14, 2}, 5)),
                {1, {1, 0}, {9, 2}, {10, 2}});
}

TEST_CASE("rectangle circle collision: R1, past the corner where the face starts") {
    // Centre (-13, -9): face 0's distance is -(-9 + 5) = 4 > 0 (face 3's too, but face 0
    // comes first). (c - v0) . (v1 - v0) = (-3, -4) . (20, 0) = -60 < 0: R1, the corner
    // v0, 5 away (3-4-5). Radius 6: depth 1, normal (-0.6, -0.8); from the rim
    // c - 6 normal = (-9.4, -4.2) to the corner (-10, -5).
    requireInfo("the corner case R1 (radius 6)", collide(kBox, engine::Circle({-13, -9}, 6)),
                {1, {-0.6, -0.8}, {-9.4, -4.2}, {-10, -5}});
    // Radius exactly 5 touches the corner, and there that counts: depth 0 at v0.
    requireInfo("the corner case R1, touching (radius 5)", collide(kBox, engine::Circle({-13, -9}, 5)),
                {0, {-0.6, -0.8}, {-10, -5}, {-10, -5}});
    CHECK_FALSE(collide(kBox, engine::Circle({-13, -9}, 4.9)).has_value());
}

TEST_CASE("rectangle circle collision: R2, past the corner where the face ends") {
    // Centre (13, -9): face 0, distance 4. (c - v0) . (v1 - v0) = (23, -4) . (20, 0) > 0,
    // not R1; (c - v1) . (v0 - v1) = (3, -4) . (-20, 0) = -60 < 0: R2, the corner v1,
    // 5 away. Radius 6: depth 1, normal (0.6, -0.8), from (9.4, -4.2) to (10, -5).
    requireInfo("the corner case R2 of the top face", collide(kBox, engine::Circle({13, -9}, 6)),
                {1, {0.6, -0.8}, {9.4, -4.2}, {10, -5}});
    // Centre (13, 9): face 0: -(9 + 5) < 0; face 1: 13 - 10 = 3 > 0. Along face 1,
    // (c - v1) . (v2 - v1) = (3, 14) . (0, 10) > 0 and (c - v2) . (v1 - v2) =
    // (3, 4) . (0, -10) = -40 < 0: R2 of face 1, the corner v2. Radius 6: depth 1,
    // normal (0.6, 0.8), from (13, 9) - 6 (0.6, 0.8) = (9.4, 4.2) to (10, 5).
    requireInfo("the corner case R2 of the right face", collide(kBox, engine::Circle({13, 9}, 6)),
                {1, {0.6, 0.8}, {9.4, 4.2}, {10, 5}});
}

TEST_CASE("rectangle circle collision: centre inside, out through the nearest face") {
    // Centre (6, 1): distances -6 (top), -4 (right), -4 (bottom), -16 (left). The least
    // far behind is -4, right face first. Depth 2 - (-4) = 6, normal (1, 0): from the rim
    // (6, 1) - 2 (1, 0) = (4, 1) to (10, 1) on the right face.
    requireInfo("centre inside, nearest the right face", collide(kBox, engine::Circle({6, 1}, 2)),
                {6, {1, 0}, {4, 1}, {10, 1}});
    // A circle far larger than the rectangle, centred on it: nearest face top, 5 behind.
    requireInfo("a circle far larger than the rectangle", collide(kBox, engine::Circle({0, 0}, 100)),
                {105, {0, -1}, {0, 100}, {0, -5}});
}

TEST_CASE("rectangle circle collision: centre exactly on a face, exactly on a corner") {
    // Centre (3, -5) on the top face: distance 0 is not in front, so it counts as
    // inside, nearest the top face (0 beats -7, -10, -13). Radius 2: depth 2, normal
    // (0, -1), from (3, -3) to the centre (3, -5).
    requireInfo("centre on the top face", collide(kBox, engine::Circle({3, -5}, 2)), {2, {0, -1}, {3, -3}, {3, -5}});
    // Centre on v1 (10, -5): distance 0 from the top face and from the right face; the
    // top face comes first. Radius 3: depth 3, normal (0, -1), from (10, -2) to (10, -5).
    requireInfo("centre on the corner v1", collide(kBox, engine::Circle({10, -5}, 3)),
                {3, {0, -1}, {10, -2}, {10, -5}});
}

TEST_CASE("rectangle circle collision: a turned rectangle, and the pass's direction") {
    // The rectangle turned by pi/4: its top face normal is (sin, -cos)(pi/4) = n =
    // (1, -1) / sqrt 2. A circle of radius 4 centred 5 (half the height) + 3 along n
    // is 3 in front of that face: depth 1, from the rim 4 n to the face 5 n.
    engine::Rectangle box({0, 0}, 20, 10);
    box.rotate(std::numbers::pi / 4);
    const Vec2 n = Vec2{1, -1} * (1 / std::sqrt(2.0));
    const engine::Circle ball(n * 8, 4);
    requireInfo("the turned rectangle, asked by the rectangle", collide(box, ball), {1, n, n * 4, n * 5});
    // The raw normal points from the rectangle to the circle whichever asks; the pass
    // turns it to point from its first shape to its second.
    requireInfo("the turned rectangle, the pass from the rectangle", engine::findCollision(box, ball),
                {1, n, n * 4, n * 5});
    requireInfo("the turned rectangle, the pass from the circle", engine::findCollision(ball, box),
                {1, -n, n * 5, n * 4});
}

TEST_CASE("rectangle circle collision: 40,000 random pairs agree with the point-to-polygon distance") {
    const test::VerdictCount count = test::checkRandomPairs(35, 20'000, true, false);
    INFO("overlapping " << count.overlap << ", apart " << count.apart << ", borderline " << count.borderline);
    CHECK(count.overlap > 4'000);
    CHECK(count.apart > 4'000);
    CHECK(count.borderline < 10);
}

TEST_CASE("rectangle circle collision: the broad phase never drops a pair the narrow phase finds") {
    // 400 shapes of 1 px to 300 px anywhere on the canvas: every pair, both ways round.
    constexpr int kShapes = 400;
    test::RandomShapes random(36);
    std::vector<std::unique_ptr<engine::RigidShape>> scene;
    for (int k = 0; k < kShapes; ++k) {
        const Vec2 where{random.uniform(0, 800), random.uniform(0, 450)};
        scene.push_back(test::build(random.shape(k % 2 == 0, where, 1, 300)));
    }
    int narrow = 0, dropped = 0;
    for (const auto& a : scene) {
        for (const auto& b : scene) {
            if (a == b || !a->collisionTest(*b)) continue;
            ++narrow;
            dropped += !a->boundTest(*b);
        }
    }
    CHECK(narrow > 1'000);
    CHECK(dropped == 0);
}

TEST_CASE(
    "rectangle circle collision: a rectangle thinner than the spacing of doubles has no side normals "
    "(pinned, found by fuzz/)") {
    // 1e-14 px wide about x = 400.5, where doubles lie 2^-44 = 5.7e-14 apart: both
    // sides round to x = 400.5, each side's normal is the zero vector, and a circle
    // beside it is "inside", behind a face 0 px away. The collision has depth = radius
    // and no normal at all. Scene sizes need a floor relative to the coordinates for
    // this (sizes >= 1e-3 px with |coordinates| <= 1e6 px keep 9 digits to spare): see
    // fuzz/collision_fuzz.cpp.
    const engine::Rectangle sliver({400.5, 200}, 1e-14, 40);
    test::expectEqual("the sliver's right side x (vertex 1), px: rounded onto its left side's", sliver.vertices()[0].x,
                      sliver.vertices()[1].x);
    test::expectEqual("the sliver's face normal 1 (right): the zero vector, normalized from zero", Vec2{0, 0},
                      sliver.faceNormals()[1]);
    const auto info = sliver.collisionTest(engine::Circle({395, 200}, 10));
    test::requireEqual(
        "a collision of the sliver and a circle of radius 10 beside it: \"inside\", behind a face 0 px "
        "away",
        true, info.has_value());
    test::expectEqual("its depth, px: the radius", 10.0, info->depth());
    test::expectEqual("its normal: none, the zero vector", Vec2{0, 0}, info->normal());
}

}  // namespace rectangle_circle_collision_test
