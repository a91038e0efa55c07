// Tunnelling speed per dt and substeps: how fast a ball must fly to get through a thin
// wall. Sub-steps shorten the distance between two looks just as a smaller dt does,
// so the speed should grow with substeps / dt.

#include <algorithm>
#include <optional>

#include "markdown.h"
#include "scene_maker.h"
#include "sweep_study.h"
#include "tunnel_search.h"

namespace bench {
namespace {

constexpr double kTolerance = 1e-3;  // the speeds are found to 0.1%
constexpr long kCostSteps = 200;     // the cost column: a run of the scene at its own speed

// The search has run already; the row's run only times the scene's steps.
Measure with_speed(double speed) {
    return [speed](BenchWorld& world, const WorldDescription&) {
        world.run(kCostSteps);
        Metrics metrics;
        metrics.tunnel_speed = speed;
        return metrics;
    };
}

}  // namespace

StudyResult tunnelling_study(const StudyContext& context) {
    const SceneDescription scene = bench_scene(context, "thin_wall");
    const RowSource source{"thin_wall", "thin_wall", scene};
    const std::vector<int> per_second = context.quick ? std::vector<int>{60} : std::vector<int>{30, 60, 120, 240};
    const std::vector<int> substeps = context.quick ? std::vector<int>{1, 2} : std::vector<int>{1, 2, 4, 8};

    StudyResult result;
    Chart chart{.title = "thin_wall: slowest speed that gets through a 4 px wall",
                .x_label = "dt (s)",
                .y_label = "speed (px/s)",
                .log_x = true,
                .log_y = true};
    // One look per step is the book's, on 5.1; sub-steps are 5.3's.
    const std::vector<Stage> stages{kChapter5Stages.begin(), kChapter5Stages.end()};
    for (int k : substeps) {
        const std::string looks = k == 1 ? "no sub-steps" : "substeps " + std::to_string(k);
        std::optional<Stage> stage;
        Series series{.joined = true};
        for (int rate : per_second) {
            SceneDescription tried = scene;
            tried.world.dt = 1.0 / rate;
            if (k > 1) tried.world.substeps = k;
            stage = oldest_expressing(stages, tried.world);
            const double speed = slowest_passing_speed(stage.value(), tried, kTolerance);
            const Setting setting{*stage, "dt, substeps", dt_label(tried.world.dt) + ", " + looks, tried.world};
            result.rows.push_back(stage_row(source, setting, context.repeats, with_speed(speed)));
            series.points.push_back({tried.world.dt, speed, ""});
        }
        series.name = stage_name(stage.value()) + " " + looks;
        chart.series.push_back(series);
    }
    chart.notes.push_back("ball 10 px across, wall 4 px thick, 1 px apart; the speed grows as substeps / dt");
    result.figures.push_back({"tunnelling.png", chart});
    // The book's own setting, dt 1/60 without sub-steps, which every run has.
    const auto book = std::find_if(result.rows.begin(), result.rows.end(), [](const Row& row) {
        return substeps_of(row.world) == 1 && dt_label(row.world.dt) == "dt 1/60";
    });
    result.key_figures.push_back(
        "Tunnelling: on stage " + stage_name(book->stage) + ", at dt 1/60 (no sub-steps) the ball gets through the " +
        figure(scenes::kWallThickness) + " px wall from " + figure(*book->metrics.tunnel_speed, 4) + " px/s (" +
        figure(*book->metrics.tunnel_speed * book->world.dt, 4) +
        " px per step); stage 5.3's sub-steps raise the speed as substeps / dt.");

    std::vector<Column> columns = cost_columns();
    columns.push_back({"slowest passing speed (px/s)", [](const Row& r) { return figure(r.metrics.tunnel_speed, 4); }});
    columns.push_back({"px per sub-step at it", [](const Row& r) {
                           return figure(*r.metrics.tunnel_speed * r.world.dt / substeps_of(r.world), 4);
                       }});
    result.markdown =
        "## Tunnelling: a fast ball at a thin wall\n\n"
        "A ball " +
        figure(2 * scenes::kWallBallRadius) + " px across starts " + figure(scenes::kWallGap) +
        " px in front of a static wall " + figure(scenes::kWallThickness) +
        " px thick, no gravity, run by the book's 5.1 with one look per step and by 5.3 with sub-steps. "
        "The table gives the slowest speed at which it ends up past the wall (bisection to "
        "0.1%), and how far it moves per sub-step at that speed. A ball caught with its centre past the middle of "
        "the wall is pushed out of the far side, so it gets through once it moves the gap plus its radius plus half "
        "the wall in one sub-step; the speed grows with substeps / dt, and substeps cost as much as a smaller dt.\n\n" +
        table(result.rows, columns) + "![tunnelling](tunnelling.png)\n\n";
    return result;
}

}  // namespace bench
