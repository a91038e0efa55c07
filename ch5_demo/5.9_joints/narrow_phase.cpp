#include "narrow_phase.h"

namespace engine {

std::optional<CollisionInfo> findCollision(const RigidShape& a, const RigidShape& b) {
    if (!a.boundTest(b)) return std::nullopt;
    return narrowPhase(a, b);
}

std::optional<CollisionInfo> narrowPhase(const RigidShape& a, const RigidShape& b) {
    std::optional<CollisionInfo> info = a.collisionTest(b);
    // A normal with a negative component along the line between the centres points
    // from b towards a.
    if (info && info->normal().dot(b.center() - a.center()) < 0) info->changeDir();
    return info;
}

}  // namespace engine
