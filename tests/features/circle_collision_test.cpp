// Collision info and the circle-circle test (every stage from 3.2 on), against cases
// worked out by hand, and against the oracle (collision_oracle.h) on random pairs.
#include <catch2/catch.hpp>

#include "circle.h"
#include "collision_checks.h"
#include "collision_info.h"
#include "expect.h"
#include "physics.h"

namespace circle_collision_test {

using engine::Vec2;
using test::requireInfo;

TEST_CASE("circle collision: collision info ends at start + normal * depth, changeDir turns it round") {
    engine::CollisionInfo info(2, {0.6, 0.8}, {11.8, 22.4});
    // end = (11.8, 22.4) + 2 (0.6, 0.8) = (13, 24)
    CHECK_THAT(info.end(), test::near(Vec2{13, 24}, test::kHandWorked));
    info.changeDir();
    // Same segment, other way round: start and end swap, the normal turns, depth stays.
    CHECK(info.depth() == 2);
    CHECK_THAT(info.normal(), test::near(Vec2{-0.6, -0.8}, test::kHandWorked));
    CHECK_THAT(info.start(), test::near(Vec2{13, 24}, test::kHandWorked));
    CHECK_THAT(info.end(), test::near(Vec2{11.8, 22.4}, test::kHandWorked));
    // A failing check prints it by its numbers.
    CHECK(Catch::Detail::stringify(engine::CollisionInfo(2, {0.6, 0.8}, {11.8, 22.4})) ==
          "depth 2, normal (0.6, 0.8), from (11.8, 22.4) to (13, 24)");
}

TEST_CASE("circle collision: circles apart report nothing") {
    // Centres 10 apart (6-8-10), radii 3 + 2 = 5.
    const engine::Circle a({0, 0}, 3), b({6, 8}, 2);
    CHECK_FALSE(a.collisionTest(b).has_value());
    CHECK_FALSE(b.collisionTest(a).has_value());
    CHECK_FALSE(engine::findCollision(a, b).has_value());
}

TEST_CASE("circle collision: circles exactly touching collide with depth 0") {
    // Centres 5 apart (3-4-5), radii 3 + 2 = 5: distance > radius sum fails, so the book
    // counts the touch. normal = (3, 4) / 5; start = c2 - normal * 2 = (3, 4) - (1.2, 1.6),
    // which is also c1 + normal * 3, the touching point; end = start.
    const engine::Circle a({0, 0}, 3), b({3, 4}, 2);
    requireInfo("circles touching", a.collisionTest(b), {0, {0.6, 0.8}, {1.8, 2.4}, {1.8, 2.4}});
}

TEST_CASE("circle collision: overlapping circles, from either side") {
    // c1 = (10, 20) r 5, c2 = (16, 28) r 7: centres 10 apart (6-8-10), radii add to 12,
    // so depth 2 along normal (6, 8) / 10 = (0.6, 0.8). The segment runs from c2's rim
    // nearest c1, c2 - 7 normal = (11.8, 22.4), to c1's rim, c1 + 5 normal = (13, 24).
    const engine::Circle a({10, 20}, 5), b({16, 28}, 7);
    requireInfo("overlapping circles, asked by the first", a.collisionTest(b), {2, {0.6, 0.8}, {11.8, 22.4}, {13, 24}});
    // Tested from c2: normal (-0.6, -0.8), from c1's rim c1 + 5 (0.6, 0.8) = (13, 24) to
    // c2's rim (11.8, 22.4).
    requireInfo("overlapping circles, asked by the second", b.collisionTest(a),
                {2, {-0.6, -0.8}, {13, 24}, {11.8, 22.4}});
    // The pass keeps each normal pointing from the first shape to the second.
    requireInfo("overlapping circles, the pass from the first", engine::findCollision(a, b),
                {2, {0.6, 0.8}, {11.8, 22.4}, {13, 24}});
    requireInfo("overlapping circles, the pass from the second", engine::findCollision(b, a),
                {2, {-0.6, -0.8}, {13, 24}, {11.8, 22.4}});
}

TEST_CASE("circle collision: circles with the same centre part straight up by both radii") {
    // c = (50, 50), radii 10 and 4: depth 10 + 4 = 14, normal (0, -1). Start at the
    // bottom of the larger circle, (50, 60); end 14 higher, (50, 46), the top of the
    // smaller one. Either way round the larger circle gives the start.
    const engine::Circle large({50, 50}, 10), small({50, 50}, 4);
    requireInfo("same centre, asked by the larger", large.collisionTest(small), {14, {0, -1}, {50, 60}, {50, 46}});
    requireInfo("same centre, asked by the smaller", small.collisionTest(large), {14, {0, -1}, {50, 60}, {50, 46}});
    // The centres give no direction, so the pass leaves the normal as it is.
    requireInfo("same centre, the pass from the smaller", engine::findCollision(small, large),
                {14, {0, -1}, {50, 60}, {50, 46}});
    // Equal radii 3: depth 6, from the bottom (50, 53) to the top (50, 47).
    requireInfo("same centre, equal radii", engine::Circle({50, 50}, 3).collisionTest(engine::Circle({50, 50}, 3)),
                {6, {0, -1}, {50, 53}, {50, 47}});
}

TEST_CASE("circle collision: 20,000 random pairs agree with the oracle") {
    const test::VerdictCount count = test::checkRandomPairs(32, 10'000, false, false);
    INFO("overlapping " << count.overlap << ", apart " << count.apart << ", borderline " << count.borderline);
    test::expectAtLeast("random pairs that overlap, of 20,000", 2'001, count.overlap);
    test::expectAtLeast("random pairs that are apart, of 20,000", 2'001, count.apart);
    test::expectAtMost("random pairs too close to call, of 20,000", 9, count.borderline);
}

TEST_CASE("circle collision: for two circles the broad phase is already exact") {
    test::RandomShapes random(33);
    for (int k = 0; k < 10'000; ++k) {
        const auto [a, b] = random.nearbyPair(false, false);
        const auto first = test::build(a), second = test::build(b);
        INFO("circles " << Catch::Detail::stringify(*first) << " and " << Catch::Detail::stringify(*second));
        test::expectEqual("the circle-circle test's verdict (collided or not): the bounding circles' (boundTest)",
                          first->boundTest(*second), first->collisionTest(*second).has_value());
    }
}

}  // namespace circle_collision_test
