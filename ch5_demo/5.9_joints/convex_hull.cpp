// The convex hull by gift wrapping (Jarvis's march).
//
// Why gift wrapping: with at most 8 points, speed is no reason to choose (quickhull and
// gift wrapping both finish in well under a microsecond), so the choice is the one a
// reader can check by hand. Gift wrapping walks round the hull the way a string wrapped
// round pins would: from a point that is surely a corner (the leftmost), the next corner
// is the point that has every other point on its left, seen from the corner we stand
// on. It needs one test, the sign of a cross product, and it gives the corners in order
// with no sorting and no recursion. Its cost, points x corners, is 64 tests at most.
//
// Two points exactly in line with the corner we stand on: the farther one is the next
// corner, and the nearer one lies on the side between them, so it is not a corner.
// Points *almost* in line are what round-off and typed-in scenes produce, so a second
// pass drops each corner that stands less than kHullTolerance off the line through its
// neighbours, nearest first. The outline moves by less than that tolerance.

#include "convex_hull.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <vector>

#include "number_format.h"

namespace engine {

namespace {

HullResult refuseHull(const std::string& problem) { return {std::nullopt, problem}; }

std::string pointText(Vec2 point) {
    std::ostringstream text;
    text << "[" << browser::to_js_string(point.x) << ", " << browser::to_js_string(point.y) << "]";
    return text.str();
}

// Positive when `to` lies to the left of the ray from `from` through `through`
// (counter-clockwise in convex_polygon.h's sense), negative to its right, zero in line.
double turnOf(Vec2 from, Vec2 through, Vec2 to) { return (through - from).cross(to - from); }

// How far `point` stands off the line through `a` and `b`, px.
double offLine(Vec2 point, Vec2 a, Vec2 b) { return std::abs(turnOf(a, b, point)) / a.distance(b); }

// The refusals that need no hull: too few or too many points, a bad coordinate, two
// points in one place, or all of them on one line. Empty when the points are fine.
std::string whyNoPolygon(std::span<const Vec2> points) {
    std::ostringstream why;
    if (points.size() > kMaxPolygonVertices) {
        why << "a polygon has at most " << kMaxPolygonVertices << " vertices (got " << points.size()
            << "); a rounder shape is better as a circle";
        return why.str();
    }
    if (points.size() < 3) {
        why << "a polygon needs at least 3 vertices (got " << points.size() << ")";
        return why.str();
    }
    for (std::size_t i = 0; i < points.size(); ++i) {
        const Vec2 p = points[i];
        const auto fine = [](double v) { return std::isfinite(v) && std::abs(v) <= kMaxHullCoordinate; };
        if (!fine(p.x) || !fine(p.y)) {
            why << "vertex " << i << " must have coordinates in [-" << browser::to_js_string(kMaxHullCoordinate) << ", "
                << browser::to_js_string(kMaxHullCoordinate) << "] px from the centre (got " << pointText(p) << ")";
            return why.str();
        }
    }
    // Welding: the points that are not within the tolerance of an earlier distinct one.
    std::vector<Vec2> distinct;
    for (Vec2 p : points) {
        bool seen = false;
        for (Vec2 q : distinct) seen = seen || p.distance(q) < kHullTolerance;
        if (!seen) distinct.push_back(p);
    }
    if (distinct.size() < 3) {
        why << "a polygon needs at least 3 distinct vertices, at least " << browser::to_js_string(kHullTolerance)
            << " px apart (got " << distinct.size() << " of " << points.size() << ")";
        return why.str();
    }
    for (std::size_t i = 0; i < points.size(); ++i) {
        for (std::size_t j = i + 1; j < points.size(); ++j) {
            const double apart = points[i].distance(points[j]);
            if (apart < kHullTolerance) {
                why << "vertices " << i << " and " << j << " are closer than " << kHullTolerance
                    << " px: a vertex given twice? (got " << pointText(points[i]) << " and " << pointText(points[j])
                    << ")";
                return why.str();
            }
        }
    }
    // On one line: every point near the line through the two farthest apart (that line
    // is the longest the points span, so no other line fits them more tightly).
    std::size_t far_a = 0;
    std::size_t far_b = 1;
    for (std::size_t i = 0; i < points.size(); ++i) {
        for (std::size_t j = i + 1; j < points.size(); ++j) {
            if (points[i].distance(points[j]) > points[far_a].distance(points[far_b])) {
                far_a = i;
                far_b = j;
            }
        }
    }
    double widest = 0.0;
    for (Vec2 p : points) widest = std::max(widest, offLine(p, points[far_a], points[far_b]));
    if (widest <= kHullTolerance) {
        why << "all vertices lie on one line, within " << browser::to_js_string(kHullTolerance)
            << " px: a polygon needs area (got " << pointText(points[far_a]) << " to " << pointText(points[far_b])
            << ")";
        return why.str();
    }
    return {};
}

// The wrap itself. The leftmost point (the lowest of them if several) is surely a
// corner; the walk ends when it comes back there. Every step adds a different corner,
// so it ends within points.size() steps; the bound only guards against the impossible.
std::vector<Vec2> wrap(std::span<const Vec2> points) {
    std::size_t start = 0;
    for (std::size_t i = 1; i < points.size(); ++i) {
        const Vec2 p = points[i];
        if (p.x < points[start].x || (p.x == points[start].x && p.y < points[start].y)) start = i;
    }
    std::vector<Vec2> corners;
    std::size_t at = start;
    do {
        corners.push_back(points[at]);
        std::size_t next = at == 0 ? 1 : 0;
        for (std::size_t i = 0; i < points.size(); ++i) {
            if (i == at) continue;
            const double turn = turnOf(points[at], points[next], points[i]);
            const bool farther_in_line =
                turn == 0.0 && points[at].distance(points[i]) > points[at].distance(points[next]);
            // A point right of the candidate edge shows the edge is not the hull's.
            if (turn < 0.0 || farther_in_line) next = i;
        }
        at = next;
    } while (at != start && corners.size() <= points.size());
    return corners;
}

// Drops the corners nearer than the tolerance to the line through their neighbours,
// the nearest first, until none is left (or too few corners remain to make a polygon).
void dropFlatCorners(std::vector<Vec2>& corners) {
    while (corners.size() >= 3) {
        std::size_t flattest = 0;
        double nearest = std::numeric_limits<double>::infinity();
        for (std::size_t i = 0; i < corners.size(); ++i) {
            const Vec2 before = corners[(i + corners.size() - 1) % corners.size()];
            const Vec2 after = corners[(i + 1) % corners.size()];
            const double off = offLine(corners[i], before, after);
            if (off < nearest) {
                nearest = off;
                flattest = i;
            }
        }
        if (nearest > kHullTolerance) return;
        corners.erase(corners.begin() + static_cast<std::ptrdiff_t>(flattest));
    }
}

}  // namespace

HullResult convexHull(std::span<const Vec2> points) {
    if (std::string why = whyNoPolygon(points); !why.empty()) return refuseHull(why);
    std::vector<Vec2> corners = wrap(points);
    dropFlatCorners(corners);
    if (corners.size() < 3) {
        std::ostringstream why;
        why << "all vertices lie on one line, within " << browser::to_js_string(kHullTolerance)
            << " px: a polygon needs area (got " << corners.size() << " corners)";
        return refuseHull(why.str());
    }
    // The same first corner whatever was dropped: the leftmost, the lowest of those.
    std::size_t first = 0;
    for (std::size_t i = 1; i < corners.size(); ++i) {
        if (corners[i].x < corners[first].x || (corners[i].x == corners[first].x && corners[i].y < corners[first].y)) {
            first = i;
        }
    }
    std::vector<Vec2> ordered;
    for (std::size_t i = 0; i < corners.size(); ++i) ordered.push_back(corners[(first + i) % corners.size()]);
    return {makeConvexPolygon(ordered), {}};
}

}  // namespace engine
