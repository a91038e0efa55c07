#include "broad_phase.h"

namespace engine {

void BroadPhase::startStep(ShapeList shapes) {
    statistics_ = {};
    shapes_ = shapes;
    circles_.assign(shapes);
    if (kind_ == BroadPhaseKind::grid && !grid_.fits(circles_)) grid_.listPairs(circles_);
}

}  // namespace engine
