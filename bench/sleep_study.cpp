// The study of 5.5's sleeping (ch5_demo/5.5_sleeping/README.md): the rain of 1000
// (bench/scenes/rain_1000.json) on both of 5.5's solvers, with sleep on and off, and on
// Box2D 2.4 with its own sleeping, one run each. For every half second of simulated
// time it writes the cost of a step and the share of the shapes asleep to
// bench/extra_results/sleep_rain_1000.csv, draws the cost against simulated time
// (sleep_rain_1000.png), and prints the figures the README quotes: when the last shape
// landed (the first step from which every moving shape touches something), the share
// asleep 4 s later, and the cost of a settled step, sleep on against sleep off. The cost
// of a window is its median step in processor time (bench/thread_clock.h, and median below). With sleep on, it also counts why shapes
// are not asleep: how often a rest timer started again, and by which part of the rule.
//
//   build/sleep_study [SECONDS]    (default 20 s of simulated time)
//
// Linked with stage 5.5's engine alone (namespace engine), beside the bench's library
// for Box2D (whose stage engines live in their own namespaces, CMakeLists.txt).
#include <algorithm>
#include <cstdint>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "box2d_world.h"
#include "browser.h"
#include "charts.h"
#include "core.h"
#include "scene_io.h"
#include "scene_json.h"
#include "thread_clock.h"

namespace {

constexpr int kWindowSteps = 30;  // half a second at the rain's 60 steps a second

struct Window {
    double end_s;         // simulated time at the window's end
    double us_per_step;   // the median step, processor time
    double asleep_share;  // of the moving shapes, at the window's end
    // Why the pile is not asleep (NaN for Box2D): over the window, how often a shape's
    // rest timer started again because of its sleep speed or of its drift, and how
    // many shapes the largest island holds at the window's end.
    double speed_restarts = 0.0;
    double drift_restarts = 0.0;
    double largest_island = std::nan("");
};

struct Run {
    std::string name;
    std::vector<Window> windows;
    double landed_s = -1.0;  // every moving shape touching something from here on
};

// The median step of a window: the machine is shared, and one preemption of 10 ms
// would add a third of a millisecond to the mean step of a half second.
double median(std::vector<double> values) {
    std::sort(values.begin(), values.end());
    return values[values.size() / 2];
}

std::size_t movingCount(const engine::Core& core) {
    std::size_t moving = 0;
    for (std::size_t i = 0; i < core.objectCount(); ++i) moving += core.object(i).isStatic() ? 0 : 1;
    return moving;
}

std::size_t largestIsland(const engine::Core& core) {
    std::map<std::uint64_t, std::size_t> sizes;
    std::size_t largest = 0;
    for (std::size_t i = 0; i < core.objectCount(); ++i) {
        if (!core.object(i).isStatic()) largest = std::max(largest, ++sizes[core.object(i).sleep().island]);
    }
    return largest;
}

bool allHeld(const engine::Core& core) {
    for (std::size_t i = 0; i < core.objectCount(); ++i) {
        const engine::RigidShape& shape = core.object(i);
        if (!shape.isStatic() && !shape.sleep().asleep && !shape.sleep().held) return false;
    }
    return true;
}

// Over one step: the shapes whose rest timer started again, by their sleep speed or,
// slow enough, by their drift (islands.h).
void countRestarts(const engine::Core& core, double sleep_speed, double& by_speed, double& by_drift) {
    for (std::size_t i = 0; i < core.objectCount(); ++i) {
        const engine::RigidShape& shape = core.object(i);
        if (shape.isResting() || shape.sleep().rested_s > 0.0) continue;
        (shape.sleep().speed >= sleep_speed ? by_speed : by_drift) += 1.0;
    }
}

Run runStage(const engine::Scene& scene, engine::SolverKind solver, bool sleep, int windows) {
    engine::WorldSettings world = scene.world;
    world.solver = solver;
    world.sleep = sleep;
    // The engine's own sleep speed, which follows gravity: 15 px/s under the rain's
    // 100 px/s^2 (world_settings.h).
    browser::Window window(world.dt * 1000.0,
                           browser::Document{browser::Canvas(static_cast<int>(std::ceil(world.width)),
                                                             static_cast<int>(std::ceil(world.height)))});
    engine::Core core(window, world);
    engine::buildScene(core, scene.bodies);
    Run run{.name = std::string(solver == engine::SolverKind::book ? "5.5 book's passes" : "5.5 sequential impulse") +
                    (sleep ? ", sleep on" : ", sleep off")};
    const double moving = static_cast<double>(movingCount(core));
    for (int w = 0; w < windows; ++w) {
        std::vector<double> step_seconds;
        Window figures{};
        for (int step = 0; step < kWindowSteps; ++step) {
            // Only the step is timed, not the counting around it.
            const double start = bench::thread_cpu_seconds();
            core.update();
            step_seconds.push_back(bench::thread_cpu_seconds() - start);
            if (!sleep) continue;
            countRestarts(core, engine::sleepSpeed(world), figures.speed_restarts, figures.drift_restarts);
            // Held is only kept while sleep is on; a run with sleep off has no landing time.
            if (run.landed_s < 0 && allHeld(core)) run.landed_s = static_cast<double>(core.stepCount()) * world.dt;
            if (run.landed_s >= 0 && !allHeld(core)) run.landed_s = -1.0;
        }
        figures.end_s = static_cast<double>(core.stepCount()) * world.dt;
        figures.us_per_step = median(step_seconds) * 1e6;
        figures.asleep_share = (moving - static_cast<double>(core.awakeCount())) / moving;
        if (sleep) {
            figures.largest_island = static_cast<double>(largestIsland(core));
        } else {
            figures.speed_restarts = figures.drift_restarts = std::nan("");
        }
        run.windows.push_back(figures);
    }
    return run;
}

Run runBox2d(const bench::SceneDescription& scene, int windows) {
    Run run{.name = bench::box2d_version() + ", sleeping on"};
    const std::unique_ptr<bench::BenchWorld> world = bench::box2d_world(scene, true);
    if (!world) return run;
    for (int w = 0; w < windows; ++w) {
        std::vector<double> step_seconds;
        for (int step = 0; step < kWindowSteps; ++step) {
            const double before = bench::thread_cpu_seconds();
            world->run(1);
            step_seconds.push_back(bench::thread_cpu_seconds() - before);
        }
        run.windows.push_back({.end_s = (w + 1) * kWindowSteps * scene.world.dt,
                               .us_per_step = median(step_seconds) * 1e6,
                               .asleep_share = std::nan(""),
                               .speed_restarts = std::nan(""),
                               .drift_restarts = std::nan("")});
    }
    return run;
}

// The mean cost of a step over the last `count` windows: the settled rain.
double settledCost(const Run& run, std::size_t count) {
    double sum = 0.0;
    for (std::size_t k = run.windows.size() - count; k < run.windows.size(); ++k) sum += run.windows[k].us_per_step;
    return sum / static_cast<double>(count);
}

double asleepAt(const Run& run, double time_s) {
    for (const Window& window : run.windows) {
        if (window.end_s >= time_s - 1e-9) return window.asleep_share;
    }
    return std::nan("");
}

}  // namespace

int main(int argc, char** argv) {
    const double seconds = argc > 1 ? std::stod(argv[1]) : 20.0;
    const int windows = static_cast<int>(std::lround(seconds * 60.0 / kWindowSteps));
    const std::filesystem::path scene_file = std::filesystem::path(BENCH_SCENES_DIR) / "rain_1000.json";
    const engine::Scene scene = engine::loadScene(scene_file);

    std::vector<Run> runs;
    for (engine::SolverKind solver : {engine::SolverKind::book, engine::SolverKind::sequential_impulse}) {
        runs.push_back(runStage(scene, solver, true, windows));
        runs.push_back(runStage(scene, solver, false, windows));
    }
    if (bench::box2d_available()) runs.push_back(runBox2d(bench::read_scene(scene_file), windows));

    const std::filesystem::path results(BENCH_EXTRA_RESULTS_DIR);
    std::ofstream csv(results / "sleep_rain_1000.csv");
    csv << "engine,simulated_s,us_per_step,asleep_share,speed_restarts,drift_restarts,largest_island\n";
    bench::Chart chart{.title = "rain of 1000: the cost of a step as the rain settles",
                       .x_label = "simulated time (s)",
                       .y_label = "cost (us per step)",
                       .log_y = true};
    for (const Run& run : runs) {
        bench::Series series{.name = run.name, .joined = true};
        for (const Window& window : run.windows) {
            csv << '"' << run.name << "\"," << window.end_s << ',' << window.us_per_step << ',' << window.asleep_share
                << ',' << window.speed_restarts << ',' << window.drift_restarts << ',' << window.largest_island << '\n';
            series.points.push_back({window.end_s, window.us_per_step, ""});
        }
        chart.series.push_back(series);
    }
    bench::write_chart(chart, results / "sleep_rain_1000.png");

    const std::size_t settled = std::min<std::size_t>(4, static_cast<std::size_t>(windows));
    for (std::size_t k = 0; k + 1 < runs.size() && k < 4; k += 2) {
        const Run& on = runs[k];
        const Run& off = runs[k + 1];
        std::printf("%s: last landing at %.2f s; asleep 4 s later: %.1f %%; at the end: %.1f %%\n", on.name.c_str(),
                    on.landed_s, 100.0 * asleepAt(on, on.landed_s + 4.0), 100.0 * on.windows.back().asleep_share);
        const Window& last = on.windows.back();
        std::printf("  last half second: %.0f restarts by speed, %.0f by drift; the largest island holds %.0f shapes\n",
                    last.speed_restarts, last.drift_restarts, last.largest_island);
        std::printf("  settled step (last 2 s): %.1f us with sleep on, %.1f us off: %.1f %%\n",
                    settledCost(on, settled), settledCost(off, settled),
                    100.0 * settledCost(on, settled) / settledCost(off, settled));
    }
    if (runs.size() == 5)
        std::printf("%s: settled step (last 2 s): %.1f us\n", runs[4].name.c_str(), settledCost(runs[4], settled));
    return 0;
}
