#pragma once
// The common shape of the accuracy studies: one scene file, run with its own world
// and with each knob changed in turn (sweep.h), plus Box2D where it applies; a table
// of cost and error per setting, and a chart of error against cost with the Pareto
// front marked: the settings no other setting beats on both.

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
    std::vector<Sweep> knobs;
    Measure measure;
    bool box2d = false;  // add Box2D's row
    ErrorAxis error;
    std::vector<Column> columns;
};

StudyResult run_sweep(const StudyContext& context, const SweepPlan& plan);

// A scene file of bench/scenes/, read as stage 5.1 reads one.
browser::SceneDescription bench_scene(const StudyContext& context, const std::string& name);

// The chart of error against cost for rows of one scene: a series per knob, one for
// the scene's own world and one for Box2D.
Chart cost_error_chart(const std::string& title, const std::vector<Row>& rows, const ErrorAxis& error);

// The table's first columns: setting, cost per step, steps per second, cost per
// simulated second, pairs per step.
std::vector<Column> cost_columns();
std::string table(const std::vector<Row>& rows, const std::vector<Column>& columns);

// Whole steps in `seconds` of simulated time (at least one).
long steps_for(double seconds, double dt);

}  // namespace bench
