#pragma once
// A convex polygon as the engine keeps it: its corners counter-clockwise and, beside
// them, each face's outward unit normal, as rectangle.h keeps its four. Not in the book,
// whose shapes are the circle and the rectangle; its "Further Exploration" names GJK for
// "many-sided convex polygons", and this is the many-sided shape.
//
// Counter-clockwise means what it means for the cross product: going round, each
// corner lies a positive turn from the one before, cross(v1 - v0, v2 - v1) > 0, and the
// signed area is positive. The canvas's y axis points down, so on screen the same order
// looks clockwise: a rectangle's corners in rectangle.h's numbering (top-left,
// top-right, bottom-right, bottom-left) are in this order already.
//
// Face i runs from corner i to corner i + 1 (the last face back to corner 0), and
// normal i is square to it, pointing out: the edge (dx, dy) turned to (dy, -dx).

#include <array>
#include <cstddef>
#include <span>

#include "vec2.h"

namespace engine {

using lib::Vec2;

// The most corners a polygon may have. Box2D v3 stops at 8, and so do we, for three
// reasons: every polygon then fits in a fixed array (a value with no heap behind it,
// copied freely, like the rectangle's four corners); GJK and SAT visit every corner per
// support query, so their cost grows with the count and a cap bounds a step's work; and
// a shape with many more corners is better as a circle, which costs one point.
inline constexpr std::size_t kMaxPolygonVertices = 8;

struct ConvexPolygon {
    std::array<Vec2, kMaxPolygonVertices> vertices{};
    std::array<Vec2, kMaxPolygonVertices> normals{};  // normals[i] is face i's
    std::size_t count = 0;

    std::span<const Vec2> corners() const { return {vertices.data(), count}; }
    std::span<const Vec2> faceNormals() const { return {normals.data(), count}; }
    Vec2 corner(std::size_t i) const { return vertices[i % count]; }
};

// The polygon with these corners (convex, counter-clockwise, at most
// kMaxPolygonVertices: what convexHull returns), with its face normals. The normals are
// computed once here, not at every collision test, because a test asks for each of
// them, and a square root each time would cost more than the test's dot products.
inline ConvexPolygon makeConvexPolygon(std::span<const Vec2> ccw_corners) {
    ConvexPolygon polygon;
    polygon.count = ccw_corners.size();
    for (std::size_t i = 0; i < polygon.count; ++i) polygon.vertices[i] = ccw_corners[i];
    for (std::size_t i = 0; i < polygon.count; ++i) {
        const Vec2 edge = polygon.corner(i + 1) - polygon.corner(i);
        polygon.normals[i] = Vec2{edge.y, -edge.x}.normalize();
    }
    return polygon;
}

// The same polygon moved by `offset`: a rigid move leaves the normals as they are.
inline ConvexPolygon movedBy(ConvexPolygon polygon, Vec2 offset) {
    for (std::size_t i = 0; i < polygon.count; ++i) polygon.vertices[i] = polygon.vertices[i] + offset;
    return polygon;
}

}  // namespace engine
