#include "circle.h"

#include <numbers>

namespace engine {

namespace {
// A solid disc's moment of inertia about its centre: I = m r^2 / 2. (The book writes
// m r^2 / 12 and never inverts it; see docs/errata.md, "Circle inertia".)
constexpr double kDiscInertiaDivisor = 2.0;
}  // namespace

// A circle is its own bounding circle.
Circle::Circle(Vec2 center, double radius, PhysicalAttributes attributes)
    : RigidShape(ShapeType::Circle, center, checkedSize(radius, "circle radius"), attributes),
      radius_(radius),
      startpoint_(center.x, center.y - radius) {
    updateInertia();
}

double Circle::rotationalInertia(double mass) const { return mass * radius_ * radius_ / kDiscInertiaDivisor; }

void Circle::move(Vec2 offset) {
    startpoint_ = startpoint_.add(offset);
    center_ = center_.add(offset);
}

void Circle::rotate(double angle) {
    // Only the reference point shows a circle's turn: it goes round the centre.
    angle_ += angle;
    startpoint_ = startpoint_.rotate(center_, angle);
}

void Circle::draw(browser::Canvas& context) const {
    context.beginPath();
    context.arc(center_.x, center_.y, radius_, 0.0, 2.0 * std::numbers::pi, true);
    context.moveTo(startpoint_.x, startpoint_.y);
    context.lineTo(center_.x, center_.y);
    context.closePath();
    context.stroke();
}

}  // namespace engine
