#include "polygon.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "convex_hull.h"
#include "polygon_mass.h"
#include "rectangle.h"

namespace engine {

namespace {

// The hull of the corners, moved so that its centre of area is the origin; the reason
// as InvalidShape when there is none.
ConvexPolygon bodyFrom(std::span<const Vec2> corners) {
    const HullResult hull = convexHull(corners);
    if (!hull.hull) throw InvalidShape("polygon corners: " + hull.refusal);
    const PolygonMass mass = polygonMass(hull.hull->corners());
    return movedBy(*hull.hull, Vec2{} - mass.centroid);
}

// randomCorners' ranges: a radius of 12 to 30 px, 3 to 8 corners.
constexpr double kRandomRadiusMin = 12.0, kRandomRadiusRange = 18.0;
constexpr int kFewestCorners = 3, kCornerChoices = 6;
// Each corner lies within the middle 70 % of its share of the turn: 15 % kept clear at
// either end.
constexpr double kShareMargin = 0.15, kShareUsed = 0.7;

double farthestCorner(const ConvexPolygon& body) {
    double farthest = 0.0;
    for (const Vec2 corner : body.corners()) farthest = std::max(farthest, corner.length());
    return farthest;
}

}  // namespace

Polygon::Polygon(Vec2 center, std::span<const Vec2> corners, PhysicalAttributes attributes)
    : Polygon(center, bodyFrom(corners), attributes) {}

// The bounding circle reaches the farthest corner from the centre of area.
Polygon::Polygon(Vec2 center, const ConvexPolygon& body, PhysicalAttributes attributes)
    : RigidShape(ShapeType::Polygon, center, farthestCorner(body), attributes),
      body_(body),
      outline_(movedBy(body, center)),
      inertia_per_mass_(polygonMass(body.corners()).inertia_per_mass) {
    updateInertia();
}

double Polygon::rotationalInertia(double mass) const { return mass * inertia_per_mass_; }

void Polygon::move(Vec2 offset) {
    outline_ = movedBy(outline_, offset);
    center_ = center_ + offset;
}

void Polygon::rotate(double angle) {
    // Turned from the body's own corners every time, not from the last turn's: the
    // corners never drift from the shape through a pile of small turns, and the normals
    // are made anew from them, unit length and square to their faces.
    angle_ += angle;
    std::vector<Vec2> turned;
    turned.reserve(body_.count);
    for (const Vec2 corner : body_.corners()) turned.push_back(corner.rotate(Vec2{}, angle_) + center_);
    outline_ = makeConvexPolygon(turned);
}

void Polygon::draw(browser::Canvas& context) const {
    context.beginPath();
    context.moveTo(outline_.vertices[0].x, outline_.vertices[0].y);
    for (std::size_t i = 1; i < outline_.count; ++i) context.lineTo(outline_.vertices[i].x, outline_.vertices[i].y);
    context.closePath();
    context.stroke();
}

std::vector<Vec2> randomCorners(browser::Random& random) {
    const int count = kFewestCorners + static_cast<int>(random.next() * kCornerChoices);
    const double radius = kRandomRadiusMin + random.next() * kRandomRadiusRange;
    const double start = random.next() * 2 * std::numbers::pi;
    std::vector<Vec2> corners;
    for (int k = 0; k < count; ++k) {
        const double share = (k + kShareMargin + kShareUsed * random.next()) / count;
        const double angle = start + share * 2 * std::numbers::pi;
        corners.push_back(Vec2{std::cos(angle), std::sin(angle)} * radius);
    }
    return corners;
}

ConvexPolygon outlineOf(const Rectangle& rectangle) { return makeConvexPolygon(rectangle.vertices()); }

ConvexPolygon cornersOf(const RigidShape& shape) {
    if (shape.type() == ShapeType::Rectangle) return outlineOf(static_cast<const Rectangle&>(shape));
    return static_cast<const Polygon&>(shape).outline();
}

}  // namespace engine
