#include "scene_io.h"

#include <algorithm>
#include <cmath>
#include <iterator>

#include "circle.h"
#include "rectangle.h"

namespace engine {

namespace {

RigidShape& addBody(Core& core, const browser::BodyDescription& body) {
    const PhysicalAttributes attributes{.mass = body.mass, .friction = body.friction, .restitution = body.restitution};
    if (body.shape == browser::ShapeKind::circle) return core.add(Circle(body.center, body.radius, attributes));
    return core.add(Rectangle(body.center, body.width, body.height, attributes));
}

// The engine's type in the browser's terms; the name a file spells is shape_name's alone.
browser::ShapeKind kindOf(const RigidShape& shape) {
    return shape.type() == ShapeType::Circle ? browser::ShapeKind::circle : browser::ShapeKind::rectangle;
}

}  // namespace

// Sub-steps and the solver's velocity sweeps: each runs a share of a step's work again,
// at least once; 1000 keeps a step's work bounded.
constexpr browser::NumberRule kRepeats{[](double v) { return v >= 1.0 && v <= 1000.0 && std::floor(v) == v; },
                                       "must be a whole number in [1, 1000]"};

// A slop of more than a few pixels would let shapes sink visibly; 100 keeps typos out.
constexpr browser::NumberRule kSlopRule{[](double v) { return v >= 0.0 && v <= 100.0; },
                                        "must be a number of px in [0, 100]"};
constexpr browser::NumberRule kSpeedRule{[](double v) { return std::isfinite(v) && v >= 0.0; },
                                         "must be a finite speed >= 0"};

constexpr browser::NumberRule kDurationRule{[](double v) { return std::isfinite(v) && v >= 0.0; },
                                            "must be a finite number of s >= 0"};

std::vector<browser::WorldKey> worldKeys(WorldSettings& world) {
    namespace rules = browser::rules;
    return {
        {"width", world.width, rules::kCanvasSize},
        {"height", world.height, rules::kCanvasSize},
        {"gravity", world.gravity, rules::kAcceleration},
        {"dt", world.dt, rules::kTimeStep},
        {"movement", world.movement},
        {"relaxation_iterations", world.relaxation_iterations, rules::kPassCount},
        {"correction_rate", world.correction_rate, rules::kFraction},
        {"positional_correction", world.positional_correction},
        {"remove_out_of_bounds", world.remove_out_of_bounds},
        {"broad_phase",
         world.broad_phase,
         {{"bounding_circle", BroadPhaseKind::bounding_circle},
          {"all_pairs", BroadPhaseKind::all_pairs},
          {"grid", BroadPhaseKind::grid}}},
        {"substeps", world.substeps, kRepeats},
        {"integrator",
         world.integrator,
         {{"symplectic", Integrator::symplectic}, {"explicit", Integrator::explicit_euler}}},
        {"friction_model", world.friction_model, {{"book", FrictionModel::book}, {"coulomb", FrictionModel::coulomb}}},
        {"rotation", world.rotation},
        {"friction", world.friction},
        {"solver", world.solver, {{"book", SolverKind::book}, {"sequential_impulse", SolverKind::sequential_impulse}}},
        {"velocity_iterations", world.velocity_iterations, kRepeats},
        {"position_iterations", world.position_iterations, rules::kPassCount},
        {"warm_starting", world.warm_starting},
        {"restitution_threshold", world.restitution_threshold, kSpeedRule},
        {"position_method",
         world.position_method,
         {{"split_impulse", PositionMethod::split_impulse},
          {"baumgarte", PositionMethod::baumgarte},
          {"relax", PositionMethod::relax}}},
        {"position_rate", world.position_rate, rules::kFraction},
        {"slop", world.slop, kSlopRule},
        {"sleep", world.sleep},
        {"sleep_speed", world.sleep_speed, kSpeedRule},
        {"time_to_sleep", world.time_to_sleep, kDurationRule},
    };
}

Scene loadScene(const std::filesystem::path& file) {
    Scene scene;
    scene.bodies = browser::load_scene(file, worldKeys(scene.world));
    return scene;
}

void buildScene(Core& core, const std::vector<browser::BodyDescription>& bodies) {
    for (const browser::BodyDescription& body : bodies) {
        RigidShape& shape = addBody(core, body);
        shape.rotate(body.angle);
        shape.setVelocity(body.velocity);
        shape.setAngularVelocity(body.angular_velocity);
    }
}

void dumpState(browser::StateDump& dump, const Core& core) {
    for (std::size_t i = 0; i < core.objectCount(); ++i) {
        const RigidShape& shape = core.object(i);
        dump.row(core.stepCount(), i, shape.id(), browser::shape_name(kindOf(shape)), shape.center(), shape.angle(),
                 shape.velocity(), shape.angularVelocity());
    }
}

void checkFinite(const Core& core) {
    for (std::size_t i = 0; i < core.objectCount(); ++i) {
        const RigidShape& shape = core.object(i);
        const double numbers[] = {shape.center().x,   shape.center().y,   shape.angle(),
                                  shape.velocity().x, shape.velocity().y, shape.angularVelocity()};
        if (!std::all_of(std::begin(numbers), std::end(numbers), [](double v) { return std::isfinite(v); })) {
            throw browser::NonFiniteState(core.stepCount(), i, browser::shape_name(kindOf(shape)));
        }
    }
}

browser::StepCost stepCost(const Core& core) {
    const WorldSettings& world = core.settings();
    // The sequential impulse solver finds the pairs once a sub-step, then goes over
    // every contact once a velocity iteration and once a position iteration; at worst
    // every pair is a contact, so a pass over the contacts counts as a pass over the
    // pairs.
    const int passes = world.solver == SolverKind::book ? world.relaxation_iterations
                                                        : 1 + world.velocity_iterations + world.position_iterations;
    // The sequential impulse solver keeps a contact for every touching pair, this step's
    // and last step's (for warm starting): 1,250 bytes a pair measured with 500 circles
    // on one point. The book's passes keep only the collisions they draw.
    const double bytes_a_contact = world.solver == SolverKind::book ? browser::StepCost{}.bytes_a_contact : 1300.0;
    // From 4.3 on a frame draws no collisions, only the shapes.
    return {.dt_s = world.dt,
            .substeps = world.substeps,
            .passes = passes,
            .shapes = core.objectCount(),
            .draws_pairs = false,
            .bytes_a_contact = bytes_a_contact};
}

}  // namespace engine
