// The narrow phase for a rectangle (the book's RigidBody/Rectangle_collision.js).
#include "rectangle.h"

namespace engine {

// Rectangles collide with nothing yet: the tests come in the next two projects.
std::optional<CollisionInfo> Rectangle::collisionTest(const RigidShape&) const { return std::nullopt; }

}  // namespace engine
