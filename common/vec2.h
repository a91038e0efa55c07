#pragma once
// Vec2: the book's small vector library (Lib/Vec2.js) as a value type. Every operation
// returns a new vector, as the JavaScript one does; operators are offered where they
// read like the math (a + b, a - b, v * s, -v).
//
// Coordinates are the canvas's: +x right, +y DOWN. So `rotate` by a positive angle,
// which is the ordinary math formula, looks clockwise on screen.
//
// Its namespace is the book's folder for it, Lib: shared math that the engine and the
// browser both use, and neither owns.

#include <cmath>

namespace lib {

struct Vec2 {
    double x = 0.0;
    double y = 0.0;

    constexpr Vec2() = default;
    constexpr Vec2(double x_, double y_) : x(x_), y(y_) {}

    double length() const { return std::sqrt(x * x + y * y); }

    constexpr Vec2 add(Vec2 v) const { return {x + v.x, y + v.y}; }
    constexpr Vec2 subtract(Vec2 v) const { return {x - v.x, y - v.y}; }
    constexpr Vec2 scale(double s) const { return {x * s, y * s}; }
    constexpr double dot(Vec2 v) const { return x * v.x + y * v.y; }

    // The z component of the 3D cross product (x, y, 0) x (v.x, v.y, 0): the signed area
    // of the parallelogram the two vectors span. Positive when v lies a positive
    // (on screen: clockwise) turn away from this vector.
    constexpr double cross(Vec2 v) const { return x * v.y - y * v.x; }

    // Turns this point about `center` by `angle` radians: translate the centre to the
    // origin, apply the rotation matrix [cos -sin; sin cos], translate back.
    Vec2 rotate(Vec2 center, double angle) const {
        const double c = std::cos(angle);
        const double s = std::sin(angle);
        const double dx = x - center.x;
        const double dy = y - center.y;
        return {dx * c - dy * s + center.x, dx * s + dy * c + center.y};
    }

    // Unit vector in the same direction; the zero vector has no direction and stays zero.
    Vec2 normalize() const {
        const double len = length();
        return len > 0.0 ? Vec2{x / len, y / len} : Vec2{};
    }

    double distance(Vec2 v) const { return subtract(v).length(); }

    friend constexpr Vec2 operator+(Vec2 a, Vec2 b) { return a.add(b); }
    friend constexpr Vec2 operator-(Vec2 a, Vec2 b) { return a.subtract(b); }
    friend constexpr Vec2 operator-(Vec2 v) { return {-v.x, -v.y}; }
    friend constexpr Vec2 operator*(Vec2 v, double s) { return v.scale(s); }
    friend constexpr Vec2 operator*(double s, Vec2 v) { return v.scale(s); }
    constexpr Vec2& operator+=(Vec2 v) { return *this = add(v); }
    constexpr Vec2& operator-=(Vec2 v) { return *this = subtract(v); }
    friend constexpr bool operator==(Vec2, Vec2) = default;
};

}  // namespace lib
