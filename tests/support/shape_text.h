#pragma once
// How Catch prints the engine's shapes: "rectangle 20 x 10 at (0, 0), turned 0.785 rad",
// "circle of radius 4 at (2, -8)", never {?}. Every stage from 2.1 has these members.

#include <catch2/catch.hpp>

#include <string>

#include "circle.h"
#include "near.h"  // Vec2's StringMaker
#include "number_format.h"
#include "rectangle.h"

namespace test::detail {
inline std::string placed(const engine::RigidShape& shape) {
    std::string text = " at ";
    text += Catch::Detail::stringify(shape.center());
    if (shape.angle() != 0) {
        text += ", turned ";
        text += browser::to_js_string(shape.angle());
        text += " rad";
    }
    return text;
}
}  // namespace test::detail

namespace Catch {
template <>
struct StringMaker<engine::Rectangle> {
    static std::string convert(const engine::Rectangle& box) {
        std::string text = "rectangle ";
        text += browser::to_js_string(box.width());
        text += " x ";
        text += browser::to_js_string(box.height());
        text += test::detail::placed(box);
        return text;
    }
};
template <>
struct StringMaker<engine::Circle> {
    static std::string convert(const engine::Circle& ball) {
        std::string text = "circle of radius ";
        text += browser::to_js_string(ball.radius());
        text += test::detail::placed(ball);
        return text;
    }
};
template <>
struct StringMaker<engine::RigidShape> {
    static std::string convert(const engine::RigidShape& shape) {
        if (shape.type() == engine::ShapeType::Rectangle) {
            return StringMaker<engine::Rectangle>::convert(static_cast<const engine::Rectangle&>(shape));
        }
        return StringMaker<engine::Circle>::convert(static_cast<const engine::Circle&>(shape));
    }
};
}  // namespace Catch
