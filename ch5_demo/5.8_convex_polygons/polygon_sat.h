#pragma once
// Two convex polygons: the book's separating axis test with support points (chapter 3,
// "Rectangle Collisions"; rectangle_collision.cpp), for any number of sides, and the
// contact points of 5.4's clipping (contact_manifold.cpp), for any number of sides.
//
// The book's test needs nothing of the rectangle but its corners and face normals: a
// face's support point is the other polygon's corner deepest behind the face; a face
// with none behind it separates the two; otherwise the face whose support point is
// shallowest is the axis of least penetration. For two convex polygons the candidate
// axes are the face normals of both, and no others (the sides of A - B, gjk.h, are
// parallel to sides of A or of B), so the book's test finds the exact depth: a rectangle
// has four faces to try, an n-gon n.

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>

#include "convex_polygon.h"

namespace engine {

// The book's collision information, and which face it came from.
struct SatCollision {
    double depth = 0.0;           // px, > 0
    Vec2 normal;                  // unit, from A towards B
    Vec2 start;                   // the book's segment: from start, depth along the normal
    bool reference_is_b = false;  // the face is B's (its normal is then -normal)
    std::size_t face = 0;         // the face of least penetration: from its corner face to face + 1
};

// Nothing when a face of either separates them. Touching (a corner exactly on a face)
// is not colliding, as for the book's rectangles.
std::optional<SatCollision> satCollision(const ConvexPolygon& a, const ConvexPolygon& b);

// A contact point, as 5.4's ContactPoint: halfway between the outlines, with its depth
// and a key naming the features that made it (the same layout as 5.4's keys: bits 0-3
// the point's feature, 4-7 the incident face, 8-11 the reference face, bit 12 set when
// the reference face is B's). The feature is an incident corner, 0 to 7, or one of the
// reference face's side lines, kClippedAtStart or kClippedAtEnd, past the corners of
// any polygon. (5.4's rectangles name the incident face's end there instead, 0 or 1,
// contact_manifold.cpp; a polygon's point still names what made it.)
inline constexpr std::uint32_t kClippedAtStart = 8;
inline constexpr std::uint32_t kClippedAtEnd = 9;

struct PolygonContact {
    Vec2 position;
    double depth = 0.0;
    std::uint32_t key = 0;
};

struct PolygonManifold {
    Vec2 normal;  // unit, from A towards B
    std::array<PolygonContact, 2> points{};
    std::size_t count = 0;
};

// The contact points of two overlapping polygons (`collision` from satCollision): the
// incident face clipped by the reference face's side lines, each end behind the
// reference face a point. One or two points; if round-off leaves none, the middle of
// the book's segment stands in, as in 5.4.
PolygonManifold polygonManifold(const ConvexPolygon& a, const ConvexPolygon& b, const SatCollision& collision);

}  // namespace engine
