// Why a settled rain of 1000 did not fall asleep under 5.5's first sleep rule
// (ch5_demo/5.5_sleeping/README.md, "When it pays"). It runs the rain
// (bench/scenes/rain_1000.json) with sleep off, so that nothing the rule decides
// changes the motion, and once a simulated second prints, for each term of that first
// rule's sleep speed, how many shapes it alone puts at or over the threshold:
//     |v|                      the velocity the shape ends its step with
//     |w| r                    its spin at its extent (the bounding radius)
//     max(0, d - slop) / dt    the overlap past the slop, as the step ends
// beside what the shape really did, its displacement over the step (correction
// included) divided by dt, centre and turn at the extent. Medians and 90th percentiles
// too, in px/s.
//
//   build/sleep_probe [book|sequential_impulse] [SECONDS] [THRESHOLD px/s]
//   (defaults: book, 12 s, 3 px/s)
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "browser.h"
#include "core.h"
#include "narrow_phase.h"
#include "scene_io.h"

namespace {

double quantile(std::vector<double> values, double share) {
    if (values.empty()) return 0.0;
    std::sort(values.begin(), values.end());
    return values[std::min(values.size() - 1, static_cast<std::size_t>(share * static_cast<double>(values.size())))];
}

// Each shape's deepest overlap with any other, as the shapes stand now.
std::vector<double> deepestOverlaps(const engine::Core& core) {
    const std::size_t count = core.objectCount();
    std::vector<double> deepest(count, 0.0);
    for (std::size_t i = 0; i < count; ++i) {
        for (std::size_t j = i + 1; j < count; ++j) {
            const engine::RigidShape& a = core.object(i);
            const engine::RigidShape& b = core.object(j);
            if (a.center().distance(b.center()) > a.boundRadius() + b.boundRadius()) continue;
            const auto info = engine::narrowPhase(a, b);
            if (!info) continue;
            deepest[i] = std::max(deepest[i], info->depth());
            deepest[j] = std::max(deepest[j], info->depth());
        }
    }
    return deepest;
}

}  // namespace

int main(int argc, char** argv) {
    const std::string solver = argc > 1 ? argv[1] : "book";
    const double seconds = argc > 2 ? std::atof(argv[2]) : 12.0;
    const double threshold = argc > 3 ? std::atof(argv[3]) : 3.0;
    if ((solver != "book" && solver != "sequential_impulse") || !(seconds > 0) || !(threshold > 0)) {
        std::fprintf(stderr, "usage: sleep_probe [book|sequential_impulse] [SECONDS > 0] [THRESHOLD > 0]\n");
        return 2;
    }
    const engine::Scene scene = engine::loadScene(std::string(BENCH_SCENES_DIR) + "/rain_1000.json");
    engine::WorldSettings world = scene.world;
    world.solver = solver == "book" ? engine::SolverKind::book : engine::SolverKind::sequential_impulse;
    world.sleep = false;
    browser::Window window(world.dt * 1000.0,
                           browser::Document{browser::Canvas(static_cast<int>(std::ceil(world.width)),
                                                             static_cast<int>(std::ceil(world.height)))});
    engine::Core core(window, world);
    engine::buildScene(core, scene.bodies);
    const int steps_per_second = static_cast<int>(std::lround(1.0 / world.dt));
    std::printf("rain_1000, %s, sleep off: shapes at or over %.1f px/s by each term alone\n", solver.c_str(),
                threshold);
    for (int second = 1; second <= static_cast<int>(seconds); ++second) {
        for (int step = 1; step < steps_per_second; ++step) core.update();
        std::vector<engine::Vec2> centers;
        std::vector<double> angles;
        for (std::size_t i = 0; i < core.objectCount(); ++i) {
            centers.push_back(core.object(i).center());
            angles.push_back(core.object(i).angle());
        }
        core.update();
        const std::vector<double> deepest = deepestOverlaps(core);
        std::vector<double> linear, spin, overlap, moved;
        for (std::size_t i = 0; i < core.objectCount(); ++i) {
            const engine::RigidShape& shape = core.object(i);
            if (shape.isStatic()) continue;
            linear.push_back(shape.velocity().length());
            spin.push_back(std::abs(shape.angularVelocity()) * shape.boundRadius());
            overlap.push_back(std::max(0.0, deepest[i] - world.slop) / world.dt);
            moved.push_back(
                (shape.center().distance(centers[i]) + std::abs(shape.angle() - angles[i]) * shape.boundRadius()) /
                world.dt);
        }
        const auto over = [&](const std::vector<double>& values) {
            return std::count_if(values.begin(), values.end(), [&](double v) { return v >= threshold; });
        };
        std::printf(
            "t %2d s  |v| %4ld  |w|r %4ld  overlap %4ld  displacement %4ld   median/p90: |v| %.2f/%.2f  "
            "|w|r %.2f/%.2f  overlap %.2f/%.2f  displacement %.2f/%.2f\n",
            second, over(linear), over(spin), over(overlap), over(moved), quantile(linear, 0.5), quantile(linear, 0.9),
            quantile(spin, 0.5), quantile(spin, 0.9), quantile(overlap, 0.5), quantile(overlap, 0.9),
            quantile(moved, 0.5), quantile(moved, 0.9));
    }
    return 0;
}
