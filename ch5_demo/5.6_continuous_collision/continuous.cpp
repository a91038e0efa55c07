#include "continuous.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "circle.h"
#include "rectangle.h"

namespace engine {

namespace {

// A quarter of the depth: a shape stopped within it of the depth is in the obstacle by
// at least three quarters of the depth, and by no more than the depth.
constexpr double kToleranceShare = 0.25;

double pointToSegment(Vec2 point, Vec2 a, Vec2 b) {
    const Vec2 along = b - a;
    const double length_squared = along.dot(along);
    const double t = length_squared > 0.0 ? std::clamp((point - a).dot(along) / length_squared, 0.0, 1.0) : 0.0;
    return point.distance(a + along * t);
}

// A point is inside a convex quadrilateral when it is on the same side of all four
// sides, whichever way round the corners run.
bool isInside(Vec2 point, const std::array<Vec2, 4>& corners) {
    bool left = false, right = false;
    for (std::size_t i = 0; i < corners.size(); ++i) {
        const double side = (corners[(i + 1) % 4] - corners[i]).cross(point - corners[i]);
        left = left || side > 0.0;
        right = right || side < 0.0;
    }
    return !(left && right);
}

double pointToQuad(Vec2 point, const std::array<Vec2, 4>& corners) {
    if (isInside(point, corners)) return 0.0;
    double nearest = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < corners.size(); ++i) {
        nearest = std::min(nearest, pointToSegment(point, corners[i], corners[(i + 1) % 4]));
    }
    return nearest;
}

// Two convex shapes apart are nearest at a corner of one of them; two that overlap have
// a corner of one inside the other (the sweep never makes them cross without one: it
// stops them before they meet).
double quadToQuad(const std::array<Vec2, 4>& a, const std::array<Vec2, 4>& b) {
    double nearest = std::numeric_limits<double>::infinity();
    for (Vec2 corner : a) nearest = std::min(nearest, pointToQuad(corner, b));
    for (Vec2 corner : b) nearest = std::min(nearest, pointToQuad(corner, a));
    return nearest;
}

double coreDistance(const Outline& a, const Outline& b) {
    if (a.is_point && b.is_point) return a.center.distance(b.center);
    if (a.is_point) return pointToQuad(a.center, b.corners);
    if (b.is_point) return pointToQuad(b.center, a.corners);
    return quadToQuad(a.corners, b.corners);
}

// The farthest any point of the outline's core is from its centre.
double farthestCorner(const Outline& outline) {
    if (outline.is_point) return 0.0;
    double farthest = 0.0;
    for (Vec2 corner : outline.corners) farthest = std::max(farthest, corner.distance(outline.center));
    return farthest;
}

// May the shape, swept from `from` to `to`, meet `other` at all? Its bounding circle
// swept along the segment against the other's bounding circle.
bool mayMeet(const RigidShape& shape, Vec2 from, Vec2 to, const RigidShape& other) {
    return pointToSegment(other.center(), from, to) <= shape.boundRadius() + other.boundRadius();
}

// The time of impact, for a shape that may already touch the obstacle where its motion
// starts: the solver left it there, in contact, but its spin or the other contacts may
// still carry it on into the obstacle and through. Then the target depth is doubled
// until the outline pulled in by it is clear at the start, up to half the shape's
// smallest extent: deeper than that the shape's middle would be in the obstacle. 0
// when even that touches at the start: a contact that deep is the step's collision
// handling's alone.
std::optional<double> impactFromContact(const StepMotion& motion, const Outline& obstacle, double extent) {
    std::optional<double> impact;
    for (double depth = std::min(kImpactDepth, extent / 4); depth <= extent / 2; depth *= 2) {
        impact = timeOfImpact(motion, obstacle, depth);
        if (!impact || *impact > 0.0) return impact;
    }
    return std::nullopt;
}

}  // namespace

Outline outlineOf(const RigidShape& shape) {
    if (shape.type() == ShapeType::Circle) {
        return {.center = shape.center(), .radius = static_cast<const Circle&>(shape).radius()};
    }
    return {.center = shape.center(), .is_point = false, .corners = static_cast<const Rectangle&>(shape).vertices()};
}

Outline moved(const Outline& outline, Vec2 offset, double turn) {
    Outline result = outline;
    result.center = outline.center + offset;
    for (Vec2& corner : result.corners) corner = corner.rotate(outline.center, turn) + offset;
    return result;
}

// Each corner moves in along both sides that meet there.
Outline shrunk(const Outline& outline, double depth) {
    Outline result = outline;
    if (outline.is_point) {
        result.radius = outline.radius - depth;
        return result;
    }
    const std::array<Vec2, 4>& c = outline.corners;
    for (std::size_t i = 0; i < c.size(); ++i) {
        const Vec2 to_next = (c[(i + 1) % 4] - c[i]).normalize();
        const Vec2 to_previous = (c[(i + 3) % 4] - c[i]).normalize();
        result.corners[i] = c[i] + (to_next + to_previous) * depth;
    }
    return result;
}

double gap(const Outline& a, const Outline& b) { return coreDistance(a, b) - a.radius - b.radius; }

double smallestExtent(const RigidShape& shape) {
    if (shape.type() == ShapeType::Circle) return static_cast<const Circle&>(shape).radius();
    const auto& rectangle = static_cast<const Rectangle&>(shape);
    return std::min(rectangle.width(), rectangle.height()) / 2;
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
    for (int advance = 0; advance < kMaxAdvances; ++advance) {
        const double left = gap(moved(inner.start, inner.offset * t, inner.turn * t), obstacle);
        if (left <= tolerance) return t;
        t += left / speed;
        if (t > 1.0) return std::nullopt;
    }
    return t;
}

void ContinuousCollision::startStep(ShapeList shapes) {
    start_.resize(shapes.size());
    for (std::size_t i = 0; i < shapes.size(); ++i) start_[i] = {shapes[i]->center(), shapes[i]->angle()};
}

void ContinuousCollision::sweep(ShapeList shapes) {
    sweeps_.clear();
    // A shape that is no bullet is swept against the static shapes alone: they are
    // listed once, so that a world of many fast shapes and few static ones pays for
    // the few.
    static_.clear();
    for (std::size_t j = 0; j < shapes.size(); ++j) {
        if (shapes[j]->isStatic()) static_.push_back(j);
    }
    for (std::size_t i = 0; i < shapes.size(); ++i) {
        RigidShape& shape = *shapes[i];
        if (shape.isResting()) continue;
        const Pose& start = start_[i];
        const Vec2 offset = shape.center() - start.center;
        const double turn = shape.angle() - start.angle;
        if (!isFast(shape, offset, turn)) continue;
        const StepMotion motion{.start = moved(outlineOf(shape), offset * -1, -turn), .offset = offset, .turn = turn};
        const double extent = smallestExtent(shape);

        std::optional<double> first;
        const auto sweepAgainst = [&](std::size_t j) {
            const RigidShape& other = *shapes[j];
            if (j == i || !mayMeet(shape, start.center, shape.center(), other)) return;
            const std::optional<double> impact = impactFromContact(motion, outlineOf(other), extent);
            if (impact && (!first || *impact < *first)) first = impact;
        };
        if (shape.isBullet()) {
            for (std::size_t j = 0; j < shapes.size(); ++j) sweepAgainst(j);
        } else {
            for (std::size_t j : static_) sweepAgainst(j);
        }
        sweeps_.push_back({i, start.center, shape.center(), first});
        if (!first) continue;
        // Back to the time of impact: the rest of the step's motion is not made.
        shape.move(start.center + offset * *first - shape.center());
        shape.rotate(start.angle + turn * *first - shape.angle());
    }
}

}  // namespace engine
