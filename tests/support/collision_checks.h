#pragma once
// Checks for the collision tests: collision info against numbers worked out by hand,
// and one pair of shapes through the engine's collision pass step
// (engine::findCollision), judged against the oracle of collision_oracle.h.
//
// Exact touching is a borderline: the book's tests count it as a collision in some
// cases and not in others (see the hand-worked cases), and on random numbers which side
// of it a pair falls is decided by rounding. So pairs whose exact depth lies within the
// tolerance of zero may go either way; they are only counted.

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <optional>

#include "collision_oracle.h"
#include "near.h"
#include "physics.h"
#include "random_scene.h"

namespace test {

// Hand-worked numbers hold to rounding: the shapes in those cases are tens of pixels.
inline constexpr double kHandWorked = 1e-12;

inline void requireNear(engine::Vec2 actual, engine::Vec2 expected) {
    CHECK_THAT(actual, test::near(expected, kHandWorked));
}

inline void requireInfo(const std::optional<engine::CollisionInfo>& info, double depth, engine::Vec2 normal,
                        engine::Vec2 start, engine::Vec2 end) {
    REQUIRE(info.has_value());
    CHECK_THAT(info->depth(), test::near(depth, kHandWorked));
    requireNear(info->normal(), normal);
    requireNear(info->start(), start);
    requireNear(info->end(), end);
}

// Depths agree to this fraction of the depth, and to this many pixels below 1 px deep:
// corners a few hundred pixels from the origin carry rounding of about 1e-13 px.
inline constexpr double kDepthTolerance = 1e-9;

enum class Verdict { Overlap, Apart, Borderline };

inline Verdict checkPair(const oracle::Shape& a, const oracle::Shape& b) {
    const double exact = oracle::depth(a, b);
    const double tolerance = kDepthTolerance * std::max(1.0, exact);
    const auto found = engine::findCollision(*build(a), *build(b));
    if (std::abs(exact) <= tolerance) return Verdict::Borderline;
    INFO("exact depth " << exact);
    if (exact < 0) {
        CHECK_FALSE(found.has_value());
        return Verdict::Apart;
    }
    REQUIRE(found.has_value());
    const double depth = found->depth();
    const engine::Vec2 normal = found->normal();
    INFO("found depth " << depth << ", normal (" << normal.x << ", " << normal.y << ")");
    CHECK(std::abs(depth - exact) <= tolerance);
    CHECK(std::abs(normal.length() - 1) <= 1e-12);
    // The pass's normal points from the first shape to the second ...
    CHECK(normal.dot(oracle::center(b) - oracle::center(a)) >= 0);
    // ... the segment runs from start along it for the depth ...
    CHECK(found->end().distance(found->start() + normal * depth) <= 1e-12 * std::max(1.0, depth));
    // ... and moving the shapes apart by the depth along it leaves them just touching,
    // whether the second moves all the way or each moves half.
    CHECK(std::abs(oracle::depth(a, oracle::moved(b, normal * depth))) <= tolerance);
    CHECK(std::abs(oracle::depth(oracle::moved(a, normal * (-depth / 2)), oracle::moved(b, normal * (depth / 2)))) <=
          tolerance);
    return Verdict::Overlap;
}

struct VerdictCount {
    int overlap = 0;
    int apart = 0;
    int borderline = 0;
    void add(Verdict verdict) {
        if (verdict == Verdict::Overlap) ++overlap;
        if (verdict == Verdict::Apart) ++apart;
        if (verdict == Verdict::Borderline) ++borderline;
    }
};

// `pairs` random pairs of the given kinds, each checked both ways round.
inline VerdictCount checkRandomPairs(std::uint64_t seed, int pairs, bool first_is_box, bool second_is_box) {
    RandomShapes random(seed);
    VerdictCount count;
    for (int k = 0; k < pairs; ++k) {
        const auto [a, b] = random.nearbyPair(first_is_box, second_is_box);
        INFO("pair " << k);
        count.add(checkPair(a, b));
        count.add(checkPair(b, a));
    }
    return count;
}

}  // namespace test
