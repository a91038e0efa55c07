#include "continuous.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <span>

#include "circle.h"
#include "gjk.h"
#include "polygon.h"
#include "rectangle.h"

namespace engine {

namespace {

// A quarter of the depth: a shape stopped within it of the depth is in the obstacle by
// at least three quarters of the depth, and by no more than the depth.
constexpr double kToleranceShare = 0.25;
// How deep a shape already in contact may go before it is stopped, at most, and how far
// short of the obstacle its centre is kept when it is in deeper still: shares of its
// smallest extent (impactAgainst).
constexpr double kDeepestShare = 0.75;
constexpr double kCentreMargin = 0.25;

double pointToSegment(Vec2 point, Vec2 a, Vec2 b) {
    const Vec2 along = b - a;
    const double length_squared = along.dot(along);
    const double t = length_squared > 0.0 ? std::clamp((point - a).dot(along) / length_squared, 0.0, 1.0) : 0.0;
    return point.distance(a + along * t);
}

// A point is inside a convex polygon when it is on the same side of all its sides,
// whichever way round the corners run.
bool isInside(Vec2 point, std::span<const Vec2> corners) {
    const std::size_t n = corners.size();
    bool left = false, right = false;
    for (std::size_t i = 0; i < n; ++i) {
        const double side = (corners[(i + 1) % n] - corners[i]).cross(point - corners[i]);
        left = left || side > 0.0;
        right = right || side < 0.0;
    }
    return !(left && right);
}

double pointToCorners(Vec2 point, std::span<const Vec2> corners) {
    if (isInside(point, corners)) return 0.0;
    const std::size_t n = corners.size();
    double nearest = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < n; ++i) {
        nearest = std::min(nearest, pointToSegment(point, corners[i], corners[(i + 1) % n]));
    }
    return nearest;
}

// Whether two convex polygons overlap: no line along a side of either has one wholly
// on each side of it (the separating axis theorem). A pulled-in outline may have sides
// of no length; they separate nothing, and the others decide.
bool overlap(std::span<const Vec2> a, std::span<const Vec2> b) {
    for (const std::span<const Vec2> sides : {a, b}) {
        const std::size_t n = sides.size();
        for (std::size_t i = 0; i < n; ++i) {
            const Vec2 side = sides[(i + 1) % n] - sides[i];
            const Vec2 across{-side.y, side.x};
            double a_low = std::numeric_limits<double>::infinity(), a_high = -a_low;
            double b_low = a_low, b_high = a_high;
            for (Vec2 corner : a) {
                a_low = std::min(a_low, across.dot(corner));
                a_high = std::max(a_high, across.dot(corner));
            }
            for (Vec2 corner : b) {
                b_low = std::min(b_low, across.dot(corner));
                b_high = std::max(b_high, across.dot(corner));
            }
            if (a_high < b_low || b_high < a_low) return false;
        }
    }
    return true;
}

// Two convex shapes apart are nearest at a corner of one of them. Two that overlap need
// not have a corner of either inside the other: a thin plate can cross a thin wall like
// an X (the solver can leave them so), which only the separating axes see.
double cornersToCorners(std::span<const Vec2> a, std::span<const Vec2> b) {
    if (overlap(a, b)) return 0.0;
    double nearest = std::numeric_limits<double>::infinity();
    for (Vec2 corner : a) nearest = std::min(nearest, pointToCorners(corner, b));
    for (Vec2 corner : b) nearest = std::min(nearest, pointToCorners(corner, a));
    return nearest;
}

double coreDistance(const Outline& a, const Outline& b) {
    if (a.is_point && b.is_point) return a.center.distance(b.center);
    if (a.is_point) return pointToCorners(a.center, b.cornerList());
    if (b.is_point) return pointToCorners(b.center, a.cornerList());
    return cornersToCorners(a.cornerList(), b.cornerList());
}

// The farthest any point of the outline's core is from its centre.
double farthestCorner(const Outline& outline) {
    if (outline.is_point) return 0.0;
    double farthest = 0.0;
    for (Vec2 corner : outline.cornerList()) farthest = std::max(farthest, corner.distance(outline.center));
    return farthest;
}

// May the shape, swept from `from` to `to`, meet `other` at all? Its bounding circle
// swept along the segment against the other's bounding circle.
bool mayMeet(const RigidShape& shape, Vec2 from, Vec2 to, const RigidShape& other) {
    return pointToSegment(other.center(), from, to) <= shape.boundRadius() + other.boundRadius();
}

// The share t of the straight path from `from` by `offset` (0 <= t <= 1) at which a
// point enters the obstacle's outline: 0 when it starts inside, nothing when it never
// enters. The outline is convex: the path is inside every side's half plane at once
// from the last side it crosses inwards until the first it crosses outwards.
std::optional<double> entryAlong(Vec2 from, Vec2 offset, const Outline& obstacle) {
    if (obstacle.is_point) {
        // |from + offset t - centre| = radius: the smaller root, when there is one.
        const Vec2 away = from - obstacle.center;
        const double a = offset.dot(offset), b = away.dot(offset),
                     c = away.dot(away) - obstacle.radius * obstacle.radius;
        if (c <= 0.0) return 0.0;
        const double discriminant = b * b - a * c;
        if (a <= 0.0 || discriminant < 0.0) return std::nullopt;
        const double t = (-b - std::sqrt(discriminant)) / a;
        if (t < 0.0 || t > 1.0) return std::nullopt;
        return t;
    }
    const std::span<const Vec2> c = obstacle.cornerList();
    const std::size_t n = c.size();
    // Which way round the corners run: the sign of the area.
    double area = 0.0;
    for (std::size_t i = 0; i < n; ++i) area += c[i].cross(c[(i + 1) % n]);
    const double turn = area >= 0.0 ? 1.0 : -1.0;
    double enter = 0.0, leave = 1.0;
    for (std::size_t i = 0; i < n; ++i) {
        const Vec2 side = c[(i + 1) % n] - c[i];
        const Vec2 outward = Vec2{side.y, -side.x} * turn;
        const double ahead = outward.dot(c[i] - from);  // >= 0: `from` is on the inner side
        const double closing = outward.dot(offset);
        if (closing == 0.0) {
            if (ahead < 0.0) return std::nullopt;
            continue;
        }
        const double t = ahead / closing;
        if (closing < 0.0) {
            enter = std::max(enter, t);
        } else {
            leave = std::min(leave, t);
        }
    }
    if (enter > leave) return std::nullopt;
    return enter;
}

}  // namespace

Outline outlineOf(const RigidShape& shape) {
    Outline outline{.center = shape.center()};
    switch (shape.type()) {
        case ShapeType::Circle: outline.radius = static_cast<const Circle&>(shape).radius(); break;
        case ShapeType::Rectangle: {
            const std::array<Vec2, 4>& corners = static_cast<const Rectangle&>(shape).vertices();
            outline.is_point = false;
            outline.square_corners = true;
            outline.count = corners.size();
            std::copy(corners.begin(), corners.end(), outline.corners.begin());
            break;
        }
        case ShapeType::Polygon: {
            const ConvexPolygon& polygon = static_cast<const Polygon&>(shape).outline();
            outline.is_point = false;
            outline.count = polygon.count;
            outline.corners = polygon.vertices;
            break;
        }
    }
    return outline;
}

Outline moved(const Outline& outline, Vec2 offset, double turn) {
    Outline result = outline;
    result.center = outline.center + offset;
    for (std::size_t i = 0; i < outline.count; ++i) {
        result.corners[i] = outline.corners[i].rotate(outline.center, turn) + offset;
    }
    return result;
}

// Each corner moves in along both sides that meet there. A square corner moves by the
// depth along each; a sharper or blunter one (a polygon's, 5.8) by depth / sin of its
// angle along each, so that both sides still move in by exactly the depth. The
// rectangle keeps the first form: the same inset, and its numbers to the last bit.
Outline shrunk(const Outline& outline, double depth) {
    Outline result = outline;
    if (outline.is_point) {
        result.radius = outline.radius - depth;
        return result;
    }
    const std::size_t n = outline.count;
    const std::array<Vec2, kMaxPolygonVertices>& c = outline.corners;
    for (std::size_t i = 0; i < n; ++i) {
        const Vec2 to_next = (c[(i + 1) % n] - c[i]).normalize();
        const Vec2 to_previous = (c[(i + n - 1) % n] - c[i]).normalize();
        const double reach = outline.square_corners ? depth : depth / std::abs(to_next.cross(to_previous));
        result.corners[i] = c[i] + (to_next + to_previous) * reach;
    }
    return result;
}

double perKindGap(const Outline& a, const Outline& b) { return coreDistance(a, b) - a.radius - b.radius; }

namespace {

// What GJK sees of an outline: its core's points and its radius.
ConvexProxy proxyOf(const Outline& outline) {
    if (outline.is_point) return makeProxy({&outline.center, 1}, outline.radius);
    return makeProxy(outline.cornerList(), outline.radius);
}

// Which of the two measures a pair, by what each costs (README.md, "Continuous
// collision's gap", has the figures). Two outlines with corners, one of them a
// polygon's: GJK, whose walk visits a few corners of A - B where the per-kind function
// measures every corner of each against every side of the other (8 x 8 twice for two
// octagons). A circle: the per-kind distance of its centre to the other outline, a few
// ns where GJK's setting up alone takes a hundred. Two rectangles: the per-kind
// function, so that a scene with no polygon moves as in 5.7 to the last bit (GJK's
// answer agrees to 1e-13 px, not to the bit).
bool measuredByGjk(const Outline& a, const Outline& b) {
    const auto polygon = [](const Outline& outline) { return !outline.is_point && !outline.square_corners; };
    return !a.is_point && !b.is_point && (polygon(a) || polygon(b));
}

// The gap, for a pair measured again and again as the sweep advances: GJK starts each
// walk from the corners its last one ended on (gjk.h's SimplexCache), which the small
// advance seldom changes.
double gapAgain(const Outline& a, const Outline& b, SimplexCache& cache) {
    if (!measuredByGjk(a, b)) return perKindGap(a, b);
    const DistanceResult result = gjkDistance(proxyOf(a), proxyOf(b), cache);
    cache = result.cache;
    return result.distance;
}

}  // namespace

double gjkGap(const Outline& a, const Outline& b) { return gjkDistance(proxyOf(a), proxyOf(b)).distance; }

double gap(const Outline& a, const Outline& b) { return measuredByGjk(a, b) ? gjkGap(a, b) : perKindGap(a, b); }

double smallestExtent(const RigidShape& shape) {
    switch (shape.type()) {
        case ShapeType::Circle: return static_cast<const Circle&>(shape).radius();
        case ShapeType::Rectangle: {
            const auto& rectangle = static_cast<const Rectangle&>(shape);
            return std::min(rectangle.width(), rectangle.height()) / 2;
        }
        case ShapeType::Polygon: {
            // How far the centre lies behind its nearest face: for a rectangle, half its
            // shorter side, as above.
            const ConvexPolygon& polygon = static_cast<const Polygon&>(shape).outline();
            double nearest = std::numeric_limits<double>::infinity();
            for (std::size_t i = 0; i < polygon.count; ++i) {
                nearest = std::min(nearest, (polygon.vertices[i] - shape.center()).dot(polygon.normals[i]));
            }
            return nearest;
        }
    }
    return 0.0;
}

double reach(const StepMotion& motion) {
    return motion.offset.length() + std::abs(motion.turn) * farthestCorner(motion.start);
}

bool isFast(const RigidShape& shape, Vec2 offset, double turn) {
    const double farthest = shape.type() == ShapeType::Circle ? 0.0 : shape.boundRadius();
    return offset.length() + std::abs(turn) * farthest > kFastShare * smallestExtent(shape);
}

std::optional<double> timeOfImpact(const StepMotion& motion, const Outline& obstacle, double depth) {
    const double tolerance = kToleranceShare * depth;
    const StepMotion inner{.start = shrunk(motion.start, depth), .offset = motion.offset, .turn = motion.turn};
    const double speed = reach(inner);  // the most any point of it moves per unit of t
    if (speed <= 0.0) return std::nullopt;
    double t = 0.0;
    SimplexCache cache;
    for (int advance = 0; advance < kMaxAdvances; ++advance) {
        const double left = gapAgain(moved(inner.start, inner.offset * t, inner.turn * t), obstacle, cache);
        if (left <= tolerance) return t;
        t += left / speed;
        if (t > 1.0) return std::nullopt;
    }
    return t;
}

// The time of impact, for a shape that may already touch the obstacle where its motion
// starts: the solver left it there, in contact, but its spin or the other contacts may
// still carry it on into the obstacle and through. Then the target depth is doubled
// until the outline pulled in by it is clear at the start, up to kDeepestShare of the
// shape's smallest extent (its thinness): the pulled-in outline still holds the centre,
// which is then still outside. A shape in deeper than that (a plate thinner than the
// solver's slop can rest there) is held back only by its centre: it is stopped
// kCentreMargin of its thinness before its centre would enter the obstacle, for with
// the centre inside, the narrow phase could push the shape out on the far side. A
// centre already inside is the step's collision handling's alone.
std::optional<double> impactAgainst(const StepMotion& motion, const Outline& obstacle, double extent) {
    const double deepest = kDeepestShare * extent;
    for (double depth = std::min(kImpactDepth, extent / 4);; depth = std::min(2 * depth, deepest)) {
        const std::optional<double> impact = timeOfImpact(motion, obstacle, depth);
        if (!impact || *impact > 0.0) return impact;
        if (depth == deepest) break;
    }
    const std::optional<double> entry = entryAlong(motion.start.center, motion.offset, obstacle);
    if (!entry || *entry == 0.0) return std::nullopt;
    return std::max(*entry - kCentreMargin * extent / motion.offset.length(), 0.0);
}

void ContinuousCollision::startStep(ShapeList shapes) {
    start_.resize(shapes.size());
    for (std::size_t i = 0; i < shapes.size(); ++i) start_[i] = {shapes[i]->center(), shapes[i]->angle()};
}

void ContinuousCollision::sweep(ShapeList shapes, const Joints* joints) {
    sweeps_.clear();
    crossings_.clear();
    // A shape that is no bullet is swept against the static shapes alone: they are
    // listed once, so that a world of many fast shapes and few static ones pays for
    // the few.
    static_.clear();
    for (std::size_t j = 0; j < shapes.size(); ++j) {
        if (shapes[j]->isStatic()) static_.push_back(j);
    }
    for (std::size_t i = 0; i < shapes.size(); ++i) {
        RigidShape& shape = *shapes[i];
        // Nothing stops a sensor, nor a kinematic shape (5.9), which moves by its velocity.
        if (shape.isResting() || shape.isSensor() || shape.isKinematic()) continue;
        const Pose& start = start_[i];
        const Vec2 offset = shape.center() - start.center;
        const double turn = shape.angle() - start.angle;
        if (!isFast(shape, offset, turn)) continue;
        const StepMotion motion{.start = moved(outlineOf(shape), offset * -1, -turn), .offset = offset, .turn = turn};
        const double extent = smallestExtent(shape);

        std::optional<double> first;
        sensors_met_.clear();
        const auto sweepAgainst = [&](std::size_t j) {
            const RigidShape& other = *shapes[j];
            if (j == i || !mayMeet(shape, start.center, shape.center(), other)) return;
            if (joints && joints->keepsApart(shape.id(), other.id())) return;
            if (other.isSensor()) {
                sensors_met_.push_back(j);  // felt, not hit: looked at once the stop is known
                return;
            }
            const std::optional<double> impact = impactAgainst(motion, outlineOf(other), extent);
            if (impact && (!first || *impact < *first)) first = impact;
        };
        if (shape.isBullet()) {
            for (std::size_t j = 0; j < shapes.size(); ++j) sweepAgainst(j);
        } else {
            for (std::size_t j : static_) sweepAgainst(j);
        }
        sweeps_.push_back({i, start.center, shape.center(), first});
        // The sensors the shape reached before anything stopped it.
        for (const std::size_t j : sensors_met_) {
            const std::optional<double> enters =
                timeOfImpact(motion, outlineOf(*shapes[j]), std::min(kImpactDepth, extent / 4));
            if (enters && (!first || *enters <= *first)) {
                crossings_.push_back({i, j, start.center + offset * *enters, offset.normalize()});
            }
        }
        if (!first) continue;
        // Back to the time of impact: the rest of the step's motion is not made.
        shape.move(start.center + offset * *first - shape.center());
        shape.rotate(start.angle + turn * *first - shape.angle());
    }
}

}  // namespace engine
