// Scale: how the cost of a step grows with the number of shapes, per broad phase. The
// shapes are spread at one density, so each has about the same neighbours whatever
// their number: the narrow phase's work grows as n, and any faster growth is the broad
// phase's. Testing every pair grows as n^2; the grid should stay close to n.

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>

#include "markdown.h"
#include "scene_maker.h"
#include "statistics.h"
#include "sweep_study.h"

namespace bench {
namespace {

constexpr double kFitFrom = 100.0;  // the target: exponent <= 1.2 from N = 100 to 2000
constexpr double kFitTo = 2000.0;
constexpr double kTargetExponent = 1.2;
// Every count and broad phase runs the same steps, so that all see the same stretch of
// the scene's life, short enough that the cloud keeps its density: one untimed step to
// warm the caches, then kSteps timed ones. The all-pairs phase takes most of a second a
// step at 2000 shapes, and the grid tens of microseconds at 50; the cheap settings make
// up for their short runs with more of them (kRepeats; the runner stops repeating a
// setting after 1.5 s of timed work).
constexpr long kSteps = 10;
constexpr long kQuickSteps = 2;
constexpr int kRepeats = 50;

// The broad phases compared: the book's bounding circles as 5.1 has them, and 5.2's
// other two. (5.2 also has the bounding circles, at 5.1's cost.)
struct Contender {
    Stage stage;
    std::optional<BroadPhase> broad_phase;  // unset: the stage's only way
    const char* name;
};
constexpr std::array kContenders{Contender{Stage::s5_1, std::nullopt, "bounding circles"},
                                 Contender{Stage::s5_2, BroadPhase::all_pairs, "all_pairs"},
                                 Contender{Stage::s5_2, BroadPhase::grid, "grid"}};

Measure timed_steps(long steps) {
    return [steps](BenchWorld& world, const WorldDescription&) {
        world.run_untimed(1);
        world.run(steps);
        return Metrics{};
    };
}

}  // namespace

StudyResult scale_study(const StudyContext& context) {
    const std::vector<int> counts =
        context.quick ? std::vector<int>{50, 100, 200} : std::vector<int>{50, 100, 200, 500, 1000, 2000};
    StudyResult result;
    Chart chart{.title = "scale: cost of a step against the number of shapes",
                .x_label = "shapes",
                .y_label = "cost (us per step)",
                .log_x = true,
                .log_y = true};
    std::string verdicts;
    std::string key = "Scale, cost growth n^b from " + figure(kFitFrom) + " to " + figure(kFitTo) + " shapes:";
    for (const Contender& contender : kContenders) {
        const std::string name = stage_name(contender.stage) + " " + contender.name;
        Series series{.name = name, .joined = true};
        for (int n : counts) {
            SceneDescription scene = scenes::scale(n);
            scene.world.broad_phase = contender.broad_phase;
            const std::string scene_name = "scale_" + std::to_string(n);
            const Setting setting{contender.stage, contender.broad_phase ? "broad_phase" : "",
                                  std::string(contender.name) + ", " + std::to_string(n) + " shapes", scene.world};
            const int repeats = context.quick ? context.repeats : std::max(context.repeats, kRepeats);
            result.rows.push_back(stage_row({"scale", scene_name, scene}, setting, repeats,
                                            timed_steps(context.quick ? kQuickSteps : kSteps)));
            series.points.push_back({static_cast<double>(n), result.rows.back().cost_us, ""});
        }
        const double exponent = fitted_exponent(series.points, kFitFrom, kFitTo);
        series.name += ": n^" + figure(exponent, 4);
        chart.notes.push_back(name + ": cost grows as n^" + figure(exponent, 4) + " from " + figure(kFitFrom) + " to " +
                              figure(kFitTo) + " shapes");
        verdicts += "- " + name + ": cost grows as n^" + figure(exponent, 4);
        key += std::string(&contender == &kContenders.front() ? " " : ", ") + name + " " + figure(exponent, 4);
        if (contender.broad_phase == BroadPhase::grid) {
            verdicts += std::isfinite(exponent) && exponent <= kTargetExponent ? " — **target met** (≤ "
                                                                               : " — **target missed** (≤ ";
            verdicts += figure(kTargetExponent) + ")";
        }
        verdicts += "\n";
        chart.series.push_back(series);
    }
    result.figures.push_back({"scale.png", chart});
    result.key_figures.push_back(key + " (target for the grid: at most " + figure(kTargetExponent) + ").");

    result.markdown =
        "## Scale: cost against the number of shapes, per broad phase\n\n"
        "Boxes and discs (8 to 14 px) on a jittered 20 px lattice, drifting at up to 20 px/s, no "
        "gravity: the same density whatever their number, so each shape has about the same "
        "neighbours (over the few steps timed they drift at most 4 px). Each broad phase runs on the "
        "stage that has it: the book's bounding circles on 5.1, all_pairs and the grid on 5.2. Each "
        "setting runs one warm-up step and " +
        std::to_string(kSteps) + " timed ones, up to " + std::to_string(kRepeats) + " times (fewer once " +
        figure(kRepeatSeconds) +
        " s have been timed). The growth exponent b of "
        "cost = a n^b is fitted by least squares on log-log axes over n = " +
        figure(kFitFrom) + " to " + figure(kFitTo) + ". **Target:** the grid's exponent at most " +
        figure(kTargetExponent) + ".\n\n" + verdicts + "\n" + table(result.rows, cost_columns()) +
        "![scale](scale.png)\n\n";
    if (context.quick) result.markdown += "(Quick run: only up to 200 shapes, so the fit covers 100 to 200.)\n\n";
    return result;
}

}  // namespace bench
