// Stacking: does a pyramid of boxes stand still? Each relaxation pass removes part of
// every overlap, but the boxes are pushed into each other anew by gravity every step;
// the fewer passes, the more overlap is left at the end of a step, and the pyramid
// slowly sinks into itself and creeps apart. The top box shows the sum of it all.

#include <algorithm>
#include <cmath>

#include "markdown.h"
#include "measures.h"
#include "sweep_study.h"

namespace bench {
namespace {

constexpr double kSeconds = 10.0;
constexpr double kQuickSeconds = 0.2;
// The boxes start 0.25 px apart, so that none overlaps at the start; closing the gaps
// drops the top by 0.25 px a row, which is not the error. The top's place after a
// second, when the gaps have closed, is where it should then stay.
constexpr double kSettleSeconds = 1.0;
constexpr double kQuickSettleSeconds = 0.1;
// Motion of less than a pixel does not show on the screen.
constexpr double kVisiblePx = 1.0;

Measure stacking(double settle, double seconds) {
    return [settle, seconds](BenchWorld& world, const WorldDescription& settings) {
        world.run_untimed(steps_for(settle, settings.dt));
        const Snapshot before = world.snapshot();
        const std::size_t top = top_body(before);
        world.run(steps_for(seconds, settings.dt));
        const Snapshot after = world.snapshot();
        const Penetration overlap = penetration(after);
        Metrics metrics;
        metrics.top_drift = oracle::center(after[top].shape).distance(oracle::center(before[top].shape));
        metrics.penetration_max = overlap.max;
        metrics.penetration_mean = overlap.mean;
        return metrics;
    };
}

// The cheapest of all the stages' rows that keep the top within a pixel, if any does.
const Row* cheapest_steady(const std::vector<Row>& results) {
    const Row* best = nullptr;
    for (const Row& row : results) {
        const bool steady = row.stage != Stage::box2d && row.metrics.top_drift && *row.metrics.top_drift < kVisiblePx;
        if (steady && (!best || row.ms_per_simulated_second() < best->ms_per_simulated_second())) best = &row;
    }
    return best;
}

// The stage the passes were varied on: the oldest of the study's.
Stage passes_stage(const std::vector<Row>& results) {
    for (const Row& row : results) {
        if (row.varied == "relaxation_iterations") return row.stage;
    }
    return results.front().stage;
}

// The rows of that stage that vary the passes (its scene row's 15 among them), fewest
// passes first.
std::vector<const Row*> pass_rows(const std::vector<Row>& results) {
    const Stage stage = passes_stage(results);
    std::vector<const Row*> rows;
    for (const Row& row : results) {
        const bool passes = row.stage == stage && (row.varied == "relaxation_iterations" || row.varied.empty());
        if (passes && row.metrics.top_drift) rows.push_back(&row);
    }
    std::sort(rows.begin(), rows.end(), [](const Row* a, const Row* b) {
        return a->world.relaxation_iterations < b->world.relaxation_iterations;
    });
    return rows;
}

std::string passes_give(const Row& row) {
    const int passes = row.world.relaxation_iterations;
    return std::to_string(passes) + (passes == 1 ? " pass gives " : " passes give ") + figure(*row.metrics.top_drift) +
           " px of top motion at " + figure(row.cost_us) + " µs per step";
}

// What each pass count buys, and the advice: the fewest passes whose top stays within a
// pixel, and the cheapest setting of all that does.
void add_advice(int rows, StudyResult& result) {
    const std::vector<const Row*> by_passes = pass_rows(result.rows);
    const std::string on_stage = " (stage " + stage_name(passes_stage(result.rows)) + ")";
    std::string text = "Relaxation passes for " + std::to_string(rows) + " rows" + on_stage + ": ";
    const Row* enough = nullptr;
    for (const Row* row : by_passes) {
        text += (row == by_passes.front() ? "" : "; ") + passes_give(*row);
        if (!enough && *row->metrics.top_drift < kVisiblePx) enough = row;
    }
    std::string advice = "for " + std::to_string(rows) + " rows" + on_stage + ", ";
    if (enough) {
        advice += passes_give(*enough) + ", the fewest passes that keep the top within " + figure(kVisiblePx) + " px";
    } else {
        advice += "no pass count tried keeps the top within " + figure(kVisiblePx) + " px";
    }
    if (const Row* best = cheapest_steady(result.rows)) {
        advice += "; the cheapest row of all that does is *" + stage_name(best->stage) + " " + best->setting + "* (" +
                  figure(*best->metrics.top_drift) + " px, " + figure(best->ms_per_simulated_second()) +
                  " ms per simulated second)";
    }
    result.markdown += text + ".\n\n**Advice:** " + advice + ".\n\n";
    result.key_figures.push_back("Stacking, " + advice + ".");
}

}  // namespace

StudyResult stacking_study(const StudyContext& context, int rows) {
    const double seconds = context.quick ? kQuickSeconds : kSeconds;
    const double settle = context.quick ? kQuickSettleSeconds : kSettleSeconds;
    SweepPlan plan;
    plan.study = "pyramid_" + std::to_string(rows);
    plan.heading = "Stacking: a pyramid of " + std::to_string(rows) + " rows";
    plan.question = "A pyramid of " + std::to_string(rows * (rows + 1) / 2) +
                    " boxes (30 px) standing on a static floor, 0.25 px apart at first, run for " + figure(settle) +
                    " s to close the gaps and then " + figure(seconds) +
                    " s more. *Top moved* is how far the top box's centre moved in those " + figure(seconds) +
                    " s (it should stay put); *overlap* is the deepest and the mean overlap of two "
                    "shapes at the end, measured by the collision oracle (oracle/collision_oracle.h), "
                    "not by the engine.";
    // The big pyramid costs five times as much a step: all the pass counts, one other
    // value of each other knob, and no broad phases (the scale study compares those).
    const bool small = rows <= 10;
    const Range range = small ? Range::all : Range::one;
    plan.knobs = {{Knob::relaxation_iterations},
                  {Knob::correction_rate, range},
                  {Knob::dt, range},
                  {Knob::substeps, range},
                  {Knob::integrator},
                  {Knob::friction_model},
                  {Knob::rotation}};
    if (small) plan.knobs.push_back({Knob::broad_phase});
    plan.knobs.insert(plan.knobs.end(),
                      {{Knob::solver}, {Knob::velocity_iterations}, {Knob::warm_starting}, {Knob::position_method}});
    plan.measure = stacking(settle, seconds);
    plan.box2d = true;
    plan.error = {"top box moved (px)", [](const Metrics& m) { return m.top_drift; }, 1e-3};
    plan.columns = {{"top moved (px)", [](const Row& r) { return figure(r.metrics.top_drift); }},
                    {"overlap max (px)", [](const Row& r) { return figure(r.metrics.penetration_max); }},
                    {"overlap mean (px)", [](const Row& r) { return figure(r.metrics.penetration_mean); }}};
    StudyResult result = run_sweep(context, plan);
    add_advice(rows, result);
    return result;
}

namespace {

constexpr double kHeavySeconds = 60.0;
constexpr double kQuickHeavySeconds = 2.0;

// The deepest overlap of any two shapes seen over the run, looked at once a second,
// and how far the heavy box (the last body) moved from where it started.
Measure heavy_load(double seconds) {
    return [seconds](BenchWorld& world, const WorldDescription& settings) {
        const Snapshot start = world.snapshot();
        const long per_second = steps_for(1.0, settings.dt);
        double deepest = 0.0;
        for (double t = 0.0; t < seconds; t += 1.0) {
            world.run(per_second);
            deepest = std::max(deepest, penetration(world.snapshot()).max);
        }
        const Snapshot end = world.snapshot();
        Metrics metrics;
        metrics.penetration_max = deepest;
        metrics.top_drift = oracle::center(end.back().shape).distance(oracle::center(start.back().shape));
        return metrics;
    };
}

}  // namespace

StudyResult heavy_on_light_study(const StudyContext& context) {
    const double seconds = context.quick ? kQuickHeavySeconds : kHeavySeconds;
    SweepPlan plan;
    plan.study = "heavy_on_light";
    plan.heading = "A heavy load: a box 100 times heavier than the slab under it";
    plan.question =
        "A box of mass 100 (60 px) on a slab of mass 1 (100 x 20 px) on a static floor, 0.25 px apart "
        "at first, run for " +
        figure(seconds) +
        " s. *Overlap max* is the deepest overlap of two "
        "shapes seen over the run (looked at once a second, by the collision oracle): the slab pressed "
        "into the floor; *box moved* is how far the heavy box's centre moved, which is 0.25 px when it "
        "only closes the gap.";
    plan.knobs = {{Knob::relaxation_iterations},
                  {Knob::solver},
                  {Knob::velocity_iterations},
                  {Knob::warm_starting},
                  {Knob::position_method}};
    plan.measure = heavy_load(seconds);
    plan.box2d = true;
    plan.error = {"deepest overlap seen (px)", [](const Metrics& m) { return m.penetration_max; }, 1e-3};
    plan.columns = {{"overlap max (px)", [](const Row& r) { return figure(r.metrics.penetration_max); }},
                    {"box moved (px)", [](const Row& r) { return figure(r.metrics.top_drift); }}};
    return run_sweep(context, plan);
}

}  // namespace bench
