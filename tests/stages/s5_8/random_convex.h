#pragma once
// What the polygon tests measure with, none of it from the code they judge:
//   - random convex shapes made without the hull builder: points at increasing angles on
//     a turned ellipse are in convex position, counter-clockwise, by construction;
//   - distances by brute force: two convex shapes that do not cross are as far apart as
//     their nearest corner-and-side pair (one corner of either, one side of the other);
//   - the exact penetration depth of two convex polygons: the least, over every face
//     normal of both, of how far the other's deepest corner lies behind that face (the
//     sides of A - B are parallel to A's and B's), worked out here in its own loop.

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <span>
#include <vector>

#include "random.h"
#include "vec2.h"

namespace test {

using lib::Vec2;

struct RandomShape {
    std::vector<Vec2> points;  // counter-clockwise; 1 point, 2 (a segment), or a convex polygon
    double radius = 0.0;
};

// `count` points in convex position round `center`: increasing angles, at least
// `min_gap` rad apart, on an ellipse of half-axes in [size / 4, size], turned at random.
inline std::vector<Vec2> randomConvex(browser::Random& random, std::size_t count, Vec2 center, double size) {
    const double semi_x = size * (0.25 + 0.75 * random.next());
    const double semi_y = size * (0.25 + 0.75 * random.next());
    const double turn = 2.0 * std::numbers::pi * random.next();
    // Angles: count slots round the circle, each point at a random place in its slot's
    // middle half, so neighbours are never nearly on top of each other.
    const double slot = 2.0 * std::numbers::pi / static_cast<double>(count);
    std::vector<Vec2> points;
    for (std::size_t i = 0; i < count; ++i) {
        const double angle = slot * (static_cast<double>(i) + 0.25 + 0.5 * random.next());
        const Vec2 on_ellipse{semi_x * std::cos(angle), semi_y * std::sin(angle)};
        points.push_back(center + on_ellipse.rotate(Vec2{}, turn));
    }
    return points;
}

// A random convex polygon of 3 to 8 corners, its centre anywhere in a `spread` x `spread`
// square, its size between 5 px and 5 + `most_size` px.
inline std::vector<Vec2> randomPolygon(browser::Random& random, double spread, double most_size) {
    const std::size_t count = 3 + static_cast<std::size_t>(random.next() * 6);
    const Vec2 center{spread * random.next(), spread * random.next()};
    return randomConvex(random, count, center, 5 + most_size * random.next());
}

inline double pointSegmentDistance(Vec2 p, Vec2 from, Vec2 to) {
    const Vec2 edge = to - from;
    const double length2 = edge.dot(edge);
    const double t = length2 > 0.0 ? std::clamp((p - from).dot(edge) / length2, 0.0, 1.0) : 0.0;
    return p.distance(from + edge * t);
}

// The sides of a shape: none for a point, one for a segment, n for a polygon.
inline std::vector<std::pair<Vec2, Vec2>> sidesOf(std::span<const Vec2> shape) {
    std::vector<std::pair<Vec2, Vec2>> sides;
    if (shape.size() == 2) sides.emplace_back(shape[0], shape[1]);
    if (shape.size() >= 3) {
        for (std::size_t i = 0; i < shape.size(); ++i) sides.emplace_back(shape[i], shape[(i + 1) % shape.size()]);
    }
    return sides;
}

// Inside or on a counter-clockwise polygon: on the left of (or on) every side.
inline bool inside(Vec2 p, std::span<const Vec2> polygon) {
    if (polygon.size() < 3) return false;
    for (const auto& [from, to] : sidesOf(polygon)) {
        if ((to - from).cross(p - from) < 0.0) return false;
    }
    return true;
}

inline double orientation(Vec2 a, Vec2 b, Vec2 c) { return (b - a).cross(c - a); }

inline bool segmentsCross(std::pair<Vec2, Vec2> s, std::pair<Vec2, Vec2> t) {
    const double o1 = orientation(s.first, s.second, t.first);
    const double o2 = orientation(s.first, s.second, t.second);
    const double o3 = orientation(t.first, t.second, s.first);
    const double o4 = orientation(t.first, t.second, s.second);
    return ((o1 <= 0 && o2 >= 0) || (o1 >= 0 && o2 <= 0)) && ((o3 <= 0 && o4 >= 0) || (o3 >= 0 && o4 <= 0)) &&
           !(o1 == 0 && o2 == 0 && o3 == 0 && o4 == 0);
}

// The distance from a point to a convex shape's core (0 inside).
inline double pointShapeDistance(Vec2 p, std::span<const Vec2> shape) {
    if (inside(p, shape)) return 0.0;
    double nearest = std::numeric_limits<double>::infinity();
    for (Vec2 corner : shape) nearest = std::min(nearest, p.distance(corner));
    for (const auto& [from, to] : sidesOf(shape)) nearest = std::min(nearest, pointSegmentDistance(p, from, to));
    return nearest;
}

// The distance between two convex cores by brute force: 0 when a side of one crosses a
// side of the other or a corner of one lies inside the other; otherwise the nearest
// corner of either to the other.
inline double bruteForceDistance(std::span<const Vec2> a, std::span<const Vec2> b) {
    for (Vec2 p : a) {
        if (inside(p, b)) return 0.0;
    }
    for (Vec2 p : b) {
        if (inside(p, a)) return 0.0;
    }
    for (const auto& s : sidesOf(a)) {
        for (const auto& t : sidesOf(b)) {
            if (segmentsCross(s, t)) return 0.0;
        }
    }
    double nearest = std::numeric_limits<double>::infinity();
    for (Vec2 p : a) nearest = std::min(nearest, pointShapeDistance(p, b));
    for (Vec2 p : b) nearest = std::min(nearest, pointShapeDistance(p, a));
    return nearest;
}

// How far the corners of `corners_of` go behind the face from `from` to `to`, with the
// face's outward normal (for a counter-clockwise polygon: the side turned to (dy, -dx)).
struct FaceDepth {
    double depth;
    Vec2 normal;
};
inline FaceDepth depthBehind(Vec2 from, Vec2 to, std::span<const Vec2> corners_of) {
    const Vec2 side = to - from;
    const Vec2 normal = Vec2{side.y, -side.x} * (1.0 / side.length());
    double depth = -std::numeric_limits<double>::infinity();
    for (Vec2 p : corners_of) depth = std::max(depth, (from - p).dot(normal));
    return {depth, normal};
}

// The exact penetration of two overlapping convex polygons: the least depth over the
// faces of both, with its normal from A towards B (a face of B's normal turned round).
inline FaceDepth exactPenetration(std::span<const Vec2> a, std::span<const Vec2> b) {
    FaceDepth least{std::numeric_limits<double>::infinity(), Vec2{}};
    for (const auto& [from, to] : sidesOf(a)) {
        const FaceDepth face = depthBehind(from, to, b);
        if (face.depth < least.depth) least = face;
    }
    for (const auto& [from, to] : sidesOf(b)) {
        const FaceDepth face = depthBehind(from, to, a);
        if (face.depth < least.depth) least = {face.depth, -face.normal};
    }
    return least;
}

}  // namespace test
