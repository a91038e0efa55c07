#pragma once
// Random shapes for the collision tests, described for the oracle (collision_oracle.h)
// and built as engine shapes from the same numbers. The engine's own corners are never
// handed to the oracle: both sides start from centre, size and angle.

#include <cmath>
#include <cstdint>
#include <memory>
#include <numbers>
#include <random>
#include <utility>

#include "circle.h"
#include "collision_oracle.h"
#include "rectangle.h"

namespace test {

using lib::Vec2;

class RandomShapes {
public:
    explicit RandomShapes(std::uint64_t seed) : engine_(seed) {}

    double uniform(double low, double high) { return std::uniform_real_distribution<double>(low, high)(engine_); }
    // Spread evenly over the orders of magnitude, so 1 px and 300 px shapes are as common.
    double logUniform(double low, double high) { return std::exp(uniform(std::log(low), std::log(high))); }
    double anyAngle() { return uniform(0.0, 2.0 * std::numbers::pi); }
    Vec2 anyDirection() {
        const double a = anyAngle();
        return {std::cos(a), std::sin(a)};
    }

    oracle::Box box(Vec2 center, double smallest, double largest) {
        return {center, logUniform(smallest, largest), logUniform(smallest, largest), anyAngle()};
    }
    oracle::Disc disc(Vec2 center, double smallest, double largest) { return {center, logUniform(smallest, largest)}; }
    // A box with sides, or a disc with a diameter, from `smallest` to `largest`.
    oracle::Shape shape(bool is_box, Vec2 center, double smallest, double largest) {
        if (is_box) return box(center, smallest, largest);
        return disc(center, smallest / 2, largest / 2);
    }

    // Two shapes of sizes from kSmallest to kLargest px, the second centred anywhere
    // within 1.5 times the two bounding radii from the first: many pairs overlap, many
    // do not, and some lie one inside the other.
    std::pair<oracle::Shape, oracle::Shape> nearbyPair(bool first_is_box, bool second_is_box);

    static constexpr double kSmallest = 1.0;
    static constexpr double kLargest = 300.0;

private:
    std::mt19937_64 engine_;
};

inline std::unique_ptr<engine::RigidShape> build(const oracle::Shape& shape) {
    if (const auto* box = std::get_if<oracle::Box>(&shape)) {
        auto rectangle = std::make_unique<engine::Rectangle>(box->center, box->width, box->height);
        rectangle->rotate(box->angle);
        return rectangle;
    }
    const auto& disc = std::get<oracle::Disc>(shape);
    return std::make_unique<engine::Circle>(disc.center, disc.radius);
}

// The radius of a circle about the centre that holds the shape, worked out again here.
inline double reach(const oracle::Shape& shape) {
    if (const auto* box = std::get_if<oracle::Box>(&shape)) return std::hypot(box->width, box->height) / 2;
    return std::get<oracle::Disc>(shape).radius;
}

inline std::pair<oracle::Shape, oracle::Shape> RandomShapes::nearbyPair(bool first_is_box, bool second_is_box) {
    constexpr double kCanvas = 800.0;
    constexpr double kFarthest = 1.5;  // times the two reaches added up
    const oracle::Shape first = shape(first_is_box, {uniform(0, kCanvas), uniform(0, kCanvas)}, kSmallest, kLargest);
    oracle::Shape second = shape(second_is_box, oracle::center(first), kSmallest, kLargest);
    const double farthest = kFarthest * (reach(first) + reach(second));
    return {first, oracle::moved(second, anyDirection() * uniform(0, farthest))};
}

}  // namespace test
