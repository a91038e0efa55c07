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
}

}  // namespace engine
