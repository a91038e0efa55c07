#pragma once
// The convex hull of a scene's polygon vertices: the smallest convex polygon holding
// them all, its corners counter-clockwise (convex_polygon.h), whatever order or winding
// the scene lists them in. Not in the book.
//
// A scene may list a polygon's points in either winding, with a point inside or on a
// side; the hull keeps only the corners. What is not a polygon at all is refused with
// one line a scene reader can print after the key's path, as scene_io.cpp's number
// rules are ("<file>: bodies[3].vertices: <problem> (got <value>)"):
//   - fewer than 3 distinct points, or all of them on one line (no area: no mass to
//     spread, no inertia to divide by);
//   - two points closer than kHullTolerance (a vertex typed twice, or a side too short
//     to carry a face normal that means anything);
//   - more than kMaxPolygonVertices points;
//   - a coordinate that is not a finite number within kMaxHullCoordinate of the
//     body's centre.
// The refusal is a value (HullResult), not an exception: the hull builder is the
// engine's, and the scene reader decides how a refusal leaves the program.

#include <optional>
#include <span>
#include <string>

#include "convex_polygon.h"

namespace engine {

// How close two points may come, and how far off the line through its neighbours a
// corner must stand to count as a corner, px. Half the smallest size a scene accepts
// for a rectangle or a circle (0.01 px, scene_io.cpp's kSize), so the smallest
// rectangle a scene may hold, given as four points, is still a polygon. A point nearer
// than this to the line through its neighbours is dropped (it adds less than
// kHullTolerance to the outline); Box2D drops them in the same way, at 2 linear slops.
inline constexpr double kHullTolerance = 0.005;

// The largest coordinate a point may have, px from the body's centre: the largest size
// a scene accepts for a rectangle (1e5 px). It keeps the moment of inertia, m r^2, within
// scene_io.cpp's stated range and every cross product of two points far from overflow.
inline constexpr double kMaxHullCoordinate = 1e5;

// Either the hull, or why there is none (one line, no full stop).
struct HullResult {
    std::optional<ConvexPolygon> hull;
    std::string refusal;
};

HullResult convexHull(std::span<const Vec2> points);

}  // namespace engine
