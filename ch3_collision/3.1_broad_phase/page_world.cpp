#include "page_world.h"

namespace engine {

namespace {

// Drawing a shape costs about 9 us (its outline, on the 800 x 450 canvas), some 200
// units.
constexpr double kDrawnShapeCost = 200.0;

// The collision pass keeps the colliding pairs it finds: 100 bytes a pair, measured in
// 4.1 (3,160 shapes on one point took about 500 MB).
constexpr double kCollisionBytes = 100.0;

// Every frame draws a line for every pair that collides: up to some 20 us a line across a
// few hundred pixels, a thousand units at most.
constexpr double kDrawnPairCost = 1000.0;

double pairsOf(double shapes) { return shapes * (shapes - 1.0) / 2.0; }

}  // namespace

browser::WorldCost worldCost(const Core& core, const browser::KeyScript& keys) {
    static const browser::KeySet kAdding = browser::KeySet::parse("f g");  // a new rectangle / circle
    const double shapes = static_cast<double>(core.objectCount()) + static_cast<double>(keys.pressCount(kAdding));
    const double pairs = pairsOf(shapes);
    // Every fixed step tests every pair and moves every shape; every frame draws the
    // shapes and a line for every pair that collides, at worst every pair.
    return {.step_s = kFrameTime,
            .step_work = pairs + shapes,
            .frame_work = pairs * kDrawnPairCost + shapes * kDrawnShapeCost,
            .bytes = pairs * kCollisionBytes,
            .objects = shapes,
            .objects_word = "shapes",
            .memory_word = "of collisions (all of them colliding)"};
}

browser::PageWorld pageWorld(Core& core) {
    return {.cost = [&core](const browser::KeyScript& keys) { return worldCost(core, keys); }};
}

}  // namespace engine
