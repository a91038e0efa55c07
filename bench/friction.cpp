// Friction, against two closed-form answers.
// Sliding: a box sliding on a floor under Coulomb friction decelerates at mu g, so from
// v it stops after v^2 / (2 mu g). Rolling: a disc rolling down a slope without
// slipping has a = g sin(angle) / (1 + I / (m r^2)) = 2/3 g sin(angle) for a solid
// disc (I = m r^2 / 2), so from rest it has run a t^2 / 2 after t.

#include <cmath>
#include <stdexcept>
#include <vector>

#include "markdown.h"
#include "scene_maker.h"
#include "sweep_study.h"

namespace bench {
namespace {

constexpr double kSlideSeconds = 8.0;  // the Coulomb slide stops after v / (mu g) = 4 s
constexpr double kRollSeconds = 2.0;

std::size_t first_moving(const Snapshot& bodies) {
    for (std::size_t i = 0; i < bodies.size(); ++i) {
        if (!bodies[i].is_static) return i;
    }
    throw std::invalid_argument("the scene has no moving body");
}

// Both friction studies turn the same knobs: the friction law, and the knobs of passes,
// step, integrator, rotation and solver that the error could come from instead.
std::vector<Sweep> friction_knobs() {
    return {{Knob::friction_model},
            {Knob::relaxation_iterations},
            {Knob::dt},
            {Knob::substeps},
            {Knob::integrator},
            {Knob::rotation},
            {Knob::solver}};
}

Measure slide_distance() {
    return [](BenchWorld& world, const WorldDescription& settings) {
        const Snapshot start = world.snapshot();
        const std::size_t box = first_moving(start);
        world.run(steps_for(kSlideSeconds, settings.dt));
        const double distance = oracle::center(world.snapshot()[box].shape).x - oracle::center(start[box].shape).x;
        const double speed = start[box].velocity.length();
        const double coulomb = speed * speed / (2 * scenes::kSlideFriction * settings.gravity.y);
        Metrics metrics;
        metrics.slide_error = distance / coulomb - 1;
        return metrics;
    };
}

Measure roll_distance() {
    return [](BenchWorld& world, const WorldDescription& settings) {
        const Snapshot start = world.snapshot();
        const std::size_t ball = first_moving(start);
        const long steps = steps_for(kRollSeconds, settings.dt);
        world.run(steps);
        const double t = static_cast<double>(steps) * settings.dt;
        const Vec2 down_slope{std::cos(scenes::kSlopeAngle), std::sin(scenes::kSlopeAngle)};
        const double run =
            (oracle::center(world.snapshot()[ball].shape) - oracle::center(start[ball].shape)).dot(down_slope);
        const double exact = 2.0 / 3.0 * settings.gravity.y * std::sin(scenes::kSlopeAngle) * t * t / 2;
        Metrics metrics;
        metrics.roll_error = run / exact - 1;
        return metrics;
    };
}

}  // namespace

StudyResult slide_study(const StudyContext& context) {
    SweepPlan plan;
    plan.study = "slide";
    plan.heading = "Friction: a sliding box";
    plan.question =
        "A 40 × 20 box slides at " + figure(scenes::kSlideSpeed) + " px/s on a static floor, friction " +
        figure(scenes::kSlideFriction) + " on both, gravity " + figure(scenes::kSlideGravity) +
        " px/s². Coulomb's law stops it after v²/(2 μ g) = " +
        figure(scenes::kSlideSpeed * scenes::kSlideSpeed / (2 * scenes::kSlideFriction * scenes::kSlideGravity)) +
        " px; *slide error* is how much further (+) or shorter (-) it went in " + figure(kSlideSeconds) +
        " s. The book's friction model is not Coulomb's (docs/errata.md, \"Friction\").";
    plan.knobs = friction_knobs();
    plan.measure = slide_distance();
    plan.error = {"size of the slide error (share of Coulomb's distance)",
                  [](const Metrics& m) { return m.slide_error; }, 1e-4};
    plan.columns = {{"slide error", [](const Row& r) { return percent(r.metrics.slide_error); }}};
    StudyResult result = run_sweep(context, plan);
    // The book's friction is the oldest stage's own; Coulomb's the row that asks for it.
    std::string key = "Sliding box against Coulomb's v²/(2 μ g): the book's friction (stage " +
                      stage_name(result.rows.front().stage) + ") " + percent(result.rows.front().metrics.slide_error);
    for (const Row& row : result.rows) {
        if (row.world.friction_model == FrictionModel::coulomb) {
            key += ", Coulomb's (stage " + stage_name(row.stage) + ") " + percent(row.metrics.slide_error);
        }
    }
    result.key_figures.push_back(key + ".");
    return result;
}

StudyResult slope_study(const StudyContext& context) {
    SweepPlan plan;
    plan.study = "slope";
    plan.heading = "Friction: a disc rolling down a slope";
    plan.question = "A disc (radius 20, friction 0.8) starts at rest on a static slope of " +
                    figure(scenes::kSlopeAngle) + " rad, gravity " + figure(scenes::kSlopeGravity) +
                    " px/s². Rolling without slipping it runs (1/3) g sin(angle) t² down the slope in t; "
                    "*roll error* is how much further (+) or shorter (-) it ran in " +
                    figure(kRollSeconds) +
                    " s. Without rotation it cannot roll, and friction holds it or lets it slide.";
    plan.knobs = friction_knobs();
    plan.measure = roll_distance();
    plan.error = {"size of the roll error (share of the exact run)", [](const Metrics& m) { return m.roll_error; },
                  1e-4};
    plan.columns = {{"roll error", [](const Row& r) { return percent(r.metrics.roll_error); }}};
    return run_sweep(context, plan);
}

}  // namespace bench
