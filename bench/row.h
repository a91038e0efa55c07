#pragma once
// One line of the results: one scene run by one stage's engine with one setting, what
// it cost and how far it strayed from the right answer. Every figure the bench reports
// is a field here, and results.csv has a column for each.

#include <cstddef>
#include <optional>
#include <string>

#include "bench_world.h"
#include "scene_description.h"
#include "stages.h"

namespace bench {

// The errors a scene can measure; a scene fills the ones it is about.
struct Metrics {
    std::optional<double> penetration_max;   // px: deepest overlap of two shapes once settled
    std::optional<double> penetration_mean;  // px: mean depth over the overlapping pairs
    std::optional<double> top_drift;         // px: how far the pyramid's top box moved
    std::optional<double> energy_change;     // (E_end - E_start) / E_start of the elastic gas
    std::optional<double> trajectory_error;  // px: distance from the exact parabola at the end
    std::optional<double> slide_error;       // (d - d_coulomb) / d_coulomb of the sliding box
    std::optional<double> roll_error;        // (s - s_exact) / s_exact of the rolling ball
    std::optional<double> tunnel_speed;      // px/s: the slowest speed that gets through the wall
    std::optional<double> ns_per_pair;       // ns per candidate pair per relaxation pass
};

struct Row {
    std::string study;          // what --only selects: "pyramid_10", "scale", ...
    std::string scene;          // the scene run: "pyramid_10", "scale_500", ...
    Stage stage = Stage::s5_1;  // whose engine made the row
    std::string varied;         // the key this row changes from the scene's own world, "" for none
    std::string setting;        // the setting in words: "passes 8", "dt 1/120", "grid", "scene"
    // The world the row ran: for a stage, every key it reads written out (its defaults
    // included, stages.h: resolved), keys it does not read unset; for Box2D, the scene's.
    WorldDescription world;
    std::size_t bodies = 0;
    long steps = 0;        // fixed steps in each timed run
    double cost_us = 0.0;  // median over the repeats of the microseconds per fixed step
    int repeats = 0;       // how many timed runs cost_us is the median of (runner.h)
    // Per fixed step, all passes together (5.2 on, which count them): the pairs the
    // broad phase looked at, those whose exact narrow-phase test was computed, those
    // whose exact test the skip rule saved, and the relaxation passes run.
    std::optional<double> candidate_pairs;
    std::optional<double> narrow_tests;
    std::optional<double> skipped_tests;
    std::optional<double> passes;
    // Per fixed step, the collision events the game read (5.7 on, events on).
    std::optional<BenchWorld::EventCounts> events;
    Metrics metrics;

    double steps_per_second() const { return 1e6 / cost_us; }
    // Cost per second of simulated time: a smaller dt costs more steps for the same
    // motion, which the cost per step alone would hide.
    double ms_per_simulated_second() const { return cost_us / world.dt / 1000.0; }
};

}  // namespace bench
