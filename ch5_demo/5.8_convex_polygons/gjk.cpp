// GJK's loop, and the heart of it: the point of a simplex nearest the origin, found by
// asking which Voronoi region of the simplex the origin lies in (Catto, GDC 2010).
//
// Voronoi regions. Every feature of a simplex (each corner, each side, the inside of a
// triangle) owns the region of the plane that lies nearer to it than to any other
// feature. The origin lies in exactly one of them, and that feature holds the nearest
// point: a corner itself, the foot of the perpendicular on a side, or the origin itself
// when it lies inside the triangle. The regions are told apart by signs, never by
// distances: beyond a segment's end or not is the sign of a dot product, which side
// of a segment the sign of a cross product.
//
// Barycentric coordinates. A point of segment w1 w2 is u w1 + v w2 with u + v = 1; for
// the foot of the perpendicular from the origin, v = -w1.e / e.e and u = w2.e / e.e (e =
// w2 - w1). A negative v says the origin lies beyond w1: w1's region. A negative u, beyond
// w2. For a triangle, each corner's coordinate is the signed area of the triangle the
// origin makes with the other two, over the whole area: all three positive, the origin is
// inside. The same numbers that choose the region weigh its nearest point, and, kept
// beside each support point, weigh A's and B's corners into the closest points pA and pB.
//
// When to stop. The nearest point v of the simplex gives the direction d = -v. The
// support point w in that direction is as near the origin as A - B reaches along d, so
// the distance lies between v.w/|v| and |v|. Three stops, each with the failure it
// prevents:
//   - the new support point was in the simplex already (same corners of A and of B): the
//     walk is over, and adding it again would loop for ever (the duplicate check);
//   - it comes no nearer than the simplex, |v| - v.w/|v| within round-off: a second
//     point on the same side of A - B, which would make a flat triangle (the progress check);
//   - kMaxGjkIterations support queries: a guard against cycling on round-off; the
//     answer so far is returned (its distance bounds are still right, only looser).
// The simplex holds the origin when the origin lies inside its triangle, or within
// round-off of its side or corner: then the shapes touch or overlap. That last test is
// relative to the shapes' size: an absolute one misjudges small shapes (Box2D's short-edge
// case, tested in gjk_test.cpp: a plank 0.1 px thick, a point 0.15 px off its end).

#include "gjk.h"

#include <algorithm>
#include <cmath>

namespace engine {

namespace {

// Box2D's cap. Polygons of 8 corners each give A - B at most 16 corners, and the walk
// visits each at most once, so 20 queries are never the limit for a real walk (the
// bench prints the most a pair took).
constexpr int kMaxGjkIterations = 20;
// Round-off, relative to the shapes' size: a double carries 16 digits, and the sums and
// products below lose a few. Nearer to the origin than this, a simplex touches it.
constexpr double kRoundOff = 1e-13;

// The proxies moved so that A's first point is the origin: coordinates the shapes' own
// size, whatever their place on the canvas, so round-off is the shapes' size too.
struct LocalShapes {
    std::array<Vec2, kMaxPolygonVertices> a{};
    std::array<Vec2, kMaxPolygonVertices> b{};
    std::size_t count_a = 0;
    std::size_t count_b = 0;
    double size = 0.0;  // the largest distance of a point from the new origin
};

LocalShapes localShapes(const ConvexProxy& a, const ConvexProxy& b, Vec2 origin) {
    LocalShapes local{.count_a = a.count, .count_b = b.count};
    for (std::size_t i = 0; i < a.count; ++i) local.a[i] = a.points[i] - origin;
    for (std::size_t i = 0; i < b.count; ++i) local.b[i] = b.points[i] - origin;
    for (std::size_t i = 0; i < a.count; ++i) local.size = std::max(local.size, local.a[i].length());
    for (std::size_t i = 0; i < b.count; ++i) local.size = std::max(local.size, local.b[i].length());
    return local;
}

std::size_t farthestAlong(std::span<const Vec2> points, Vec2 direction) {
    std::size_t best = 0;
    for (std::size_t i = 1; i < points.size(); ++i) {
        if (points[i].dot(direction) > points[best].dot(direction)) best = i;
    }
    return best;
}

// The support point of A - B in `direction`: A's farthest corner along it, minus B's
// farthest along the opposite.
SimplexVertex supportOf(const LocalShapes& shapes, Vec2 direction) {
    SimplexVertex v;
    v.index_a = farthestAlong({shapes.a.data(), shapes.count_a}, direction);
    v.index_b = farthestAlong({shapes.b.data(), shapes.count_b}, -direction);
    v.a = shapes.a[v.index_a];
    v.b = shapes.b[v.index_b];
    v.w = v.a - v.b;
    return v;
}

// What solving a simplex tells the loop: where to look next (towards the origin, from
// the nearest point), and whether the simplex already holds the origin.
struct Nearest {
    Vec2 toward_origin;  // not unit; its length means nothing for a side
    bool holds_origin = false;
};

Vec2 leftNormal(Vec2 v) { return {-v.y, v.x}; }

Nearest keepCorner(Simplex& simplex, std::size_t i, double touching) {
    simplex.vertices[0] = simplex.vertices[i];
    simplex.vertices[0].weight = 1.0;
    simplex.count = 1;
    const Vec2 w = simplex.vertices[0].w;
    return {-w, w.length() <= touching};
}

// The side from corner i to corner j, whose region holds the origin; u and v are the
// unnormalised barycentric coordinates of the foot of the perpendicular (u for i).
Nearest keepSide(Simplex& simplex, std::size_t i, std::size_t j, double u, double v, double touching) {
    const SimplexVertex first = simplex.vertices[i];
    const SimplexVertex second = simplex.vertices[j];
    simplex.vertices[0] = first;
    simplex.vertices[1] = second;
    simplex.vertices[0].weight = u / (u + v);
    simplex.vertices[1].weight = v / (u + v);
    simplex.count = 2;
    // The direction is the side's normal on the origin's side, not -(u w1 + v w2): that
    // sum loses the digits the two nearly opposite terms share, the normal loses none.
    const Vec2 side = second.w - first.w;
    const double origin_side = side.cross(-first.w);  // > 0: the origin is left of the side
    const double off_line = std::abs(origin_side) / side.length();
    const Vec2 normal = origin_side >= 0.0 ? leftNormal(side) : -leftNormal(side);
    return {normal, off_line <= touching};
}

// A segment's two corner regions and its side's (the file's header).
Nearest solveSegment(Simplex& simplex, double touching) {
    const Vec2 w1 = simplex.vertices[0].w;
    const Vec2 w2 = simplex.vertices[1].w;
    const Vec2 side = w2 - w1;
    const double v = -w1.dot(side);  // the weight of w2, times side.side
    const double u = w2.dot(side);   // the weight of w1, times side.side
    if (v <= 0.0) return keepCorner(simplex, 0, touching);
    if (u <= 0.0) return keepCorner(simplex, 1, touching);
    return keepSide(simplex, 0, 1, u, v, touching);
}

// A triangle's seven regions: three corners, three sides, the inside. A side's region
// needs both its barycentric coordinates positive (the foot falls on the side) and the
// origin outside the triangle across that side (the third corner's triangle coordinate
// not positive).
Nearest solveTriangle(Simplex& simplex, double touching) {
    const Vec2 w1 = simplex.vertices[0].w;
    const Vec2 w2 = simplex.vertices[1].w;
    const Vec2 w3 = simplex.vertices[2].w;
    const Vec2 e12 = w2 - w1;
    const Vec2 e13 = w3 - w1;
    const Vec2 e23 = w3 - w2;
    const double u12 = w2.dot(e12), v12 = -w1.dot(e12);
    const double u13 = w3.dot(e13), v13 = -w1.dot(e13);
    const double u23 = w3.dot(e23), v23 = -w2.dot(e23);
    // Each corner's triangle coordinate: the area of the triangle the origin makes with
    // the other two corners, signed so that it is positive when the origin is inside.
    const double area = e12.cross(e13);
    const double t1 = area * w2.cross(w3);
    const double t2 = area * w3.cross(w1);
    const double t3 = area * w1.cross(w2);

    if (v12 <= 0.0 && v13 <= 0.0) return keepCorner(simplex, 0, touching);
    if (u12 <= 0.0 && v23 <= 0.0) return keepCorner(simplex, 1, touching);
    if (u13 <= 0.0 && u23 <= 0.0) return keepCorner(simplex, 2, touching);
    if (u12 > 0.0 && v12 > 0.0 && t3 <= 0.0) return keepSide(simplex, 0, 1, u12, v12, touching);
    if (u13 > 0.0 && v13 > 0.0 && t2 <= 0.0) return keepSide(simplex, 0, 2, u13, v13, touching);
    if (u23 > 0.0 && v23 > 0.0 && t1 <= 0.0) return keepSide(simplex, 1, 2, u23, v23, touching);
    const double sum = t1 + t2 + t3;
    if (sum <= 0.0) {
        // Three support points on one line (a flat triangle has no inside) that none of
        // the tests above placed, as round-off can leave them: keep the two farthest
        // apart, the segment that covers the third, and solve it as a segment.
        const double d12 = e12.dot(e12), d13 = e13.dot(e13), d23 = e23.dot(e23);
        if (d13 >= d12 && d13 >= d23) simplex.vertices[1] = simplex.vertices[2];
        if (d23 > d12 && d23 > d13) simplex.vertices[0] = simplex.vertices[2];
        simplex.count = 2;
        return solveSegment(simplex, touching);
    }
    simplex.vertices[0].weight = t1 / sum;
    simplex.vertices[1].weight = t2 / sum;
    simplex.vertices[2].weight = t3 / sum;
    return {Vec2{}, true};
}

Nearest solve(Simplex& simplex, double touching) {
    if (simplex.count == 1) return keepCorner(simplex, 0, touching);
    if (simplex.count == 2) return solveSegment(simplex, touching);
    return solveTriangle(simplex, touching);
}

Simplex simplexFrom(const SimplexCache& cache, const LocalShapes& shapes) {
    Simplex simplex;
    for (std::size_t i = 0; i < cache.count; ++i) {
        if (cache.index_a[i] >= shapes.count_a || cache.index_b[i] >= shapes.count_b) return simplexFrom({}, shapes);
        SimplexVertex& v = simplex.vertices[i];
        v.index_a = cache.index_a[i];
        v.index_b = cache.index_b[i];
        v.a = shapes.a[v.index_a];
        v.b = shapes.b[v.index_b];
        v.w = v.a - v.b;
    }
    simplex.count = cache.count;
    if (simplex.count == 0) {
        simplex.vertices[0] = {shapes.a[0], shapes.b[0], shapes.a[0] - shapes.b[0], 0, 0, 1.0};
        simplex.count = 1;
    }
    return simplex;
}

bool alreadyIn(const Simplex& simplex, const SimplexVertex& v) {
    for (std::size_t i = 0; i < simplex.count; ++i) {
        if (simplex.vertices[i].index_a == v.index_a && simplex.vertices[i].index_b == v.index_b) return true;
    }
    return false;
}

SimplexCache cacheOf(const Simplex& simplex) {
    SimplexCache cache;
    cache.count = simplex.count;
    for (std::size_t i = 0; i < simplex.count; ++i) {
        cache.index_a[i] = static_cast<std::uint8_t>(simplex.vertices[i].index_a);
        cache.index_b[i] = static_cast<std::uint8_t>(simplex.vertices[i].index_b);
    }
    return cache;
}

// The answer from the solved simplex: its weights mix A's and B's corners into the
// closest points; the radii then move them out along the normal.
DistanceResult answerFrom(const ConvexProxy& a, const ConvexProxy& b, const Simplex& simplex, const Nearest& nearest,
                          Vec2 origin, int iterations) {
    DistanceResult result{
        .iterations = iterations, .simplex = simplex, .simplex_origin = origin, .cache = cacheOf(simplex)};
    Vec2 on_a;
    Vec2 on_b;
    for (std::size_t i = 0; i < simplex.count; ++i) {
        on_a = on_a + simplex.vertices[i].a * simplex.vertices[i].weight;
        on_b = on_b + simplex.vertices[i].b * simplex.vertices[i].weight;
    }
    result.point_a = on_a + origin;
    result.point_b = on_b + origin;
    if (nearest.holds_origin) {
        // Cores touch or overlap: no direction to part them, and no gap.
        if (simplex.count == 3) result.point_b = result.point_a;
        return result;
    }
    // From A to B: the search direction points from A - B's nearest point, pA - pB,
    // towards the origin, which is the way from pA to pB.
    result.normal = nearest.toward_origin.normalize();
    // The gap between the cores, from a corner of the simplex: for a side, the normal is
    // square to it, so either corner gives the distance of its line, with none of the
    // round-off of the mixed point.
    const double cores_apart = -result.normal.dot(simplex.vertices[0].w);
    result.distance = std::max(0.0, cores_apart - a.radius - b.radius);
    result.point_a = result.point_a + result.normal * a.radius;
    result.point_b = result.point_b - result.normal * b.radius;
    return result;
}

// The pass as a trace records it: the solved simplex, its nearest point, the direction.
GjkStep stepOf(const Simplex& simplex, const Nearest& nearest) {
    GjkStep step{.simplex = simplex, .direction = nearest.toward_origin, .holds_origin = nearest.holds_origin};
    for (std::size_t i = 0; i < simplex.count; ++i)
        step.nearest = step.nearest + simplex.vertices[i].w * simplex.vertices[i].weight;
    return step;
}

}  // namespace

ConvexProxy makeProxy(std::span<const Vec2> points, double radius) {
    ConvexProxy proxy;
    proxy.count = std::min(points.size(), kMaxPolygonVertices);
    for (std::size_t i = 0; i < proxy.count; ++i) proxy.points[i] = points[i];
    proxy.radius = radius;
    return proxy;
}

std::size_t supportIndex(const ConvexProxy& shape, Vec2 direction) {
    return farthestAlong({shape.points.data(), shape.count}, direction);
}

SimplexVertex supportOfDifference(const ConvexProxy& a, const ConvexProxy& b, Vec2 direction, Vec2 origin) {
    SimplexVertex v;
    v.index_a = supportIndex(a, direction);
    v.index_b = supportIndex(b, -direction);
    v.a = a.points[v.index_a] - origin;
    v.b = b.points[v.index_b] - origin;
    v.w = v.a - v.b;
    return v;
}

DistanceResult gjkDistance(const ConvexProxy& a, const ConvexProxy& b, const SimplexCache& start,
                           std::vector<GjkStep>* trace) {
    const Vec2 origin = a.points[0];
    const LocalShapes shapes = localShapes(a, b, origin);
    // Never less than 1e-13 px: shapes far smaller than a pixel still round off at that.
    const double touching = kRoundOff * std::max(shapes.size, 1.0);
    Simplex simplex = simplexFrom(start, shapes);
    int iterations = 0;
    while (true) {
        const Nearest nearest = solve(simplex, touching);
        if (trace) trace->push_back(stepOf(simplex, nearest));
        if (nearest.holds_origin || iterations == kMaxGjkIterations) {
            return answerFrom(a, b, simplex, nearest, origin, iterations);
        }
        const SimplexVertex next = supportOf(shapes, nearest.toward_origin);
        ++iterations;
        // The progress check: how much nearer the origin, along the unit direction d, the
        // new point reaches than the simplex's nearest point does (every corner of a side
        // reaches as far as its nearest point: d is square to the side).
        const Vec2 d = nearest.toward_origin.normalize();
        const double progress = next.w.dot(d) - simplex.vertices[0].w.dot(d);
        const bool stops = alreadyIn(simplex, next) || progress <= touching;
        if (trace) {
            trace->back().queried = true;
            trace->back().support = next;
            trace->back().kept = !stops;
        }
        if (stops) {
            return answerFrom(a, b, simplex, nearest, origin, iterations);
        }
        simplex.vertices[simplex.count] = next;
        ++simplex.count;
    }
}

}  // namespace engine
