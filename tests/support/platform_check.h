#pragma once
// The book's platforms (4.3 on) are static rectangles: one check of a platform in a
// stage's scene against the numbers the book gives it.

#include <catch2/catch.hpp>

#include "rectangle.h"

namespace test {

struct Platform {
    browser::Vec2 center;
    double width = 400;
    double height = 20;
    double angle = 0;
    double friction = 0.8;
    double restitution = 0.2;
};

inline void checkPlatform(const engine::RigidShape& shape, const Platform& expected) {
    REQUIRE(shape.type() == engine::ShapeType::Rectangle);
    const auto& platform = static_cast<const engine::Rectangle&>(shape);
    CHECK(platform.isStatic());
    CHECK(platform.center() == expected.center);
    CHECK(platform.width() == expected.width);
    CHECK(platform.height() == expected.height);
    CHECK(platform.angle() == expected.angle);
    CHECK(platform.friction() == expected.friction);
    CHECK(platform.restitution() == expected.restitution);
}

}  // namespace test
