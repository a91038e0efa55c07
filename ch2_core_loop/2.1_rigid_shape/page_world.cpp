#include "page_world.h"

namespace engine {

namespace {

// Drawing a shape costs about 9 us (its outline, on the 800 x 450 canvas), some 200
// units.
constexpr double kDrawnShapeCost = 200.0;

}  // namespace

browser::WorldCost worldCost(const Core& core, const browser::KeyScript& keys) {
    static const browser::KeySet kAdding = browser::KeySet::parse("f g");  // a new rectangle / circle
    const double shapes = static_cast<double>(core.objectCount()) + static_cast<double>(keys.pressCount(kAdding));
    // No engine loop yet: every frame only draws the shapes.
    return {.frame_work = shapes * kDrawnShapeCost, .objects = shapes, .objects_word = "shapes"};
}

browser::PageWorld pageWorld(Core& core) {
    return {.cost = [&core](const browser::KeyScript& keys) { return worldCost(core, keys); }};
}

}  // namespace engine
