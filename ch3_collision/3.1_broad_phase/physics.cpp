#include "physics.h"

namespace engine {

void Physics::collision(ShapeList shapes) {
    collisions_.clear();
    for (std::size_t i = kFirstTestedObject; i < shapes.size(); ++i) {
        for (std::size_t j = i + 1; j < shapes.size(); ++j) {
            if (shapes[i]->boundTest(*shapes[j])) collisions_.push_back({i, j});
        }
    }
}

void Physics::drawCollisions(browser::Canvas& context, ShapeList shapes) const {
    context.setStrokeStyle(browser::colors::kGreen);
    for (const Collision& pair : collisions_) {
        shapes[pair.first]->draw(context);
        shapes[pair.second]->draw(context);
    }
}

}  // namespace engine
