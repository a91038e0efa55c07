#include "page_world.h"

#include <algorithm>

#include "continuous.h"
#include "number_format.h"
#include "scene_io.h"

namespace engine {

namespace {

// The sequential impulse solver keeps a contact for every touching pair, this step's
// and last step's (for warm starting): 1,250 bytes a pair measured with 500 circles on
// one point. The book's passes keep only the colliding pairs of a pass: 100 bytes a pair,
// measured in 4.1.
constexpr double kContactBytes = 1300.0;
constexpr double kCollisionBytes = 100.0;

// A fast shape swept against another (continuous.cpp) measures the gap between their
// outlines up to kMaxAdvances times, and once more for every doubling of the depth it
// tries when the two already touch where the step began: from 0.5 px up to three
// quarters of the smallest extent, 5e4 px at most, 18 depths; then its centre's path,
// about one gap more. A gap between two rectangles, the dearest, takes about 360 ns with
// the separating axes that see two of them crossing, some 8 pair tests (measured with
// continuous.h's moved and gap).
constexpr double kDepthsTried = 19.0;
constexpr double kGapCost = 8.0;  // pair tests
constexpr double kSweptPairCost = (kMaxAdvances + kDepthsTried) * kGapCost;

double pairsOf(double shapes) { return shapes * (shapes - 1.0) / 2.0; }

// --events FILE: every collision event of the run, a line each, in the order the step
// told them (contact_events.h). Numbers carry 17 digits, as the dump's, so that a
// reader's script may find the very point and speed again.
constexpr std::string_view kEventsHeader = "step,kind,id_a,id_b,x,y,nx,ny,speed";

void appendEvent(std::string& lines, const ContactEvent& event) {
    lines.append(std::to_string(event.step)).append(",").append(kindName(event.kind));
    lines.append(",").append(std::to_string(event.id_a)).append(",").append(std::to_string(event.id_b));
    for (const double value : {event.point.x, event.point.y, event.normal.x, event.normal.y, event.speed}) {
        lines += ',';
        browser::append_round_trip(lines, value + 0.0);  // + 0.0: a normal's -0 reads as 0
    }
    lines += '\n';
}

}  // namespace

browser::WorldCost worldCost(const Core& core, const browser::KeyScript& keys) {
    const WorldSettings& world = core.settings();
    static const browser::KeySet kAdding = browser::KeySet::parse("f g");      // a new rectangle / circle
    static const browser::KeySet kMakingStatic = browser::KeySet::parse("z");  // mass -1: 0 is static
    double bullets = 0.0, statics = 0.0;
    for (std::size_t i = 0; i < core.objectCount(); ++i) {
        bullets += core.object(i).isBullet() ? 1.0 : 0.0;
        statics += core.object(i).isStatic() ? 1.0 : 0.0;
    }
    const double shapes = static_cast<double>(core.objectCount()) + static_cast<double>(keys.pressCount(kAdding));
    statics = std::min(shapes, statics + static_cast<double>(keys.pressCount(kMakingStatic)));
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
    // Continuous collision sweeps every fast shape against the static shapes, and a
    // fast bullet against every shape: at worst every shape is fast.
    const double swept_pairs = world.continuous ? bullets * shapes + (shapes - bullets) * statics : 0.0;
    const double substep_work = passes * pairs + shapes + swept_pairs * kSweptPairCost;
    // From 4.3 on a frame draws no collisions, only the shapes.
    return {.step_s = world.dt,
            .step_work = world.substeps * substep_work,
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
                                           .id = shape.id(),
                                           .center = shape.center(),
                                           .angle = shape.angle(),
                                           .velocity = shape.velocity(),
                                           .angular_velocity = shape.angularVelocity()});
                    }
                    return objects;
                },
            .on_step = [&core](std::function<void()> listener) { core.onStep(std::move(listener)); },
            .cost = [&core](const browser::KeyScript& keys) { return worldCost(core, keys); },
            .logs = {{.option = std::string(kEventsOption),
                      .what = "event list",
                      .header = std::string(kEventsHeader),
                      .start = [&core] { core.keepEvents(true); },
                      .append =
                          [&core](std::string& lines) {
                              for (const ContactEvent& event : core.events().events()) appendEvent(lines, event);
                          }}}};
}

}  // namespace engine
