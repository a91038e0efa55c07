#include "broad_phase.h"

#include <limits>

namespace engine {

void BroadPhase::startStep(ShapeList shapes, int passes) {
    statistics_ = {};
    shapes_ = shapes;
    circles_.assign(shapes);
    if (kind_ == BroadPhaseKind::grid && !grid_.fits(circles_)) grid_.listPairs(circles_);

    // The clock (see the top of broad_phase.h): pass p's ticks start at (p + 1) n^2, and
    // every shape counts as touched at pass 0's start.
    const std::uint64_t count = shapes.size();
    constexpr std::uint64_t kLargest = std::numeric_limits<std::uint64_t>::max();
    const auto ticks_per_step = static_cast<std::uint64_t>(passes) + 2;
    skipping_ = count < (std::uint64_t{1} << 32) && count * count <= kLargest / ticks_per_step;
    square_ = count * count;
    pass_tick_ = square_;
    touched_at_.assign(shapes.size(), square_);
    resting_.assign(shapes.size(), kAwake);
    noteResting();
}

// A shape woken in the middle of a pass had its pairs with other sleepers passed over
// until now, untested: the skip rule must not take them for known apart. So it counts
// as touched at the end of this pass, later than it really was, which only makes the
// rule skip less.
void BroadPhase::noteResting() {
    for (std::size_t i = 0; i < shapes_.size(); ++i) {
        const RigidShape& shape = *shapes_[i];
        const Rest resting = shape.isStatic() ? kStatic : shape.sleep().asleep ? kAsleep : kAwake;
        if (resting_[i] == kAsleep && resting == kAwake) touched_at_[i] = pass_tick_ + square_ - 1;
        resting_[i] = resting;
    }
}

}  // namespace engine
