#include "runner.h"

#include <algorithm>
#include <stdexcept>

#include "box2d_world.h"

namespace bench {
namespace {

using WorldMaker = std::function<std::unique_ptr<BenchWorld>()>;

struct Runs {
    Metrics metrics;
    long steps = 0;
    double cost_us = 0.0;
    std::optional<double> candidate_pairs;          // per step
    std::optional<double> narrow_tests;             // per step
    std::optional<double> skipped_tests;            // per step
    std::optional<double> passes;                   // per step
    std::optional<BenchWorld::EventCounts> events;  // per step
    int repeats = 0;                                // timed runs made
};

// The counts of a world's steps so far, per step.
void take_counts(const BenchWorld& world, Runs& runs) {
    runs.steps = world.steps();
    if (const auto counts = world.pair_counts()) {
        runs.candidate_pairs = counts->candidates;
        runs.narrow_tests = counts->narrow_tests;
        runs.skipped_tests = counts->skipped_tests;
        runs.passes = counts->passes;
    }
    runs.events = world.event_counts();
}

Runs run_repeats(const WorldMaker& make, const WorldDescription& settings, int repeats, const Measure& measure) {
    if (repeats < 1) throw std::invalid_argument("run_repeats: repeats must be at least 1");
    Runs runs;
    std::vector<double> costs;
    double timed = 0.0;
    for (int repeat = 0; repeat < repeats && timed < kRepeatSeconds; ++repeat) {
        const std::unique_ptr<BenchWorld> world = make();
        const Metrics metrics = measure(*world, settings);
        if (world->steps() == 0) throw std::logic_error("run_repeats: the measure ran no step");
        costs.push_back(world->seconds() * 1e6 / static_cast<double>(world->steps()));
        timed += world->seconds();
        if (repeat == 0) {
            runs.metrics = metrics;
            take_counts(*world, runs);
        }
    }
    runs.cost_us = median(costs);
    runs.repeats = static_cast<int>(costs.size());
    return runs;
}

Row row_of(const RowSource& source, const Runs& runs) {
    Row row;
    row.study = source.study;
    row.scene = source.scene_name;
    row.bodies = source.scene.bodies.size();
    row.steps = runs.steps;
    row.cost_us = runs.cost_us;
    row.repeats = runs.repeats;
    row.candidate_pairs = runs.candidate_pairs;
    row.narrow_tests = runs.narrow_tests;
    row.skipped_tests = runs.skipped_tests;
    row.passes = runs.passes;
    row.events = runs.events;
    row.metrics = runs.metrics;
    return row;
}

Row setting_row(const RowSource& source, const Setting& setting, const Runs& runs) {
    Row row = row_of(source, runs);
    row.stage = setting.stage;
    row.varied = setting.varied;
    row.setting = setting.label;
    row.world = resolved(setting.stage, setting.world);
    return row;
}

}  // namespace

Row stage_row(const RowSource& source, const Setting& setting, int repeats, const Measure& measure) {
    SceneDescription scene = source.scene;
    scene.world = setting.world;
    const Runs runs = run_repeats([&] { return stage_world(setting.stage, scene); }, scene.world, repeats, measure);
    return setting_row(source, setting, runs);
}

std::array<Row, 2> paired_rows(const RowSource& source, const std::array<Setting, 2>& settings, int repeats, long steps,
                               const Look& look) {
    if (repeats < 1 || steps < 1) throw std::invalid_argument("paired_rows: repeats and steps must be at least 1");
    std::array<Runs, 2> runs;
    std::array<std::vector<double>, 2> costs;
    for (int repeat = 0; repeat < repeats; ++repeat) {
        std::array<std::unique_ptr<BenchWorld>, 2> worlds;
        for (std::size_t k = 0; k < 2; ++k) {
            SceneDescription scene = source.scene;
            scene.world = settings[k].world;
            worlds[k] = stage_world(settings[k].stage, scene);
        }
        // Each goes first in every other turn: the second of a turn may find the caches
        // warmer, or colder, for what the first left in them.
        for (long done = 0, turn = 0; done < steps; done += kTurnSteps, ++turn) {
            const long now = std::min(kTurnSteps, steps - done);
            worlds[turn % 2]->run(now);
            worlds[1 - turn % 2]->run(now);
        }
        for (std::size_t k = 0; k < 2; ++k) {
            costs[k].push_back(worlds[k]->seconds() * 1e6 / static_cast<double>(steps));
            if (repeat == 0) {
                runs[k].metrics = look(*worlds[k]);
                take_counts(*worlds[k], runs[k]);
            }
        }
    }
    std::array<Row, 2> rows;
    for (std::size_t k = 0; k < 2; ++k) {
        runs[k].cost_us = median(costs[k]);
        runs[k].repeats = repeats;
        rows[k] = setting_row(source, settings[k], runs[k]);
    }
    return rows;
}

std::optional<Row> box2d_row(const RowSource& source, int repeats, const Measure& measure) {
    if (!box2d_available()) return std::nullopt;
    const Runs runs = run_repeats([&] { return box2d_world(source.scene); }, source.scene.world, repeats, measure);
    Row row = row_of(source, runs);
    row.stage = Stage::box2d;
    row.setting = box2d_version();
    row.world = source.scene.world;
    return row;
}

double median(std::vector<double> values) {
    if (values.empty()) throw std::invalid_argument("median of no values");
    std::sort(values.begin(), values.end());
    const std::size_t middle = values.size() / 2;
    return values.size() % 2 == 1 ? values[middle] : (values[middle - 1] + values[middle]) / 2;
}

}  // namespace bench
