// EPA's loop, and the start that the known failures come from.
//
// Why the depth is right when it stops. The polygon's corners are all points of A - B,
// so the polygon lies inside A - B, and it is kept convex around the origin; its side
// nearest the origin is then at least as near as A - B's nearest side: side <= depth.
// And every line with all of A - B behind it is at least as far from the origin as A - B's
// nearest side: depth <= reach, the support point's distance along the same normal. So
// when reach - side <= tolerance, side is within the tolerance of the depth.
//
// The start. GJK ends on whatever simplex held the origin, and it is not always a
// triangle around it: two points with the origin on the segment between them (shapes
// whose outlines cross at a corner), or a single point (shapes that touch at a corner).
// A triangle of three points on one line would have no inside and no outward normals,
// and EPA started on any of these divides by a side of length zero or takes a normal
// that points nowhere (fcl #395 and Jolt #660 are such reports). GJK never ends on a
// flat triangle (gjk.cpp cuts one to a segment), and the start is made a proper triangle
// here: a point gains the support point towards the origin, a segment the support point
// square to it, on whichever side A - B reaches out. The origin may lie on the
// triangle's outline, which is fine: its side then has distance 0 and is the first to be
// pushed out.
//
// Kept convex. A new point can stand outside a neighbouring side's line too, and then
// the corner between them is no longer a corner. Such a corner is dropped, so the
// polygon stays the hull of its points and "nearest side" means what the proof needs.

#include "epa.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace engine {

namespace {

// Every corner the polygon can hold: the start's 3 and one per query.
constexpr std::size_t kMaxPolytopeCorners = 3 + kMaxEpaIterations;

class Polytope {
public:
    std::size_t size() const { return count_; }
    const SimplexVertex& operator[](std::size_t i) const { return corners_[i % count_]; }
    void push_back(const SimplexVertex& v) { corners_[count_++] = v; }
    bool holds(const SimplexVertex& v) const {
        for (std::size_t i = 0; i < count_; ++i) {
            if (corners_[i].index_a == v.index_a && corners_[i].index_b == v.index_b) return true;
        }
        return false;
    }
    void insertAfter(std::size_t side, const SimplexVertex& v) {
        std::copy_backward(corners_.begin() + static_cast<std::ptrdiff_t>(side + 1),
                           corners_.begin() + static_cast<std::ptrdiff_t>(count_),
                           corners_.begin() + static_cast<std::ptrdiff_t>(count_ + 1));
        corners_[side + 1] = v;
        ++count_;
    }
    void erase(std::size_t i) {
        std::copy(corners_.begin() + static_cast<std::ptrdiff_t>(i + 1),
                  corners_.begin() + static_cast<std::ptrdiff_t>(count_),
                  corners_.begin() + static_cast<std::ptrdiff_t>(i));
        --count_;
    }
    void swap(std::size_t i, std::size_t j) { std::swap(corners_[i], corners_[j]); }

private:
    std::array<SimplexVertex, kMaxPolytopeCorners> corners_{};
    std::size_t count_ = 0;
};

// What the loop needs of the proxies: the support point of A - B and the scale.
struct Difference {
    const ConvexProxy& a;
    const ConvexProxy& b;
    Vec2 origin;
    double flat;  // nearer than this to a line, px, a point is on it (round-off)
    SimplexVertex support(Vec2 direction) const { return supportOfDifference(a, b, direction, origin); }
};

double offSide(Vec2 point, Vec2 from, Vec2 to) { return (to - from).cross(point - from) / from.distance(to); }

// The start (the file's header): GJK's simplex made a triangle, counter-clockwise. False
// when A - B has no area (both cores points or segments on one line).
bool startTriangle(Polytope& polygon, const Difference& difference) {
    if (polygon.size() == 1) {
        const Vec2 w = polygon[0].w;
        for (Vec2 direction : {-w, Vec2{1.0, 0.0}, Vec2{-1.0, 0.0}}) {
            const SimplexVertex v = difference.support(direction);
            if (polygon.size() == 1 && !polygon.holds(v) && v.w.distance(w) > difference.flat) polygon.push_back(v);
        }
        if (polygon.size() == 1) return false;
    }
    if (polygon.size() == 2) {
        const Vec2 side = polygon[1].w - polygon[0].w;
        for (Vec2 direction : {Vec2{-side.y, side.x}, Vec2{side.y, -side.x}}) {
            const SimplexVertex v = difference.support(direction);
            if (polygon.size() == 2 && std::abs(offSide(v.w, polygon[0].w, polygon[1].w)) > difference.flat) {
                polygon.push_back(v);
            }
        }
        if (polygon.size() == 2) return false;
    }
    if (offSide(polygon[2].w, polygon[0].w, polygon[1].w) < 0.0) polygon.swap(1, 2);
    return true;
}

struct Side {
    std::size_t index = 0;  // from corner index to corner index + 1
    Vec2 normal;            // unit, outward
    double distance = 0.0;  // of its line from the origin; negative if the origin is outside it
};

Side nearestSide(const Polytope& polygon) {
    Side nearest;
    nearest.distance = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < polygon.size(); ++i) {
        const Vec2 edge = polygon[i + 1].w - polygon[i].w;
        const Vec2 normal = Vec2{edge.y, -edge.x}.normalize();
        const double distance = normal.dot(polygon[i].w);
        if (distance < nearest.distance) nearest = {i, normal, distance};
    }
    return nearest;
}

// Puts `v` in after side `side` and drops the neighbours it leaves inside.
void insertConvex(Polytope& polygon, std::size_t side, const SimplexVertex& v) {
    polygon.insertAfter(side, v);
    std::size_t at = side + 1;
    while (polygon.size() > 3) {
        const std::size_t before = (at + polygon.size() - 1) % polygon.size();
        const std::size_t before2 = (at + polygon.size() - 2) % polygon.size();
        if (offSide(polygon[before].w, polygon[before2].w, polygon[at].w) < 0.0) break;  // still a corner
        polygon.erase(before);
        if (before < at) --at;
    }
    while (polygon.size() > 3) {
        const std::size_t after = (at + 1) % polygon.size();
        const std::size_t after2 = (at + 2) % polygon.size();
        if (offSide(polygon[after].w, polygon[at].w, polygon[after2].w) < 0.0) break;
        polygon.erase(after);
        if (after < at) --at;
    }
}

EpaPenetration answerFrom(const Polytope& polygon, const Side& side, Vec2 origin, int iterations, bool converged) {
    const SimplexVertex& from = polygon[side.index];
    const SimplexVertex& to = polygon[side.index + 1];
    // The foot of the perpendicular from the origin on the side, as a share of the way.
    const Vec2 edge = to.w - from.w;
    const double t = std::clamp(-from.w.dot(edge) / edge.dot(edge), 0.0, 1.0);
    EpaPenetration answer;
    answer.depth = std::max(0.0, side.distance);
    answer.normal = side.normal;
    answer.point_a = from.a + (to.a - from.a) * t + origin;
    answer.point_b = answer.point_a - answer.normal * answer.depth;
    answer.iterations = iterations;
    answer.converged = converged;
    return answer;
}

}  // namespace

std::optional<EpaPenetration> epaPenetration(const ConvexProxy& a, const ConvexProxy& b,
                                             std::vector<Vec2>* polygon_corners) {
    ConvexProxy core_a = a;
    ConvexProxy core_b = b;
    core_a.radius = 0.0;
    core_b.radius = 0.0;
    const DistanceResult gjk = gjkDistance(core_a, core_b);
    if (gjk.distance > 0.0) return std::nullopt;

    double size = 0.0;
    for (std::size_t i = 0; i < a.count; ++i) size = std::max(size, a.points[i].distance(gjk.simplex_origin));
    for (std::size_t i = 0; i < b.count; ++i) size = std::max(size, b.points[i].distance(gjk.simplex_origin));
    const double tolerance = kEpaRelativeTolerance * std::max(size, 1.0);
    const Difference difference{core_a, core_b, gjk.simplex_origin, tolerance};

    Polytope polygon;
    for (std::size_t i = 0; i < gjk.simplex.count; ++i) {
        if (!polygon.holds(gjk.simplex.vertices[i])) polygon.push_back(gjk.simplex.vertices[i]);
    }
    if (!startTriangle(polygon, difference)) {
        // A - B is a point or a segment: no area, no depth, no normal worth the name.
        EpaPenetration flat;
        flat.point_a = gjk.point_a;
        flat.point_b = gjk.point_b;
        flat.converged = false;
        return flat;
    }
    // The corners, for the diagram, whichever way the loop ends.
    const auto report = [&] {
        if (!polygon_corners) return;
        polygon_corners->clear();
        for (std::size_t i = 0; i < polygon.size(); ++i) polygon_corners->push_back(polygon[i].w);
    };
    for (int iteration = 1; iteration <= kMaxEpaIterations; ++iteration) {
        const Side side = nearestSide(polygon);
        const SimplexVertex next = difference.support(side.normal);
        if (polygon.holds(next) || next.w.dot(side.normal) - side.distance <= tolerance) {
            report();
            return answerFrom(polygon, side, gjk.simplex_origin, iteration, true);
        }
        insertConvex(polygon, side.index, next);
    }
    report();
    return answerFrom(polygon, nearestSide(polygon), gjk.simplex_origin, kMaxEpaIterations, false);
}

}  // namespace engine
