#include "physics.h"

namespace engine {

std::optional<CollisionInfo> findCollision(const RigidShape& a, const RigidShape& b) {
    if (!a.boundTest(b)) return std::nullopt;
    std::optional<CollisionInfo> info = a.collisionTest(b);
    // A normal with a negative component along the line between the centres points
    // from b towards a.
    if (info && info->normal().dot(b.center() - a.center()) < 0) info->changeDir();
    return info;
}

void Physics::collision(ShapeList shapes) {
    // The narrow phase is exact, so the cursor and the borders can take part again.
    collisions_.clear();
    for (std::size_t i = 0; i < shapes.size(); ++i) {
        for (std::size_t j = i + 1; j < shapes.size(); ++j) {
            if (auto info = findCollision(*shapes[i], *shapes[j])) collisions_.push_back({i, j, *info});
        }
    }
}

void Physics::drawCollisions(browser::Canvas& context) const {
    context.setStrokeStyle(browser::colors::kOrange);
    for (const Collision& pair : collisions_) {
        context.beginPath();
        context.moveTo(pair.info.start().x, pair.info.start().y);
        context.lineTo(pair.info.end().x, pair.info.end().y);
        context.stroke();
    }
}

}  // namespace engine
