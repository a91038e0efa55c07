// Energy: an elastic gas (restitution 1, no friction, no gravity) in a closed box.
// Every collision should give back all the energy it takes, so the total kinetic
// energy should stay what it was. Positional correction moves shapes without asking
// about energy, and the relaxation applies impulses pair by pair; what the energy does
// over many steps shows how far from elastic the collisions really are.

#include "markdown.h"
#include "measures.h"
#include "sweep_study.h"

namespace bench {
namespace {

constexpr long kSteps = 10'000;
constexpr long kQuickSteps = 50;

Measure energy_drift(long steps) {
    return [steps](BenchWorld& world, const WorldDescription&) {
        const double before = kinetic_energy(world.snapshot());
        world.run(steps);
        Metrics metrics;
        metrics.energy_change = (kinetic_energy(world.snapshot()) - before) / before;
        return metrics;
    };
}

}  // namespace

StudyResult gas_study(const StudyContext& context) {
    const long steps = context.quick ? kQuickSteps : kSteps;
    SweepPlan plan;
    plan.study = "gas";
    plan.heading = "Energy: an elastic gas";
    plan.question =
        "60 discs at 150 px/s in a closed box, restitution 1, friction 0, no gravity. *Energy change* "
        "is (E_end - E_start) / E_start of the kinetic energy (1/2 m v^2 + 1/2 I w^2) after " +
        std::to_string(steps) + " fixed steps, whatever the dt; it should be 0.";
    // No broad phases: they change only the cost, and 10,000 steps of testing every pair
    // would take most of the bench's time (the scale study compares them). No correction
    // rates either: discs that bounce apart at once leave it nothing to correct.
    plan.knobs = {{Knob::relaxation_iterations},
                  {Knob::dt},
                  {Knob::substeps},
                  {Knob::integrator},
                  {Knob::rotation},
                  {Knob::solver}};
    plan.measure = energy_drift(steps);
    plan.box2d = true;
    plan.error = {"size of the energy change (share of the start)", [](const Metrics& m) { return m.energy_change; },
                  1e-12};
    plan.columns = {{"energy change", [](const Row& r) { return percent(r.metrics.energy_change); }}};
    StudyResult result = run_sweep(context, plan);
    const Row& book = result.rows.front();
    std::string key = "Elastic gas, kinetic energy change after " + std::to_string(steps) +
                      " steps: " + percent(book.metrics.energy_change) + " (stage " + stage_name(book.stage) +
                      ", the scene's world)";
    if (result.rows.back().stage == Stage::box2d) {
        key += ", " + percent(result.rows.back().metrics.energy_change) + " (Box2D)";
    }
    result.key_figures.push_back(key + ".");
    return result;
}

}  // namespace bench
