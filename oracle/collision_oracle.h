#pragma once
// An independent referee for the collision tests and the bench: how deep two shapes
// overlap, worked out the plain way, with nothing taken from the engine (not even its
// corners).
//
//   box - box      the projection form of the separating axis theorem: project all
//                  eight corners on the four side directions of both boxes; on each
//                  axis the overlap is the shorter of the two pushes that would part
//                  the shadows; the smallest overlap over the axes is the depth.
//   disc - box     the signed distance from the disc's centre to the box outline
//                  (point-to-polygon: nearest side segment outside, minus the nearest
//                  side line inside); depth = radius - that distance.
//   disc - disc    radii added up minus the distance between the centres.
//
// depth > 0: overlap by that much; depth == 0: touching; depth < 0: apart (for two
// boxes only the sign means anything then).

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <variant>

#include "vec2.h"

namespace oracle {

using lib::Vec2;

struct Box {
    Vec2 center;
    double width = 0;
    double height = 0;
    double angle = 0;  // radians, turned like the engine's rotate (clockwise on screen)
};

struct Disc {
    Vec2 center;
    double radius = 0;
};

using Shape = std::variant<Box, Disc>;

// The box's own x and y directions.
inline std::array<Vec2, 2> axes(const Box& box) {
    const double c = std::cos(box.angle);
    const double s = std::sin(box.angle);
    return {Vec2{c, s}, Vec2{-s, c}};
}

// Corners in order round the outline.
inline std::array<Vec2, 4> corners(const Box& box) {
    const auto [u, v] = axes(box);
    const Vec2 half_u = u * (box.width / 2);
    const Vec2 half_v = v * (box.height / 2);
    return {box.center - half_u - half_v, box.center + half_u - half_v, box.center + half_u + half_v,
            box.center - half_u + half_v};
}

struct Interval {
    double low;
    double high;
};

inline Interval shadow(const Box& box, Vec2 axis) {
    Interval result{std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()};
    for (Vec2 corner : corners(box)) {
        result.low = std::min(result.low, corner.dot(axis));
        result.high = std::max(result.high, corner.dot(axis));
    }
    return result;
}

inline double depth(const Box& a, const Box& b) {
    double smallest = std::numeric_limits<double>::infinity();
    for (const Box* owner : {&a, &b}) {
        for (Vec2 axis : axes(*owner)) {
            const Interval sa = shadow(a, axis);
            const Interval sb = shadow(b, axis);
            smallest = std::min(smallest, std::min(sa.high - sb.low, sb.high - sa.low));
        }
    }
    return smallest;
}

inline double segmentDistance(Vec2 p, Vec2 from, Vec2 to) {
    const Vec2 along = to - from;
    const double t = std::clamp((p - from).dot(along) / along.dot(along), 0.0, 1.0);
    return p.distance(from + along * t);
}

// Negative inside the box: minus the distance to the nearest side.
inline double signedDistance(Vec2 p, const Box& box) {
    const auto c = corners(box);
    bool inside = true;
    double outside_distance = std::numeric_limits<double>::infinity();
    double inside_distance = std::numeric_limits<double>::infinity();
    for (int i = 0; i < 4; ++i) {
        const Vec2 from = c[i];
        const Vec2 to = c[(i + 1) % 4];
        const Vec2 side = to - from;
        // The corners run one way round, so the inside is on the same side of every edge.
        const double signed_area = side.cross(p - from);
        if (signed_area < 0) inside = false;
        inside_distance = std::min(inside_distance, std::abs(signed_area) / side.length());
        outside_distance = std::min(outside_distance, segmentDistance(p, from, to));
    }
    return inside ? -inside_distance : outside_distance;
}

inline double depth(const Disc& disc, const Box& box) { return disc.radius - signedDistance(disc.center, box); }
inline double depth(const Box& box, const Disc& disc) { return depth(disc, box); }
inline double depth(const Disc& a, const Disc& b) { return a.radius + b.radius - a.center.distance(b.center); }

inline double depth(const Shape& a, const Shape& b) {
    return std::visit([](const auto& x, const auto& y) { return depth(x, y); }, a, b);
}

inline Vec2 center(const Shape& shape) {
    return std::visit([](const auto& s) { return s.center; }, shape);
}

inline Shape moved(Shape shape, Vec2 offset) {
    std::visit([offset](auto& s) { s.center += offset; }, shape);
    return shape;
}

}  // namespace oracle
