// Fuzz target: the narrow phase of 5.3 (circle_collision.cpp, rectangle_collision.cpp,
// the same files from 3.4 on) for two shapes a scene could give: circle-circle,
// rectangle-rectangle, rectangle-circle and circle-rectangle.
//
// Properties, whenever one shape's collisionTest(other) reports a collision:
//  - depth, normal and start are finite numbers (no NaN, no infinity);
//  - the normal has unit length (to kUnitTolerance);
//  - the depth is >= 0;
// and the two shapes agree: a.collisionTest(b) finds a collision exactly when
// b.collisionTest(a) does.
//
// How the input's bytes make two shapes (clang's FuzzedDataProvider, which takes
// integers from the end of the input; an input too short reads zeros):
//   shape A: centre x, centre y, kind (bool: circle or rectangle), size 1, size 2, angle
//   shape B: offset x, offset y, kind, size 1, size 2, angle; its centre is A's centre
//            plus the offset, so that the two shapes are near each other
// A circle's radius is size 1 (size 2 is read and left unused), a rectangle is
// size 1 wide and size 2 high; each shape is turned by its angle (rotate(angle), as a
// scene's "angle" is applied). Every number is
//   sign (bool), exponent e (integer from the range's smallest exponent, less one
//   when 0 may come up, to its largest), mantissa m (32 bits):
//   (-1)^sign * (1 + m / 2^32) * 2^e,  or 0 when e is below the smallest exponent,
// so that every scale in a range is tried as often as any other, and exact zeros,
// equal centres and equal sizes come up. The ranges (kCoordinates, kOffsets, kSizes,
// kAngles below) are the ones within which the engine keeps the properties; wider,
// this target finds each of these at once (the first two pinned by tests):
//  - a rectangle thinner than the spacing of doubles at its centre (1e-14 px wide at
//    x = 400.5, 9e-13 px at x = 6000) has both sides on one double and no side normal:
//    a circle beside it collides with normal (0, 0) (rectangle_circle_collision_test);
//  - centres under 1.5e-154 px apart but not equal (coordinates such as 3e-162):
//    the squares in length() are subnormal, and the normal is 0.95 long (vec2_test);
//  - magnitudes above 1e154 px: the squares overflow, length() is infinite and the
//    normal (0, 0).
// So a scene needs sizes with a floor and coordinates with a ceiling, far enough apart
// (sizes >= 1e-3 px and |coordinates| <= 1e6 px: a ratio of 1e-9, where 2^-52, 2e-16,
// breaks), and non-zero coordinates no smaller than about 1e-150 px.

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>

#include <fuzzer/FuzzedDataProvider.h>

#include "circle.h"
#include "fuzz_check.h"
#include "rectangle.h"

namespace {

using engine::Vec2;

// The magnitudes tried, as powers of two: the ranges a scene's numbers may take.
struct Magnitudes {
    int smallest_exponent;  // the smallest magnitude but 0 is 2^smallest_exponent
    int largest_exponent;   // every magnitude is below 2^(largest_exponent + 1)
    bool zero;              // 0 may come up too
};
// Centre coordinates 0 or from 2^-40 (9e-13) px to under 2^21 (2.1e6) px, the offset
// from A's centre to B's from 0 (the same centre) or 2^-40 px to as far as the centres
// go apart.
constexpr Magnitudes kCoordinates{-40, 20, true};
constexpr Magnitudes kOffsets{-40, 21, true};
// Sizes from 2^-10 (1e-3) px to under 2^21 (2.1e6) px.
constexpr Magnitudes kSizes{-10, 20, false};
// Angles 0 or from 2^-40 to under 2^41 (2.2e12) rad.
constexpr Magnitudes kAngles{-40, 40, true};

// normalize() divides by a rounded length: the result is within a few units in the
// last place of length 1.
constexpr double kUnitTolerance = 1e-12;

double number(FuzzedDataProvider& bytes, Magnitudes range) {
    const bool negative = bytes.ConsumeBool();
    const int exponent =
        bytes.ConsumeIntegralInRange(range.smallest_exponent - (range.zero ? 1 : 0), range.largest_exponent);
    const auto mantissa = bytes.ConsumeIntegral<std::uint32_t>();
    if (exponent < range.smallest_exponent) return 0.0;
    const double magnitude = std::ldexp(1.0 + std::ldexp(static_cast<double>(mantissa), -32), exponent);
    return negative ? -magnitude : magnitude;
}

double size(FuzzedDataProvider& bytes) { return std::abs(number(bytes, kSizes)); }

std::unique_ptr<engine::RigidShape> shape(FuzzedDataProvider& bytes, Vec2 center) {
    const bool circle = bytes.ConsumeBool();
    const double size1 = size(bytes);
    const double size2 = size(bytes);
    const double angle = number(bytes, kAngles);
    std::unique_ptr<engine::RigidShape> made;
    if (circle) {
        made = std::make_unique<engine::Circle>(center, size1);
    } else {
        made = std::make_unique<engine::Rectangle>(center, size1, size2);
    }
    made->rotate(angle);
    return made;
}

bool finite(Vec2 v) { return std::isfinite(v.x) && std::isfinite(v.y); }

std::string describe(const engine::RigidShape& a, const engine::RigidShape& b, const engine::CollisionInfo& info) {
    const auto shape_text = [](const engine::RigidShape& s) {
        char text[200];
        if (s.type() == engine::ShapeType::Circle) {
            std::snprintf(text, sizeof text, "circle center (%.17g, %.17g) radius %.17g angle %.17g", s.center().x,
                          s.center().y, static_cast<const engine::Circle&>(s).radius(), s.angle());
        } else {
            const auto& r = static_cast<const engine::Rectangle&>(s);
            std::snprintf(text, sizeof text, "rectangle center (%.17g, %.17g) %.17g x %.17g angle %.17g", r.center().x,
                          r.center().y, r.width(), r.height(), r.angle());
        }
        return std::string(text);
    };
    char result[200];
    std::snprintf(result, sizeof result, " -> depth %.17g normal (%.17g, %.17g) start (%.17g, %.17g)", info.depth(),
                  info.normal().x, info.normal().y, info.start().x, info.start().y);
    return "\n  " + shape_text(a) + "\n  " + shape_text(b) + "\n " + result;
}

void check(const engine::RigidShape& a, const engine::RigidShape& b, const engine::CollisionInfo& info) {
    const bool finite_numbers = std::isfinite(info.depth()) && finite(info.normal()) && finite(info.start());
    const bool unit_normal = std::abs(info.normal().length() - 1.0) <= kUnitTolerance;
    const bool not_negative = info.depth() >= 0.0;
    if (finite_numbers && unit_normal && not_negative) return;
    // Described only when a property fails: most inputs collide, and this is slow.
    const std::string shapes = describe(a, b, info);
    fuzz::require(finite_numbers, "depth, normal and start are finite", shapes.c_str());
    fuzz::require(unit_normal, "the normal has unit length", shapes.c_str());
    fuzz::require(not_negative, "the depth is >= 0", shapes.c_str());
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    FuzzedDataProvider bytes(data, size);
    const Vec2 center_a{number(bytes, kCoordinates), number(bytes, kCoordinates)};
    const auto a = shape(bytes, center_a);
    const Vec2 offset{number(bytes, kOffsets), number(bytes, kOffsets)};
    const auto b = shape(bytes, center_a + offset);

    const auto a_meets_b = a->collisionTest(*b);
    const auto b_meets_a = b->collisionTest(*a);
    if (a_meets_b) check(*a, *b, *a_meets_b);
    if (b_meets_a) check(*b, *a, *b_meets_a);
    fuzz::require(a_meets_b.has_value() == b_meets_a.has_value(), "both orders agree on a collision");
    return 0;
}
