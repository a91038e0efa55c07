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
#include "shape_text.h"

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
// The parts one after the other (appended: g++ 12 warns wrongly about "a" + a temporary string).
template <typename... Parts>
std::string joined(const Parts&... parts) {
    std::string text;
    ((text += parts), ...);
    return text;
}

inline bool within(double actual, double expected) { return std::abs(actual - expected) <= kHandWorked; }
inline bool within(engine::Vec2 actual, engine::Vec2 expected) {
    return within(actual.x, expected.x) && within(actual.y, expected.y);
}
// "normal of R1 (radius 6): expected (-0.6, -0.8), got (0.6, 0.8)"
template <typename Value>
void checkQuantity(const std::source_location& where, const char* quantity, const std::string& case_name, Value actual,
                   Value expected) {
    const std::string text = joined(quantity, " of ", case_name, ": expected ", Catch::Detail::stringify(expected),
                                    ", got ", Catch::Detail::stringify(actual));
    checkedAt(where, quantity, within(actual, expected), text);
}
}  // namespace detail

// The collision found in the hand-worked case `case_name` has the expected depth,
// normal, start and end (each within kHandWorked). Each quantity is a check of its own,
// named with the case, and reported at the test's line.
inline void requireInfo(const std::string& case_name, const std::optional<engine::CollisionInfo>& found,
                        const ExpectedCollision& expected,
                        std::source_location where = std::source_location::current()) {
    checkedAt(where, "collision", found.has_value(), detail::joined(case_name, ": expected a collision, found none"),
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

namespace detail {
// "of random pair 17 (rectangle 20 x 10 at (1, 2) and circle of radius 4 at (3, 4))"
inline std::string pairName(const std::string& case_name, const engine::RigidShape& a, const engine::RigidShape& b) {
    return joined(" of ", case_name, " (", Catch::Detail::stringify(a), " and ", Catch::Detail::stringify(b), ")");
}
// A check on a random pair: its sentence is written only when it fails, as 40,000
// pairs pass every time.
template <typename Sentence>
void checkPairQuantity(const std::source_location& where, const char* quantity, bool passed, Sentence&& sentence) {
    checkedAt(where, quantity, passed, passed ? std::string() : sentence());
}
}  // namespace detail

// One pair through the engine's collision pass, judged against the oracle's exact depth;
// a failure names the quantity, the pair (`case_name`, both shapes) and the numbers, at
// `where`, the test's line.
inline Verdict checkPair(const oracle::Shape& a, const oracle::Shape& b, const std::string& case_name,
                         const std::source_location& where) {
    const double exact = oracle::depth(a, b);
    const double tolerance = kDepthTolerance * std::max(1.0, exact);
    const auto first = build(a), second = build(b);
    const auto found = engine::findCollision(*first, *second);
    if (std::abs(exact) <= tolerance) return Verdict::Borderline;
    const auto pair = [&] { return detail::pairName(case_name, *first, *second); };  // only for a failure
    const auto number = [](double value) { return browser::to_js_string(value); };
    const auto vector = [](engine::Vec2 v) { return Catch::Detail::stringify(v); };
    using detail::joined;
    if (exact < 0) {
        detail::checkPairQuantity(where, "collision", !found.has_value(), [&] {
            return joined("collision", pair(), ": expected none, as they are ", number(-exact), " px apart, found one");
        });
        return Verdict::Apart;
    }
    checkedAt(
        where, "collision", found.has_value(),
        found ? std::string() : joined("collision", pair(), ": expected one, ", number(exact), " px deep, found none"),
        true);
    const double depth = found->depth();
    const engine::Vec2 normal = found->normal();
    detail::checkPairQuantity(where, "depth", std::abs(depth - exact) <= tolerance, [&] {
        return joined("depth", pair(), ": expected ", number(exact), " (the oracle's), got ", number(depth));
    });
    detail::checkPairQuantity(where, "normal", std::abs(normal.length() - 1) <= 1e-12, [&] {
        return joined("normal", pair(), ": expected a unit vector, got ", vector(normal), ", ", number(normal.length()),
                      " long");
    });
    // The pass's normal points from the first shape to the second ...
    detail::checkPairQuantity(where, "normal", normal.dot(oracle::center(b) - oracle::center(a)) >= 0, [&] {
        return joined("normal", pair(), ": expected it to point from the first shape to the second, got ",
                      vector(normal));
    });
    // ... the segment runs from start along it for the depth ...
    const engine::Vec2 end = found->start() + normal * depth;
    detail::checkPairQuantity(where, "end", found->end().distance(end) <= 1e-12 * std::max(1.0, depth), [&] {
        return joined("end", pair(), ": expected start + normal * depth = ", vector(end), ", got ",
                      vector(found->end()));
    });
    // ... and moving the shapes apart by the depth along it leaves them just touching,
    // whether the second moves all the way or each moves half.
    const double second_moved = oracle::depth(a, oracle::moved(b, normal * depth));
    const double both_moved =
        oracle::depth(oracle::moved(a, normal * (-depth / 2)), oracle::moved(b, normal * (depth / 2)));
    const bool touching = std::abs(second_moved) <= tolerance && std::abs(both_moved) <= tolerance;
    detail::checkPairQuantity(where, "depth", touching, [&] {
        return joined("depth and normal", pair(), ": expected the shapes just touching once moved apart by them, got ",
                      number(second_moved), " px deep (the second moved) and ", number(both_moved),
                      " px (each moved half)");
    });
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

// `pairs` random pairs of the given kinds, each checked both ways round; a failure is
// reported at the test's line.
inline VerdictCount checkRandomPairs(std::uint64_t seed, int pairs, bool first_is_box, bool second_is_box,
                                     std::source_location where = std::source_location::current()) {
    RandomShapes random(seed);
    VerdictCount count;
    for (int k = 0; k < pairs; ++k) {
        const auto [a, b] = random.nearbyPair(first_is_box, second_is_box);
        const std::string name = detail::joined("random pair ", std::to_string(k));
        count.add(checkPair(a, b, name, where));
        count.add(checkPair(b, a, name + ", the other way round", where));
    }
    return count;
}

}  // namespace test
