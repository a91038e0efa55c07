#pragma once
// Runs one scene with one setting on one engine and makes its row: the errors from the
// first run, the cost as the median over `repeats` runs, each on a fresh world. The
// median, not the mean: on a shared machine a run is sometimes slowed by something
// else, never sped up, and the median ignores the odd slow run. A setting whose runs have taken
// kRepeatSeconds of timed work is not run again: its cost is then already an average
// over many steps, and the whole bench must stay within minutes. The row says how many
// runs its cost is the median of.

#include <array>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "bench_world.h"
#include "row.h"
#include "sweep.h"

namespace bench {

inline constexpr double kRepeatSeconds = 1.5;

// What a scene measures: it runs the world (world.run(...) is the timed part) and
// returns the errors it found. `settings` is the world the run has (its dt says how
// many steps make a second). Every run of one setting does the same steps.
using Measure = std::function<Metrics(BenchWorld& world, const WorldDescription& settings)>;

// Where a row comes from: the study, the scene's name and the scene itself.
struct RowSource {
    std::string study;
    std::string scene_name;
    const SceneDescription& scene;
};

// The setting's stage with the setting's world in place of the scene's.
Row stage_row(const RowSource& source, const Setting& setting, int repeats, const Measure& measure);
// Two settings of one scene, timed side by side where a difference of a few per cent is
// the figure: in each of `repeats` runs a fresh world of each runs `steps` steps, the two
// taking turns kTurnSteps steps at a time, each first in every other turn, so that a
// busy moment of the shared machine falls on both alike (run one after the other, a few per cent comes and goes with the
// load). Each cost is the median of its runs (every one made: no kRepeatSeconds); the
// errors are what `look` finds in each world after its first run.
inline constexpr long kTurnSteps = 30;
using Look = std::function<Metrics(const BenchWorld& world)>;
std::array<Row, 2> paired_rows(const RowSource& source, const std::array<Setting, 2>& settings, int repeats, long steps,
                               const Look& look);
// Box2D with the scene's world; nothing in a build without Box2D.
std::optional<Row> box2d_row(const RowSource& source, int repeats, const Measure& measure);

double median(std::vector<double> values);

}  // namespace bench
