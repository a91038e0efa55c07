#pragma once
// The distance between two convex shapes by GJK (Gilbert, Johnson and Keerthi, 1988),
// as Erin Catto teaches it in "Computing Distance" (GDC 2010). Not in the book, whose
// "Further Exploration" names it: "GJK provides more flexibility and performs
// collision detection for many-sided convex polygons."
//
// One idea carries it. The Minkowski difference A - B is the set of every a - b, a in
// A and b in B; it is convex when both shapes are. The shapes share a point exactly when
// A - B holds the origin, and otherwise their distance is the distance from the origin
// to A - B: its point nearest the origin is pA - pB, the closest points' difference.
// A - B has up to 8 x 8 candidate corners and is never built. GJK needs only its
// support point in a direction d, the point of A - B farthest along d, and that is A's
// farthest corner along d minus B's farthest along -d: 8 + 8 dot products.
//
// GJK keeps a simplex, 1 to 3 of those support points (a point, a segment, a
// triangle), and repeats: find the simplex's point nearest the origin; if the simplex
// holds the origin, the shapes overlap; otherwise ask for the support point in the
// direction from that nearest point towards the origin, and add it. The simplex creeps
// over A - B towards the origin and stops when the new point comes no nearer
// (gjk.cpp).
//
// Rounded shapes: each shape is a core (its corners) and a radius around it. A circle
// is one corner and its radius; a polygon or a rectangle its corners and radius 0. GJK
// measures the cores; the radii are taken off afterwards.

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "convex_polygon.h"

namespace engine {

// What GJK sees of a shape: up to kMaxPolygonVertices points (their convex hull is the
// core) and a radius.
struct ConvexProxy {
    std::array<Vec2, kMaxPolygonVertices> points{};
    std::size_t count = 0;
    double radius = 0.0;  // px
};

// A polygon or a rectangle: its corners, radius 0. A circle: its centre and radius. A
// segment: its two ends. At least one point, at most kMaxPolygonVertices.
ConvexProxy makeProxy(std::span<const Vec2> points, double radius = 0.0);

// One corner of the simplex: the support point w = a - b of A - B, with the corners of A
// and of B it came from (their index in their proxy) and its weight in the simplex's
// point nearest the origin (its barycentric coordinate).
struct SimplexVertex {
    Vec2 a;
    Vec2 b;
    Vec2 w;
    std::size_t index_a = 0;
    std::size_t index_b = 0;
    double weight = 0.0;
};

struct Simplex {
    std::array<SimplexVertex, 3> vertices{};
    std::size_t count = 0;
};

// Which corners made the last simplex: the next call on the same pair starts there. A
// shape moves little in one step, so the nearest features seldom change, and a call
// started on them often ends after its first support query instead of walking there
// again (the bench measures it; docs/polygons_geometry.md).
struct SimplexCache {
    std::array<std::uint8_t, 3> index_a{};
    std::array<std::uint8_t, 3> index_b{};
    std::size_t count = 0;  // 0: start afresh
};

struct DistanceResult {
    double distance = 0.0;  // px between the rounded outlines; 0 when they touch or overlap
    Vec2 point_a;           // the point of A nearest B (on A's rounded outline when apart)
    Vec2 point_b;           // the point of B nearest A
    Vec2 normal;            // unit, from A towards B; (0, 0) when the cores overlap
    int iterations = 0;     // support queries made
    Simplex simplex;        // the last simplex, in coordinates relative to A's first point
    Vec2 simplex_origin;    // that point: simplex coordinates + simplex_origin = canvas
    SimplexCache cache;     // the same corners, for the next call
};

// One pass of GJK's loop as the loop saw it: what a reader following the walk by hand
// writes down. The overlay draws a pair's walk from these (gjk_overlay.h), and the tests
// check them against hand calculations.
struct GjkStep {
    Simplex simplex;            // solved: cut to the feature nearest the origin, weighted
    Vec2 nearest;               // that feature's point nearest the origin: the weighted sum of w
    Vec2 direction;             // where the pass looked next, towards the origin (not unit)
    bool holds_origin = false;  // the simplex holds the origin: the walk ends, no query
    bool queried = false;       // the pass asked A - B for its support point in `direction`
    SimplexVertex support;      // that point, when queried
    bool kept = false;          // it came nearer and joined the simplex; if not, the walk ended
};

// With a `trace`, every pass is appended to it; the answer is the same with or without.
DistanceResult gjkDistance(const ConvexProxy& a, const ConvexProxy& b, const SimplexCache& start = {},
                           std::vector<GjkStep>* trace = nullptr);

// The overlap test: the rounded shapes touch or overlap exactly when their distance is 0.
inline bool gjkOverlap(const ConvexProxy& a, const ConvexProxy& b) { return gjkDistance(a, b).distance == 0.0; }

// The support point of A - B in `direction`, with the corners it came from, in
// coordinates relative to `origin` (GJK's simplex_origin). EPA grows its polygon with it.
SimplexVertex supportOfDifference(const ConvexProxy& a, const ConvexProxy& b, Vec2 direction, Vec2 origin);

// The support point of a proxy's core in `direction`: the index of its point farthest
// along it (the first of equals). GJK, EPA and the tests ask it the same way.
std::size_t supportIndex(const ConvexProxy& shape, Vec2 direction);

}  // namespace engine
