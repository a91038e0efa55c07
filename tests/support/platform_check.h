#pragma once
// The book's platforms (4.3 on) are static rectangles: one check of a platform in a
// stage's scene against the numbers the book gives it, and one of the borders.

#include <catch2/catch.hpp>

#include <cstddef>

#include "core.h"
#include "rectangle.h"

namespace test {

struct Platform {
    lib::Vec2 center;
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

// The four borders of chapter 4's scene, 3 px thick along the canvas's edges, in the
// book's order (top, bottom, left, right), static, from object `first` on.
inline void checkBorders(const engine::Core& core, std::size_t first) {
    const struct {
        lib::Vec2 center;
        double width, height;
    } borders[] = {{{400, 0}, 800, 3}, {{400, 450}, 800, 3}, {{0, 225}, 3, 450}, {{800, 225}, 3, 450}};
    for (std::size_t k = 0; k < 4; ++k) {
        INFO("border " << k << ", object " << first + k);
        const engine::RigidShape& shape = core.object(first + k);
        REQUIRE(shape.type() == engine::ShapeType::Rectangle);
        const auto& border = static_cast<const engine::Rectangle&>(shape);
        CHECK(border.isStatic());
        CHECK(border.center() == borders[k].center);
        CHECK(border.width() == borders[k].width);
        CHECK(border.height() == borders[k].height);
    }
}

}  // namespace test
