#pragma once
// The narrow phase on its own: the exact test of one pair, and what a pass records of a
// pair that collides. In the book it lives in the physics component; from 5.4 on there are two
// users of it, the book's relaxation passes (physics.h) and the contact solver
// (contact_solver.h), so it sits below both, and neither includes the other.

#include <cstddef>
#include <optional>

#include "collision_info.h"
#include "rigid_shape.h"

namespace engine {

// Two shapes the pass found colliding, by their places in the list; first < second.
struct Collision {
    std::size_t first;
    std::size_t second;
    CollisionInfo info;  // its normal points from the first shape towards the second
};

// The narrow phase. The info's normal is turned, where needed, to point from `a`
// towards `b`, whichever shape's test worked it out.
std::optional<CollisionInfo> narrowPhase(const RigidShape& a, const RigidShape& b);
// The book's broad phase, the bounding circles, then the narrow phase.
std::optional<CollisionInfo> findCollision(const RigidShape& a, const RigidShape& b);

}  // namespace engine
