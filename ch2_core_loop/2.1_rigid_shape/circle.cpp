#include "circle.h"

#include <numbers>

namespace engine {

Circle::Circle(Vec2 center, double radius)
    : RigidShape(ShapeType::Circle, center), radius_(radius), startpoint_(center.x, center.y - radius) {}

void Circle::draw(browser::Canvas& context) const {
    context.beginPath();
    context.arc(center_.x, center_.y, radius_, 0.0, 2.0 * std::numbers::pi, true);
    context.moveTo(startpoint_.x, startpoint_.y);
    context.lineTo(center_.x, center_.y);
    context.closePath();
    context.stroke();
}

}  // namespace engine
