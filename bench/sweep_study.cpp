#include "sweep_study.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <map>

#include "markdown.h"
#include "scene_json.h"
#include "statistics.h"

namespace bench {
namespace {

std::string series_name(const Row& row) {
    if (row.stage == Stage::box2d) return row.setting;
    if (row.varied.empty()) return "scene's own world";
    return stage_name(row.stage) + " " + knob_title(row.varied);
}

// Each point says its setting; on the scene's own series, its stage.
std::string point_label(const Row& row) {
    if (row.stage != Stage::box2d && row.varied.empty()) return stage_name(row.stage);
    return row.setting;
}

// "5.1 passes 8": rows of one table differ in stage as well as setting.
std::string row_label(const Row& row) {
    if (row.stage == Stage::box2d) return row.setting;
    return stage_name(row.stage) + " " + row.setting;
}

ChartPoint point_of(const Row& row, const ErrorAxis& error, const std::string& label) {
    const std::optional<double> value = error.value(row.metrics);
    const double size = value ? std::abs(*value) : std::nan("");
    if (size < error.floor) return {row.ms_per_simulated_second(), error.floor, label + " (below)"};
    return {row.ms_per_simulated_second(), size, label};
}

std::string pareto_line(const std::vector<Row>& rows, const ErrorAxis& error) {
    std::vector<ChartPoint> points;
    for (const Row& row : rows) points.push_back(point_of(row, error, row_label(row)));
    std::string line = "Pareto front, cheapest first (no other row is both cheaper and more accurate): ";
    bool first = true;
    for (const ChartPoint& point : pareto_front(points)) {
        line += (first ? "" : ", ") + point.label;
        first = false;
    }
    return line + ".\n\n";
}

}  // namespace

std::vector<Stage> stages_for(std::size_t bodies) {
    if (bodies < kBookStageMostBodies) return {kChapter5Stages.begin(), kChapter5Stages.end()};
    return {std::next(kChapter5Stages.begin()), kChapter5Stages.end()};
}

SceneDescription bench_scene(const StudyContext& context, const std::string& name) {
    return read_scene(context.scenes_dir / (name + ".json"));
}

long steps_for(double seconds, double dt) { return std::max(1L, std::lround(seconds / dt)); }

std::vector<Column> cost_columns() {
    return {{"stage", [](const Row& r) { return stage_name(r.stage); }},
            {"setting", [](const Row& r) { return r.setting; }},
            {"µs/step", [](const Row& r) { return figure(r.cost_us); }},
            {"steps/s", [](const Row& r) { return figure(r.steps_per_second()); }},
            {"ms per simulated s", [](const Row& r) { return figure(r.ms_per_simulated_second()); }},
            {"pairs/step (narrow)", [](const Row& r) {
                 if (!r.candidate_pairs) return std::string();
                 return figure(*r.candidate_pairs) + " (" + figure(r.narrow_tests) + ")";
             }}};
}

std::string table(const std::vector<Row>& rows, const std::vector<Column>& columns) {
    std::vector<std::string> headers;
    for (const Column& column : columns) headers.push_back(column.header);
    MarkdownTable markdown(headers);
    for (const Row& row : rows) {
        std::vector<std::string> cells;
        for (const Column& column : columns) cells.push_back(column.cell(row));
        markdown.add(cells);
    }
    return markdown.text();
}

Chart cost_error_chart(const std::string& title, const std::vector<Row>& rows, const ErrorAxis& error) {
    Chart chart;
    chart.title = title;
    chart.x_label = "cost (ms of CPU per simulated second)";
    chart.y_label = error.label;
    chart.log_x = true;
    chart.log_y = true;
    chart.mark_pareto = true;
    std::vector<std::string> order;  // series in the order their first row came
    std::map<std::string, Series> by_name;
    for (const Row& row : rows) {
        const std::string name = series_name(row);
        if (!by_name.contains(name)) {
            order.push_back(name);
            by_name[name].name = name;
        }
        by_name[name].points.push_back(point_of(row, error, point_label(row)));
    }
    for (const std::string& name : order) chart.series.push_back(by_name[name]);
    chart.notes.push_back(
        "each knob changed alone from the scene's own world, on the oldest stage that has it; "
        "outlined: the Pareto front");
    const bool floored = std::any_of(rows.begin(), rows.end(), [&](const Row& row) {
        const std::optional<double> value = error.value(row.metrics);
        return value && std::abs(*value) < error.floor;
    });
    if (floored)
        chart.notes.push_back("\"(below)\": an error under " + figure(error.floor) + ", drawn at " +
                              figure(error.floor));
    return chart;
}

StudyResult run_sweep(const StudyContext& context, const SweepPlan& plan) {
    const SceneDescription scene = bench_scene(context, plan.study);
    const RowSource source{plan.study, plan.study, scene};
    const std::vector<Stage> stages = plan.stages.empty() ? stages_for(scene.bodies.size()) : plan.stages;
    StudyResult result;
    for (const Setting& setting : one_at_a_time(scene.world, stages, plan.knobs, context.quick)) {
        result.rows.push_back(stage_row(source, setting, context.repeats, plan.measure));
    }
    if (plan.box2d) {
        if (auto row = box2d_row(source, context.repeats, plan.measure)) result.rows.push_back(*row);
    }

    const std::string file = "cost_vs_error_" + plan.study + ".png";
    result.figures.push_back({file, cost_error_chart(plan.study + ": cost against error", result.rows, plan.error)});

    std::vector<Column> columns = cost_columns();
    columns.insert(columns.end(), plan.columns.begin(), plan.columns.end());
    std::string question = plan.question;
    if (stages.front() != Stage::s5_1) {
        question +=
            " Stage 5.1 is left out: its test of every pair would take most of the bench's time here, and "
            "5.2's grid finds the very same pairs.";
    }
    result.markdown = "## " + plan.heading + "\n\n" + question + "\n\n" + table(result.rows, columns) +
                      pareto_line(result.rows, plan.error) + "![" + plan.study + "](" + file + ")\n\n";
    return result;
}

}  // namespace bench
