// Trajectory: a thrown disc with nothing to hit, against the exact parabola
// p(t) = p0 + v0 t + g t^2 / 2. Both integrators take the new velocity v + g dt each
// step; symplectic Euler then moves with the new velocity, explicit Euler with the old
// one. Summed over n = t / dt steps the first falls g dt^2 n (n + 1) / 2, the second
// g dt^2 n (n - 1) / 2: either side of g t^2 / 2 by the same g t dt / 2. Both are
// first order, the error halving with dt.

#include <cmath>

#include "markdown.h"
#include "measures.h"
#include "scene_maker.h"
#include "sweep_study.h"

namespace bench {
namespace {

constexpr double kSeconds = 2.0;

Measure parabola_error() {
    return [](BenchWorld& world, const WorldDescription& settings) {
        const Snapshot start = world.snapshot();
        const long steps = steps_for(kSeconds, settings.dt);
        world.run(steps);
        const double t = static_cast<double>(steps) * settings.dt;
        const Vec2 exact = oracle::center(start[0].shape) + start[0].velocity * t + settings.gravity * (t * t / 2);
        Metrics metrics;
        metrics.trajectory_error = oracle::center(world.snapshot()[0].shape).distance(exact);
        return metrics;
    };
}

}  // namespace

StudyResult trajectory_study(const StudyContext& context) {
    const SceneDescription scene = bench_scene(context, "projectile");
    const RowSource source{"projectile", "projectile", scene};
    const std::vector<int> per_second = context.quick ? std::vector<int>{30, 60} : std::vector<int>{30, 60, 120, 240};
    StudyResult result;
    Chart chart{.title = "projectile: distance from the exact parabola after 2 s",
                .x_label = "dt (s)",
                .y_label = "position error (px)",
                .log_x = true,
                .log_y = true};
    // The integrator is a key of 5.3's: both lines are its.
    const Stage stage = Stage::s5_3;
    for (Integrator integrator : {Integrator::symplectic, Integrator::explicit_euler}) {
        const std::string name(spelling(integrator));
        Series series{.name = stage_name(stage) + " " + name, .joined = true};
        for (int rate : per_second) {
            WorldDescription world = scene.world;
            world.integrator = integrator;
            world.dt = 1.0 / rate;
            const Setting setting{stage, "integrator", name + ", " + dt_label(world.dt), world};
            result.rows.push_back(stage_row(source, setting, context.repeats, parabola_error()));
            series.points.push_back({world.dt, result.rows.back().metrics.trajectory_error.value_or(std::nan("")), ""});
        }
        chart.series.push_back(series);
    }
    chart.notes.push_back(
        "the two lines coincide: both are off by g t dt / 2, symplectic below the parabola, explicit above");
    result.figures.push_back({"trajectory.png", chart});
    result.key_figures.push_back(
        "Projectile after " + figure(kSeconds) + " s: symplectic " + figure(result.rows[1].metrics.trajectory_error) +
        " px and explicit " + figure(result.rows[per_second.size() + 1].metrics.trajectory_error) +
        " px from the parabola at dt 1/60 (g t dt / 2 = " + figure(scenes::kProjectileGravity * kSeconds / 60 / 2) +
        " px), halving with dt.");

    std::vector<Column> columns = cost_columns();
    columns.push_back({"error (px)", [](const Row& r) { return figure(r.metrics.trajectory_error); }});
    columns.push_back(
        {"g t dt / 2 (px)", [](const Row& r) { return figure(r.world.gravity.length() * kSeconds * r.world.dt / 2); }});
    result.markdown =
        "## Trajectory: a projectile per integrator and dt\n\n"
        "A disc thrown at (150, -150) px/s under gravity " +
        figure(scenes::kProjectileGravity) + " px/s² with nothing to hit, on stage " + stage_name(stage) +
        " (the integrator is its key); *error* is its distance from the exact parabola after " + figure(kSeconds) +
        " s. Under constant gravity both integrators are off by exactly "
        "g t dt / 2, symplectic Euler below the parabola (it moves with the velocity of the end "
        "of the step) and explicit Euler above it (the velocity of the start): halving dt halves "
        "the error, and the two cost the same.\n\n" +
        table(result.rows, columns) + "![trajectory](trajectory.png)\n\n";
    return result;
}

}  // namespace bench
