#include "page_world.h"

#include <algorithm>

#include "scene_io.h"

namespace engine {

namespace {

// The sequential impulse solver keeps a contact for every touching pair, this step's
// and last step's (for warm starting): 1,250 bytes a pair measured with 500 circles on
// one point. The book's passes keep only the colliding pairs of a pass: 100 bytes a pair,
// measured in 4.1.
constexpr double kContactBytes = 1300.0;
constexpr double kCollisionBytes = 100.0;

double pairsOf(double shapes) { return shapes * (shapes - 1.0) / 2.0; }

}  // namespace

browser::WorldCost worldCost(const Core& core, const browser::KeyScript& keys) {
    const WorldSettings& world = core.settings();
    static const browser::KeySet kAdding = browser::KeySet::parse("f g");  // a new rectangle / circle
    const double shapes = static_cast<double>(core.objectCount()) + static_cast<double>(keys.pressCount(kAdding));
    const double pairs = pairsOf(shapes);
    const bool book = world.solver == SolverKind::book;
    // The book's relaxation makes its passes over the pairs; the sequential impulse
    // solver finds the pairs once, then goes over every contact once a velocity
    // iteration and once a position iteration: at worst every pair is a contact, so a
    // pass over the contacts counts as a pass over the pairs. The islands of sleeping
    // walk the contacts once more, and with the sequential impulse solver a wake in the
    // middle of its pass over the pairs runs that pass again (contact_solver.h).
    double passes =
        book ? std::max(world.relaxation_iterations, 1) : 1.0 + world.velocity_iterations + world.position_iterations;
    if (world.sleep) passes += book ? 1.0 : 2.0;
    // From 4.3 on a frame draws no collisions, only the shapes.
    return {.step_s = world.dt,
            .step_work = world.substeps * (passes * pairs + shapes),
            .bytes = pairs * (book ? kCollisionBytes : kContactBytes),
            .objects = shapes,
            .objects_word = "shapes",
            .work_word = "pair tests",
            .memory_word = "of contacts (all of them in contact)",
            .lighter = "passes or sub-steps, or a longer dt"};
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
