#include "page_world.h"

#include <algorithm>

#include "scene_io.h"

namespace engine {

namespace {

// The collision passes keep the colliding pairs of a pass: 100 bytes a pair, measured in
// 4.1 (3,160 shapes on one point took about 500 MB).
constexpr double kCollisionBytes = 100.0;

double pairsOf(double shapes) { return shapes * (shapes - 1.0) / 2.0; }

}  // namespace

browser::WorldCost worldCost(const Core& core, const browser::KeyScript& keys) {
    const WorldSettings& world = core.settings();
    static const browser::KeySet kAdding = browser::KeySet::parse("f g");  // a new rectangle / circle
    const double shapes = static_cast<double>(core.objectCount()) + static_cast<double>(keys.pressCount(kAdding));
    const double pairs = pairsOf(shapes);
    // Every collision pass goes over every pair; then every shape moves.
    const double passes = std::max(world.relaxation_iterations, 1);
    // From 4.3 on a frame draws no collisions, only the shapes.
    return {.step_s = world.dt,
            .step_work = passes * pairs + shapes,
            .bytes = pairs * kCollisionBytes,
            .objects = shapes,
            .objects_word = "shapes",
            .work_word = "pair tests",
            .memory_word = "of contacts (all of them in contact)",
            .lighter = "passes, or a longer dt"};
}

browser::PageWorld pageWorld(Core& core) {
    return {.steps = [&core] { return core.stepCount(); },
            .objects =
                [&core] {
                    std::vector<browser::ObjectState> objects;
                    objects.reserve(core.objectCount());
                    for (std::size_t i = 0; i < core.objectCount(); ++i) {
                        const RigidShape& shape = core.object(i);
                        objects.push_back({.kind = shapeName(shape.type()),
                                           .center = shape.center(),
                                           .angle = shape.angle(),
                                           .velocity = shape.velocity(),
                                           .angular_velocity = shape.angularVelocity()});
                    }
                    return objects;
                },
            .on_step = [&core](std::function<void()> listener) { core.onStep(std::move(listener)); },
            .cost = [&core](const browser::KeyScript& keys) { return worldCost(core, keys); }};
}

}  // namespace engine
