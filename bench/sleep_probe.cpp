// Which part of 5.5's sleep rule keeps each awake shape awake
// (ch5_demo/5.5_sleeping/README.md, "Why a pile stays awake"). It runs a pile with
// sleep on, exactly as the stage runs it, and watches the rule decide: every step, each
// awake shape whose rest timer starts again is charged to the part of the rule that
// stopped it (islands.h):
//     moved       its centre went the sleep speed times dt, or more, in the step
//     turned      its farthest point did, turning (or the two together)
//     overlap     with the correction off: its overlap past the slop did
//     unheld      no contact held it, in this step or the last
//     drift       it crept farther than the drift allowed since its rest began
//     woken       it was asleep, and a wake started its timer again
// Once a simulated second it prints, over the last second, how many shapes each part
// stopped; how the awake shapes stand (restless: their timer started again within the
// last time to sleep; or waiting for their island, their own timer full); the awake
// islands and the largest, with its restless shapes; and the share of the solver's
// contact points found again from the step before (warm started).
//
//   build/sleep_probe [--solver S] [--seconds N] [--scene FILE | pile options]
//                     [--world JSON] [--list | --noise | --woken SECONDS | --box2d | --terms]
//
// With no scene the pile is the one of issue 35 (bench/sleep_piles.h): 400 circles and
// squares of 10 to 25 px under the demo's gravity, friction 0.5, restitution 0.2.
// --world sets world keys over the scene's, as a scene file does
// ('{"velocity_iterations": 30}'). The other modes:
//     --list       each second, every restless shape: where, how fast, and why
//     --noise      sleep off: how far the shapes of the pile still go over the last
//                  time to sleep, each at its worst (what the rule must call rest)
//     --woken S    sleep on for --seconds (unless --world turns it off), then off for S
//                  more: how far the shapes go once woken (what sleeping had frozen)
//     --box2d      sleep off, beside Box2D 2.4 on the same pile: how many shapes move
//                  faster than 0.3 and 3 px/s, each second
//     --terms      sleep off: each second, how many shapes each term of 5.5's first,
//                  obvious sleep speed puts at or over 3 px/s alone (the README's table,
//                  on --scene bench/scenes/rain_1000.json)
#include <CLI/CLI.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>
#include <variant>
#include <vector>

#include "box2d_world.h"
#include "browser.h"
#include "core.h"
#include "narrow_phase.h"
#include "scene_io.h"
#include "scene_json.h"
#include "sleep_piles.h"

namespace {

enum Part { kMoved, kTurned, kOverlap, kUnheld, kDrift, kWoken, kPartCount };
constexpr std::array<const char*, kPartCount> kPartNames{"moved", "turned", "overlap", "unheld", "drift", "woken"};

// What the probe remembers of a shape from before the step.
struct Before {
    engine::Vec2 center;
    double angle = 0.0;
    double rested_s = 0.0;
    bool held = false;
    bool asleep = false;
};

// The part of the rule that started `shape`'s rest timer again in the step that took it
// from `before` to where it is now. The order is the rule's own: a shape that was
// neither held nor slow is charged to being unheld, a slow held one to its drift.
Part stoppedBy(const engine::RigidShape& shape, const Before& before, const engine::WorldSettings& world) {
    const engine::SleepState& sleep = shape.sleep();
    if (before.asleep && sleep.rested_s > 0.0) return kWoken;
    if (!sleep.held && !before.held && world.gravity != engine::Vec2{}) return kUnheld;
    const double limit = engine::sleepSpeed(world);
    if (sleep.speed >= limit) {
        const double moved = shape.center().distance(before.center) / world.dt;
        const double turned = std::abs(shape.angle() - before.angle) * shape.boundRadius() / world.dt;
        if (moved >= limit) return kMoved;
        if (moved + turned >= limit) return kTurned;
        return kOverlap;
    }
    return kDrift;
}

double quantile(std::vector<double> values, double share) {
    if (values.empty()) return 0.0;
    std::sort(values.begin(), values.end());
    return values[std::min(values.size() - 1, static_cast<std::size_t>(share * static_cast<double>(values.size())))];
}

struct Options {
    std::string solver = "sequential_impulse";
    double seconds = 30.0;
    std::string scene_file;
    bench::piles::PileRecipe pile;
    std::string kinds = "mixed";
    std::string world_json;
    bool list = false;
    bool noise = false;
    double woken_s = 0.0;
    bool box2d = false;
    bool terms = false;
};

bench::SceneDescription pileScene(const Options& options) { return bench::piles::pile(options.pile); }

engine::Scene sceneOf(const Options& options) {
    engine::Scene scene;
    if (!options.scene_file.empty()) {
        scene = engine::loadScene(options.scene_file);
    } else {
        scene = engine::readScene(bench::scene_json(pileScene(options)), "pile");
    }
    if (!options.world_json.empty()) {
        // The world's keys over the scene's world, so a key it leaves out keeps the scene's.
        std::vector<engine::BodyDescription> no_bodies;
        const browser::SceneList bodies = engine::bodyList(no_bodies);
        browser::read_scene_text(R"({"world": )" + options.world_json + R"(, "bodies": []})", "--world",
                                 engine::worldKeys(scene.world), {&bodies, 1});
    }
    return scene;
}

struct Probe {
    explicit Probe(const engine::WorldSettings& settings)
        : world(settings),
          window(settings.dt * 1000.0,
                 browser::Document{browser::Canvas(static_cast<int>(std::ceil(settings.width)),
                                                   static_cast<int>(std::ceil(settings.height)))}),
          core(window, settings) {}
    int stepsPerSecond() const { return static_cast<int>(std::lround(1.0 / world.dt)); }
    std::vector<engine::Vec2> centers() const {
        std::vector<engine::Vec2> at;
        for (std::size_t i = 0; i < core.objectCount(); ++i) at.push_back(core.object(i).center());
        return at;
    }

    engine::WorldSettings world;
    browser::Window window;
    engine::Core core;
};

// The rule at work, second by second (the default mode, and --list).
void watchTheRule(Probe& probe, const Options& options) {
    engine::Core& core = probe.core;
    const engine::WorldSettings& world = probe.world;
    std::printf(
        "   t  asleep  | rest timers started again over the second, by part of the rule | awake now: "
        "restless / waiting; awake islands, largest (restless in it) | contact points found again\n");
    std::vector<Before> before;
    std::vector<double> last_restart_s;
    std::vector<Part> last_part;
    for (int second = 1; second <= static_cast<int>(options.seconds); ++second) {
        std::array<long, kPartCount> restarts{};
        double points = 0.0, persisted = 0.0;
        for (int step = 0; step < probe.stepsPerSecond(); ++step) {
            before.resize(core.objectCount());
            for (std::size_t i = 0; i < core.objectCount(); ++i) {
                const engine::RigidShape& shape = core.object(i);
                before[i] = {shape.center(), shape.angle(), shape.sleep().rested_s, shape.sleep().held,
                             shape.sleep().asleep};
            }
            core.update();
            points += static_cast<double>(core.physics().contactSolver().pointCount());
            persisted += static_cast<double>(core.physics().contactSolver().persistedPointCount());
            last_restart_s.resize(core.objectCount(), 0.0);
            last_part.resize(core.objectCount(), kMoved);
            const double now = static_cast<double>(core.stepCount()) * world.dt;
            for (std::size_t i = 0; i < std::min(core.objectCount(), before.size()); ++i) {
                const engine::RigidShape& shape = core.object(i);
                if (shape.isResting()) continue;
                // A wake that started the timer again leaves it at dt, not 0, after the step.
                const bool woken = before[i].asleep && shape.sleep().rested_s < before[i].rested_s;
                if (shape.sleep().rested_s > 0.0 && !woken) continue;
                last_part[i] = stoppedBy(shape, before[i], world);
                ++restarts[last_part[i]];
                last_restart_s[i] = now;
            }
        }
        const double now = static_cast<double>(core.stepCount()) * world.dt;
        std::size_t moving = 0, restless = 0, waiting = 0;
        std::map<std::uint64_t, std::pair<std::size_t, std::size_t>> islands;  // shapes, restless ones
        for (std::size_t i = 0; i < core.objectCount(); ++i) {
            const engine::RigidShape& shape = core.object(i);
            if (shape.isStatic()) continue;
            ++moving;
            if (shape.sleep().asleep) continue;
            const bool is_restless = shape.sleep().rested_s < world.time_to_sleep;
            (is_restless ? restless : waiting) += 1;
            auto& island = islands[shape.sleep().island];
            ++island.first;
            island.second += is_restless ? 1 : 0;
        }
        std::pair<std::size_t, std::size_t> largest{0, 0};
        for (const auto& [label, island] : islands) largest = std::max(largest, island);
        std::printf("%4.0f  %4zu/%-4zu |", now, moving - restless - waiting, moving);
        for (int part = 0; part < kPartCount; ++part) std::printf(" %s %5ld", kPartNames[part], restarts[part]);
        std::printf(" | %4zu / %4zu; %3zu islands, %4zu (%zu) | %.1f %%\n", restless, waiting, islands.size(),
                    largest.first, largest.second, points > 0 ? 100.0 * persisted / points : 100.0);
        if (!options.list) continue;
        for (std::size_t i = 0; i < core.objectCount(); ++i) {
            const engine::RigidShape& shape = core.object(i);
            if (shape.isResting() || shape.sleep().rested_s >= world.time_to_sleep) continue;
            std::printf(
                "      #%zu %s r %.1f px at (%.1f, %.1f), v (%.2f, %.2f) px/s, w %.3f rad/s; sleep speed "
                "%.2f px/s, rested %.2f s, last stopped by %s at %.2f s; island of %zu\n",
                i, shape.type() == engine::ShapeType::Circle ? "circle" : "square", shape.boundRadius(),
                shape.center().x, shape.center().y, shape.velocity().x, shape.velocity().y, shape.angularVelocity(),
                shape.sleep().speed, shape.sleep().rested_s, kPartNames[last_part[i]], last_restart_s[i],
                islands[shape.sleep().island].first);
        }
    }
}

// --noise: with sleep off, over the last time to sleep of the run, how far each shape
// goes, per step and over the whole window, and how fast it ends, as quantiles over the
// shapes, each shape taken at its worst.
void printNoise(Probe& probe, const Options& options) {
    engine::Core& core = probe.core;
    const engine::WorldSettings& world = probe.world;
    const int window = static_cast<int>(std::lround(world.time_to_sleep / world.dt));
    for (int step = 0; step < static_cast<int>(options.seconds) * probe.stepsPerSecond() - window; ++step) {
        core.update();
    }
    const std::size_t count = core.objectCount();
    std::vector<double> worst_step(count, 0.0), worst_velocity(count, 0.0);
    const std::vector<engine::Vec2> start = probe.centers();
    std::vector<double> start_angle(count);
    for (std::size_t i = 0; i < count; ++i) start_angle[i] = core.object(i).angle();
    for (int step = 0; step < window; ++step) {
        const std::vector<engine::Vec2> centers = probe.centers();
        std::vector<double> angles(count);
        for (std::size_t i = 0; i < count; ++i) angles[i] = core.object(i).angle();
        core.update();
        for (std::size_t i = 0; i < count; ++i) {
            const engine::RigidShape& shape = core.object(i);
            const double moved =
                shape.center().distance(centers[i]) + std::abs(shape.angle() - angles[i]) * shape.boundRadius();
            worst_step[i] = std::max(worst_step[i], moved / world.dt);
            worst_velocity[i] = std::max(
                worst_velocity[i], shape.velocity().length() + std::abs(shape.angularVelocity()) * shape.boundRadius());
        }
    }
    std::vector<double> step_speed, velocity, went;
    for (std::size_t i = 0; i < count; ++i) {
        const engine::RigidShape& shape = core.object(i);
        if (shape.isStatic()) continue;
        step_speed.push_back(worst_step[i]);
        velocity.push_back(worst_velocity[i]);
        went.push_back(shape.center().distance(start[i]) +
                       std::abs(shape.angle() - start_angle[i]) * shape.boundRadius());
    }
    const auto line = [](const char* name, const std::vector<double>& values, const char* unit) {
        std::printf("  %-34s p50 %8.4f  p90 %8.4f  p99 %8.4f  max %8.4f %s\n", name, quantile(values, 0.5),
                    quantile(values, 0.9), quantile(values, 0.99), quantile(values, 1.0), unit);
    };
    const double g = world.gravity.length();
    std::printf("sleep off, the last %.2f s of %.0f s, each shape at its worst (g dt = %.3f px/s, g dt^2 = %.5f px):\n",
                window * world.dt, options.seconds, g * world.dt, g * world.dt * world.dt);
    line("sleep speed (displacement / dt)", step_speed, "px/s");
    line("|v| + |w| r", velocity, "px/s");
    line("went over the window", went, "px");
}

// --woken: how far the shapes go once woken, and where the pile's middle goes.
void printWoken(Probe& probe, const Options& options) {
    engine::Core& core = probe.core;
    for (int step = 0; step < static_cast<int>(options.seconds) * probe.stepsPerSecond(); ++step) core.update();
    const std::size_t awake = core.awakeCount();
    const std::vector<engine::Vec2> start = probe.centers();
    engine::WorldSettings sleep_off = core.settings();
    sleep_off.sleep = false;
    core.changeSettings(sleep_off);  // wakes every shape
    for (int step = 0; step < static_cast<int>(options.woken_s * probe.stepsPerSecond()); ++step) core.update();
    std::vector<double> went;
    double depth_before = 0.0, depth_after = 0.0;
    for (std::size_t i = 0; i < core.objectCount(); ++i) {
        if (core.object(i).isStatic()) continue;
        went.push_back(core.object(i).center().distance(start[i]));
        depth_before += start[i].y;
        depth_after += core.object(i).center().y;
    }
    const double n = static_cast<double>(went.size());
    std::printf(
        "at %.0f s, %zu of %zu awake; %.1f s after turning sleep off, each shape went p50 %.3f, p90 %.3f, "
        "p99 %.3f, max %.3f px; the mean centre's y went %.3f -> %.3f px\n",
        options.seconds, awake, went.size(), options.woken_s, quantile(went, 0.5), quantile(went, 0.9),
        quantile(went, 0.99), quantile(went, 1.0), depth_before / n, depth_after / n);
}

double boundRadius(const oracle::Shape& shape) {
    if (const auto* disc = std::get_if<oracle::Disc>(&shape)) return disc->radius;
    const auto& box = std::get<oracle::Box>(shape);
    return std::hypot(box.width, box.height) / 2;
}

// --box2d: sleep off, ours and Box2D's motion side by side.
void compareWithBox2d(Probe& probe, const Options& options) {
    const std::unique_ptr<bench::BenchWorld> box2d = bench::box2d_world(pileScene(options), false);
    if (!box2d) {
        std::printf("%s\n", std::string(bench::kNoBox2d).c_str());
        return;
    }
    std::printf("   t  shapes faster than 0.3 / 3 px/s (|v| + |w| r) and the median, 99th percentile speed\n");
    for (int second = 1; second <= static_cast<int>(options.seconds); ++second) {
        for (int k = 0; k < probe.stepsPerSecond(); ++k) probe.core.update();
        box2d->run(probe.stepsPerSecond());
        const bench::Snapshot theirs = box2d->snapshot();
        std::vector<double> ours_speed, theirs_speed;
        for (std::size_t i = 0; i < probe.core.objectCount(); ++i) {
            const engine::RigidShape& shape = probe.core.object(i);
            if (shape.isStatic()) continue;
            ours_speed.push_back(shape.velocity().length() + std::abs(shape.angularVelocity()) * shape.boundRadius());
            theirs_speed.push_back(theirs[i].velocity.length() +
                                   std::abs(theirs[i].angular_velocity) * boundRadius(theirs[i].shape));
        }
        const auto over = [](const std::vector<double>& speeds, double limit) {
            return std::count_if(speeds.begin(), speeds.end(), [limit](double s) { return s >= limit; });
        };
        std::printf("%4d  5.5: %4ld / %4ld, %.3f / %.3f px/s   Box2D 2.4: %4ld / %4ld, %.3f / %.3f px/s\n", second,
                    over(ours_speed, 0.3), over(ours_speed, 3.0), quantile(ours_speed, 0.5), quantile(ours_speed, 0.99),
                    over(theirs_speed, 0.3), over(theirs_speed, 3.0), quantile(theirs_speed, 0.5),
                    quantile(theirs_speed, 0.99));
    }
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

// --terms: with sleep off, each second, how many shapes each term of the first rule's
// sleep speed alone puts at or over 3 px/s, beside the displacement over the step:
//     |v|                      the velocity the shape ends its step with
//     |w| r                    its spin at its extent (the bounding radius)
//     max(0, d - slop) / dt    the overlap past the slop, as the step ends
// with medians and 90th percentiles, in px/s.
void printTerms(Probe& probe, const Options& options) {
    constexpr double kThreshold = 3.0;  // px/s, the first rule's sleep speed
    engine::Core& core = probe.core;
    const engine::WorldSettings& world = probe.world;
    std::printf("shapes at or over %.1f px/s by each term alone\n", kThreshold);
    for (int second = 1; second <= static_cast<int>(options.seconds); ++second) {
        for (int step = 1; step < probe.stepsPerSecond(); ++step) core.update();
        const std::vector<engine::Vec2> centers = probe.centers();
        std::vector<double> angles;
        for (std::size_t i = 0; i < core.objectCount(); ++i) angles.push_back(core.object(i).angle());
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
            return std::count_if(values.begin(), values.end(), [&](double v) { return v >= kThreshold; });
        };
        std::printf(
            "t %2d s  |v| %4ld  |w|r %4ld  overlap %4ld  displacement %4ld   median/p90: |v| %.2f/%.2f  "
            "|w|r %.2f/%.2f  overlap %.2f/%.2f  displacement %.2f/%.2f\n",
            second, over(linear), over(spin), over(overlap), over(moved), quantile(linear, 0.5), quantile(linear, 0.9),
            quantile(spin, 0.5), quantile(spin, 0.9), quantile(overlap, 0.5), quantile(overlap, 0.9),
            quantile(moved, 0.5), quantile(moved, 0.9));
    }
}

}  // namespace

int main(int argc, char** argv) {
    Options options;
    CLI::App app("sleep_probe: which part of 5.5's sleep rule keeps each awake shape awake", "sleep_probe");
    app.add_option("--solver", options.solver, "book or sequential_impulse")
        ->check(CLI::IsMember({"book", "sequential_impulse"}))
        ->capture_default_str();
    app.add_option("--seconds", options.seconds, "simulated seconds")
        ->check(CLI::Range(1.0, 600.0))
        ->capture_default_str();
    app.add_option("--scene", options.scene_file, "a scene file in place of the pile")->check(CLI::ExistingFile);
    app.add_option("--world", options.world_json, "world keys over the scene's, as JSON: '{\"substeps\": 2}'");
    app.add_option("--gravity", options.pile.gravity, "px/s^2")->check(CLI::Range(1.0, 1e4))->capture_default_str();
    app.add_option("--friction", options.pile.friction)->check(CLI::Range(0.0, 10.0))->capture_default_str();
    app.add_option("--restitution", options.pile.restitution)->check(CLI::Range(0.0, 1.0))->capture_default_str();
    app.add_option("--smallest", options.pile.smallest, "px across")
        ->check(CLI::Range(1.0, 100.0))
        ->capture_default_str();
    app.add_option("--largest", options.pile.largest, "px across")
        ->check(CLI::Range(1.0, 100.0))
        ->capture_default_str();
    app.add_option("--layers", options.pile.layers)->check(CLI::Range(1, 40))->capture_default_str();
    app.add_option("--kinds", options.kinds)
        ->check(CLI::IsMember({"circles", "squares", "mixed"}))
        ->capture_default_str();
    app.add_option("--seed", options.pile.seed, "the pile's seed")->capture_default_str();
    auto* list = app.add_flag("--list", options.list, "each second, every restless shape: where, how fast, and why");
    auto* noise = app.add_flag("--noise", options.noise, "sleep off: how far a settled pile's shapes still go");
    auto* woken = app.add_option("--woken", options.woken_s, "then sleep off for this many s: how far shapes go")
                      ->check(CLI::Range(0.1, 600.0));
    auto* box2d = app.add_flag("--box2d", options.box2d, "sleep off, beside Box2D 2.4: how many shapes move");
    auto* terms = app.add_flag("--terms", options.terms, "sleep off: the shapes each term of the first rule holds");
    list->excludes(noise, woken, box2d, terms);
    noise->excludes(woken, box2d, terms);
    woken->excludes(box2d, terms);
    box2d->excludes(terms);
    CLI11_PARSE(app, argc, argv);
    options.pile.kinds = options.kinds == "circles"   ? bench::piles::Kinds::circles
                         : options.kinds == "squares" ? bench::piles::Kinds::squares
                                                      : bench::piles::Kinds::mixed;
    if (options.pile.largest < options.pile.smallest) {
        std::fprintf(stderr, "sleep_probe: --largest must be at least --smallest\n");
        return 2;
    }
    if (options.box2d && !options.scene_file.empty()) {
        std::fprintf(stderr, "sleep_probe: --box2d runs the pile, not a scene file\n");
        return 2;
    }

    engine::Scene scene;
    try {
        scene = sceneOf(options);
    } catch (const std::exception& error) {
        std::fprintf(stderr, "sleep_probe: %s\n", error.what());
        return 2;
    }
    engine::WorldSettings world = scene.world;
    world.solver = options.solver == "book" ? engine::SolverKind::book : engine::SolverKind::sequential_impulse;
    world.sleep = !options.noise && !options.box2d && !options.terms;
    Probe probe(world);
    engine::buildScene(probe.core, scene.bodies);
    std::printf("%s, %s; sleep speed %.2f px/s, time to sleep %.2f s, drift allowed %.3f px\n",
                options.scene_file.empty() ? bench::piles::describe(options.pile).c_str() : options.scene_file.c_str(),
                options.solver.c_str(), engine::sleepSpeed(world), world.time_to_sleep,
                engine::kCreepSpeed * world.time_to_sleep);
    if (options.noise) {
        printNoise(probe, options);
    } else if (options.woken_s > 0.0) {
        printWoken(probe, options);
    } else if (options.box2d) {
        compareWithBox2d(probe, options);
    } else if (options.terms) {
        printTerms(probe, options);
    } else {
        watchTheRule(probe, options);
    }
    return 0;
}
