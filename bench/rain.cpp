// Rain: shapes of assorted sizes fall into a box and settle into a pile. A pile is
// where the relaxation works hardest: every shape presses on several others, and the
// weight of the whole pile rests on its bottom layer. What is left of the overlaps once
// it settles is the error; and the rain of 1000 is the race against Box2D.

#include "box2d_world.h"
#include "markdown.h"
#include "measures.h"
#include "sweep_study.h"

namespace bench {
namespace {

constexpr double kSeconds = 6.0;
constexpr double kQuickSeconds = 0.1;
constexpr int kSmallRain = 100;   // shapes: every knob
constexpr int kMiddleRain = 400;  // shapes: fewer values of each knob

double seconds_of(const StudyContext& context) { return context.quick ? kQuickSeconds : kSeconds; }

Measure settled_overlap(double seconds) {
    return [seconds](BenchWorld& world, const WorldDescription& settings) {
        world.run(steps_for(seconds, settings.dt));
        const Penetration overlap = penetration(world.snapshot());
        Metrics metrics;
        metrics.penetration_max = overlap.max;
        metrics.penetration_mean = overlap.mean;
        return metrics;
    };
}

std::vector<Column> overlap_columns() {
    return {{"overlap max (px)", [](const Row& r) { return figure(r.metrics.penetration_max); }},
            {"overlap mean (px)", [](const Row& r) { return figure(r.metrics.penetration_mean); }}};
}

std::string scene_text(int shapes, double seconds) {
    return std::to_string(shapes) + " boxes and discs (10 to 18 px) fall into a box and pile up; after " +
           figure(seconds) +
           " s of simulated time the deepest and the mean overlap of two shapes are measured "
           "by the collision oracle. A settled pile should not overlap at all.";
}

// Each run costs more as the rain grows, so the bigger rains try fewer settings: every
// value of every knob on the small one; on 400 shapes all the pass counts and one other
// value of the rest, and no broad phases (testing every pair exactly takes minutes there;
// the scale study compares the broad phases); on the biggest only the scene itself.
std::vector<Sweep> knobs_for(int shapes) {
    if (shapes <= kSmallRain) {
        return {{Knob::relaxation_iterations},
                {Knob::correction_rate},
                {Knob::dt},
                {Knob::broad_phase},
                {Knob::substeps},
                {Knob::integrator},
                {Knob::friction_model},
                {Knob::rotation},
                {Knob::friction},
                {Knob::solver},
                {Knob::velocity_iterations},
                {Knob::sleep}};
    }
    if (shapes <= kMiddleRain) {
        return {{Knob::relaxation_iterations},
                {Knob::correction_rate, Range::one},
                {Knob::dt, Range::one},
                {Knob::substeps, Range::one},
                {Knob::integrator},
                {Knob::friction_model},
                {Knob::rotation},
                {Knob::friction},
                {Knob::solver},
                {Knob::sleep}};
    }
    return {};
}

}  // namespace

StudyResult rain_study(const StudyContext& context, int shapes) {
    const double seconds = seconds_of(context);
    SweepPlan plan;
    plan.study = "rain_" + std::to_string(shapes);
    plan.heading = "Piles: a rain of " + std::to_string(shapes) + " shapes";
    plan.question = scene_text(shapes, seconds);
    if (shapes > kMiddleRain) plan.question += " No knob is varied here: each run of this scene takes seconds.";
    plan.knobs = knobs_for(shapes);
    plan.measure = settled_overlap(seconds);
    plan.box2d = true;
    plan.error = {"deepest overlap once settled (px)", [](const Metrics& m) { return m.penetration_max; }, 1e-4};
    plan.columns = overlap_columns();
    return run_sweep(context, plan);
}

StudyResult box2d_target_study(const StudyContext& context) {
    const double seconds = seconds_of(context);
    const std::string name = "rain_1000";
    const SceneDescription scene = bench_scene(context, name);
    const RowSource source{name, name, scene};
    const Measure measure = settled_overlap(seconds);
    StudyResult result;
    // Stage 5.2 as its scene files leave it: the grid, and the book's 15 passes.
    result.rows.push_back(stage_row(source, {Stage::s5_2, "", "scene", scene.world}, context.repeats, measure));
    const Row ours = result.rows.front();
    // Stage 5.4's sequential impulse solver, with its defaults, on the same scene.
    SceneDescription solved = scene;
    solved.world.solver = Solver::sequential_impulse;
    result.rows.push_back(
        stage_row(source, {Stage::s5_4, "solver", "sequential impulse", solved.world}, context.repeats, measure));
    const Row solver = result.rows.back();
    std::string verdict;
    if (auto reference = box2d_row(source, context.repeats, measure)) {
        result.rows.push_back(*reference);
        const double ratio = ours.cost_us / reference->cost_us;
        verdict = ratio >= 1.0 ? reference->setting + " is " + figure(ratio) + " times as fast as stage 5.2"
                               : "stage 5.2 is " + figure(1.0 / ratio) + " times as fast as " + reference->setting;
        result.key_figures.push_back("Rain of 1000, stage 5.2 (grid, 15 passes) against " + reference->setting + ": " +
                                     figure(ours.cost_us) + " µs per step against " + figure(reference->cost_us) +
                                     ": " + verdict + "; deepest overlap once settled " +
                                     figure(ours.metrics.penetration_max) + " px against " +
                                     figure(reference->metrics.penetration_max) + " px.");
        result.key_figures.push_back("Rain of 1000, stage 5.4's sequential impulse solver against " +
                                     reference->setting + ": " + figure(solver.cost_us) + " µs per step against " +
                                     figure(reference->cost_us) + "; deepest overlap once settled " +
                                     figure(solver.metrics.penetration_max) + " px against " +
                                     figure(reference->metrics.penetration_max) + " px.");
        verdict = "**" + verdict + "** here.";
    } else {
        verdict = "No Box2D in this build, so no comparison (Debian: libbox2d-dev).";
    }
    std::vector<Column> columns = cost_columns();
    for (Column& column : overlap_columns()) columns.push_back(column);
    result.markdown = "## Target: a rain of 1000 against Box2D\n\n" + scene_text(1000, seconds) +
                      " Stage 5.2 runs as its scene files leave it, with its grid broad phase and the book's 15 "
                      "relaxation passes; stage 5.4 with its sequential impulse solver at its defaults; Box2D 2.4 "
                      "with continuous collision off, 8 velocity and 3 position iterations, sleeping off, the same "
                      "scene scaled to metres (" +
                      figure(kPixelsPerMetre) + " px to the metre) and the same dt.\n\n" + table(result.rows, columns) +
                      verdict + "\n\n";
    return result;
}

}  // namespace bench
