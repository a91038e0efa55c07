#include "circle.h"

#include <numbers>

namespace engine {

Circle::Circle(Vec2 center, double radius, bool fixed)
    : RigidShape(ShapeType::Circle, center, fixed), radius_(radius), startpoint_(center.x, center.y - radius) {}

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
