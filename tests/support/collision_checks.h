#pragma once
// Checks for the collision tests: collision info against numbers worked out by hand
// (each quantity named with its case, at the test's line: checked_at.h),
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
#include <source_location>
#include <string>

#include "checked_at.h"
#include "collision_info.h"
#include "collision_oracle.h"
#include "near.h"
#include "number_format.h"
#include "physics.h"
#include "random_scene.h"

namespace Catch {
// "depth 1, normal (-0.6, -0.8), from (-9.4, -4.2) to (-10, -5)".
template <>
struct StringMaker<engine::CollisionInfo> {
    static std::string convert(const engine::CollisionInfo& info) {
        std::string text = "depth ";
        text += browser::to_js_string(info.depth());
        text += ", normal ";
        text += Detail::stringify(info.normal());
        text += ", from ";
        text += Detail::stringify(info.start());
        text += " to ";
        text += Detail::stringify(info.end());
        return text;
    }
};
}  // namespace Catch

namespace test {

// Hand-worked numbers hold to rounding: the shapes in those cases are tens of pixels.
inline constexpr double kHandWorked = 1e-12;

// What a hand-worked case expects: the collision info's four quantities.
struct ExpectedCollision {
    double depth;
    engine::Vec2 normal;
    engine::Vec2 start;
    engine::Vec2 end;
};

namespace detail {
inline bool within(double actual, double expected) { return std::abs(actual - expected) <= kHandWorked; }
inline bool within(engine::Vec2 actual, engine::Vec2 expected) {
    return within(actual.x, expected.x) && within(actual.y, expected.y);
}
// "normal of R1 (radius 6): expected (-0.6, -0.8), got (0.6, 0.8)"
template <typename Value>
void checkQuantity(const std::source_location& where, const char* quantity, const std::string& case_name, Value actual,
                   Value expected) {
    std::string text = quantity;
    text += " of ";
    text += case_name;
    text += ": expected ";
    text += Catch::Detail::stringify(expected);
    text += ", got ";
    text += Catch::Detail::stringify(actual);
    checkedAt(where, quantity, within(actual, expected), text);
}
}  // namespace detail

// The collision found in the hand-worked case `case_name` has the expected depth,
// normal, start and end (each within kHandWorked). Each quantity is a check of its own,
// named with the case, and reported at the test's line.
inline void requireInfo(const std::string& case_name, const std::optional<engine::CollisionInfo>& found,
                        const ExpectedCollision& expected,
                        std::source_location where = std::source_location::current()) {
    checkedAt(where, "collision", found.has_value(), case_name + std::string(": expected a collision, found none"),
              true);
    detail::checkQuantity(where, "depth", case_name, found->depth(), expected.depth);
    detail::checkQuantity(where, "normal", case_name, found->normal(), expected.normal);
    detail::checkQuantity(where, "start", case_name, found->start(), expected.start);
    detail::checkQuantity(where, "end", case_name, found->end(), expected.end);
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
