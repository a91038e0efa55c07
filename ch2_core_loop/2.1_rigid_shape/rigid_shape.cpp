#include "rigid_shape.h"

namespace engine {

// Every shape starts unturned; angle_ keeps count of the turns that follow.
RigidShape::RigidShape(ShapeType type, Vec2 center) : type_(type), center_(center) {}

}  // namespace engine
