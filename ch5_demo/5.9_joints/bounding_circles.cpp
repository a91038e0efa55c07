#include "bounding_circles.h"

namespace engine {

void BoundingCircles::assign(ShapeList shapes) {
    const std::size_t count = shapes.size();
    x_.resize(count);
    y_.resize(count);
    radius_.resize(count);
    is_static_.resize(count);
    for (std::size_t i = 0; i < count; ++i) {
        refresh(i, *shapes[i]);
        radius_[i] = shapes[i]->boundRadius();
        is_static_[i] = shapes[i]->isStatic();
    }
}

}  // namespace engine
