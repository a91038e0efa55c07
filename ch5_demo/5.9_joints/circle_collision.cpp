// The narrow phase for a circle (the book's RigidBody/Circle_collision.js).
#include "circle.h"

#include "rectangle.h"

namespace engine {

namespace {
// Concentric circles give no direction to part them; the book pushes straight up.
constexpr Vec2 kConcentricNormal{0, -1};
}  // namespace

std::optional<CollisionInfo> Circle::collisionTest(const RigidShape& other) const {
    if (other.type() == ShapeType::Circle) return collidedCircCirc(static_cast<const Circle&>(other));
    if (other.type() == ShapeType::Polygon)
        return turnedRound(other.collisionTest(*this));  // 5.8's polygon_collision.cpp
    // The rectangle works it out, with its normal pointing towards this circle: from
    // the other shape to this one. The pass turns it round.
    return static_cast<const Rectangle&>(other).collidedRectCirc(*this);
}

// Figure 3-8: two circles overlap by the radii added up minus the distance between
// their centres, along the line through the centres. The overlap starts at the point of
// the other circle's rim nearest this centre and ends on this circle's rim.
std::optional<CollisionInfo> Circle::collidedCircCirc(const Circle& other) const {
    const Vec2 from_this_to_other = other.center_ - center_;
    const double radius_sum = radius_ + other.radius_;
    const double distance = from_this_to_other.length();
    if (distance > radius_sum) return std::nullopt;

    if (distance != 0) {
        const Vec2 normal = from_this_to_other.normalize();
        return CollisionInfo(radius_sum - distance, normal, other.center_ - normal * other.radius_);
    }
    // Same centre: moving either circle by both radii, straight up, parts them. The
    // segment runs up from the bottom of the larger circle to the top of the smaller.
    const Circle& larger = radius_ > other.radius_ ? *this : other;
    return CollisionInfo(radius_sum, kConcentricNormal, larger.center_ - kConcentricNormal * larger.radius_);
}

}  // namespace engine
