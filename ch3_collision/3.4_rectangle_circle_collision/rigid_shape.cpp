#include "rigid_shape.h"

namespace engine {

// Every shape starts unturned; angle_ keeps count of the turns that follow.
RigidShape::RigidShape(ShapeType type, Vec2 center, double bound_radius)
    : type_(type), center_(center), bound_radius_(bound_radius) {}

bool RigidShape::boundTest(const RigidShape& other) const {
    // Two circles overlap exactly when their centres are no farther apart than their
    // radii added up; at exactly that distance they touch, which counts.
    return center_.distance(other.center_) <= bound_radius_ + other.bound_radius_;
}

void RigidShape::update() {}

}  // namespace engine
