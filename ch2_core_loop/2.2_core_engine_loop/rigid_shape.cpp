#include "rigid_shape.h"

namespace engine {

// Every shape starts unturned; angle_ keeps count of the turns that follow.
RigidShape::RigidShape(ShapeType type, Vec2 center, bool fixed) : type_(type), center_(center), fixed_(fixed) {}

void RigidShape::update(double canvas_height) {
    // +y points down the canvas, so sinking is a step of +1 in y.
    if (center_.y < canvas_height && !fixed_) move({0, 1});
}

}  // namespace engine
