#pragma once
// The common shape of the accuracy studies: one scene file, run with its own world on
// each stage of the study and with each knob changed in turn on the oldest stage that
// has it (sweep.h), plus Box2D where it applies; a table of cost and error per row, and
// a chart of error against cost with the Pareto front marked: the rows no other row
// beats on both.

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "runner.h"
#include "study.h"
#include "sweep.h"

namespace bench {

// A table column after the cost columns.
struct Column {
    std::string header;
    std::function<std::string(const Row&)> cell;
};

// The error the chart plots against cost: lower is better, so a signed error is
// plotted as its size. Sizes below `floor`, too small to matter (a thousandth of a
// pixel, rounding), are drawn at the floor, so that one setting that is exact to
// rounding does not squeeze all the others into a corner of the log axis; the chart's
// notes and the point's label say so.
struct ErrorAxis {
    std::string label;  // with units, ASCII (the chart font has no others)
    std::function<std::optional<double>(const Metrics&)> value;
    double floor = 0.0;
};

struct SweepPlan {
    std::string study;     // also the scene file's name in bench/scenes/
    std::string heading;   // of the results.md section
    std::string question;  // a paragraph under the heading: what is measured, and how
    // Oldest first; none given, stages_for the scene's size.
    std::vector<Stage> stages;
    std::vector<Sweep> knobs;
    Measure measure;
    bool box2d = false;  // add Box2D's row
    ErrorAxis error;
    std::vector<Column> columns;
};

StudyResult run_sweep(const StudyContext& context, const SweepPlan& plan);

// The stages a scene of this many bodies runs on: every chapter 5 stage, but from
// kBookStageMostBodies on not 5.1, whose test of every pair would then take most of the
// bench's time (5.2's grid finds the very same pairs, in a fraction of it).
inline constexpr std::size_t kBookStageMostBodies = 200;
std::vector<Stage> stages_for(std::size_t bodies);

// A scene file of bench/scenes/.
SceneDescription bench_scene(const StudyContext& context, const std::string& name);

// The chart of error against cost for rows of one scene: a series per stage and knob,
// one for the scene's own world on each stage, and one for Box2D.
Chart cost_error_chart(const std::string& title, const std::vector<Row>& rows, const ErrorAxis& error);

// The table's first columns: stage, setting, cost per step, steps per second, cost per
// simulated second, pairs per step.
std::vector<Column> cost_columns();
std::string table(const std::vector<Row>& rows, const std::vector<Column>& columns);

// Whole steps in `seconds` of simulated time (at least one).
long steps_for(double seconds, double dt);

}  // namespace bench
