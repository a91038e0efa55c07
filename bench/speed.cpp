// Speed: what the book's method costs as the book writes it (5.1) and as 5.2 runs it,
// the very same computation. Two measures:
//  - the bounding-circle test: discs spread so that no two touch, run with no pass and
//    with 1 (a pass that finds nothing is the step's last, broad_phase.h); the
//    difference over the n (n - 1) / 2 pairs of the pass is the cost of one test (its
//    loop included);
//  - a rain of 400 on 5.1 and on 5.2 with the book's bounding circles and with the
//    grid, and a rain of 1000 on 5.2 against Box2D: microseconds per step, the share
//    of exact tests the skip rule saved, and the cost of a step per pair.
// And what 5.7's collision events cost: the rain of 1000 on 5.7 with no one reading its
// events and with a game reading them after every step, on both solvers, side by side.

#include <array>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "markdown.h"
#include "measures.h"
#include "runner.h"
#include "scene_maker.h"
#include "sweep_study.h"

namespace bench {
namespace {

constexpr int kSpreadShapes = 1000;
constexpr int kQuickSpreadShapes = 100;
constexpr int kFewPasses = 0;
constexpr int kManyPasses = 1;
constexpr long kSpreadSteps = 10;
constexpr double kRainSeconds = 3.0;  // the pile forms: falling, landing, settling
constexpr double kQuickRainSeconds = 0.1;
constexpr double kBoundTestTarget = 1.0;  // ns
constexpr double kRain400Target = 3.0;    // times as fast as 5.1
constexpr double kBox2dTarget = 1.0;      // times Box2D's cost, rain of 1000 on the grid
constexpr double kBookJsTarget = 30.0;    // times as fast as the book's JavaScript, rain of 400 on the grid
constexpr double kEventsTarget = 3.0;     // per cent more a step with 5.7's events read (issue 37)
// The book's own JavaScript (Chapter 5.1 project, with the circle-inertia fix) under
// Node, against 5.1 on the rain of 400, 540 steps after 60, measured side by side by
// hand for issue 24 on the machine these results come from: 5.1 ran 2.1 times as fast.
// The bench does not run Node; the ratio is carried over to put the grid against the
// target above.
constexpr double kBookJsPer51 = 2.1;

struct Contender {
    Stage stage;
    std::optional<BroadPhase> broad_phase;  // unset: the stage's only way (5.1) or its default
    const char* name;
};

Setting setting_for(const Contender& contender, WorldDescription world, const std::string& label) {
    if (contender.broad_phase) world.broad_phase = *contender.broad_phase;
    return {contender.stage, contender.broad_phase ? "broad_phase" : "", label, world};
}

// A rain, timed.
Metrics rain_metrics(BenchWorld& world, long steps) {
    world.run(steps);
    const Penetration overlap = penetration(world.snapshot());
    Metrics metrics;
    metrics.penetration_max = overlap.max;
    metrics.penetration_mean = overlap.mean;
    return metrics;
}

std::string percent(double share) { return figure(100.0 * share, 2) + "%"; }

// A rain's row of the table. Per pair: the whole step's cost over the pairs of all its
// passes, those whose exact test was computed and those the broad phase handed on.
std::vector<std::string> rain_cells(const std::string& scene, const std::string& who, const Row& row,
                                    double book_cost) {
    const auto per_pair = [&](std::optional<double> pairs) {
        return pairs && *pairs > 0 ? figure(row.cost_us * 1000.0 / *pairs) : std::string();
    };
    std::string skipped;
    if (row.narrow_tests && row.skipped_tests && *row.narrow_tests + *row.skipped_tests > 0) {
        skipped = percent(*row.skipped_tests / (*row.narrow_tests + *row.skipped_tests));
    }
    return {scene,
            who,
            figure(row.cost_us),
            book_cost > 0 ? figure(book_cost / row.cost_us) : "",
            row.passes ? figure(*row.passes) : "",
            row.narrow_tests ? figure(*row.narrow_tests) : "",
            skipped,
            per_pair(row.narrow_tests),
            per_pair(row.candidate_pairs),
            figure(row.metrics.penetration_max)};
}

// "met", or how far the figure falls short of its target.
std::string against(double figure_reached, double target, bool at_most) {
    const bool met = at_most ? figure_reached <= target : figure_reached >= target;
    if (met) return "met";
    return "missed by " + figure(at_most ? figure_reached / target : target / figure_reached) + " times";
}

using BookLoop = std::array<Contender, 3>;

// The bounding-circle test on each stage of the book's loop: ns per test, and the table.
struct BoundTests {
    std::array<double, 3> ns_per_test{};
    int shapes = 0;
    double pairs_per_pass = 0.0;
    std::string table;
};

BoundTests bound_tests(const StudyContext& context, const BookLoop& book_loop, StudyResult& result) {
    BoundTests found;
    found.shapes = context.quick ? kQuickSpreadShapes : kSpreadShapes;
    found.pairs_per_pass = found.shapes * (found.shapes - 1) / 2.0;
    const SceneDescription spread = scenes::spread(found.shapes);
    MarkdownTable table({"stage", "µs/step, no pass", "µs/step, 1 pass", "ns per bound test"});
    for (std::size_t c = 0; c < book_loop.size(); ++c) {
        std::array<Row, 2> rows;
        for (int k = 0; k < 2; ++k) {
            WorldDescription world = spread.world;
            world.relaxation_iterations = k == 0 ? kFewPasses : kManyPasses;
            const std::string label =
                std::string(book_loop[c].name) + ", passes " + std::to_string(world.relaxation_iterations);
            rows[k] = stage_row({"speed", "spread_" + std::to_string(found.shapes), spread},
                                setting_for(book_loop[c], world, label), context.repeats,
                                [](BenchWorld& w, const WorldDescription&) {
                                    w.run(kSpreadSteps);
                                    return Metrics{};
                                });
        }
        found.ns_per_test[c] = (rows[1].cost_us - rows[0].cost_us) * 1000.0 / found.pairs_per_pass;
        table.add({book_loop[c].name, figure(rows[0].cost_us), figure(rows[1].cost_us), figure(found.ns_per_test[c])});
        result.rows.insert(result.rows.end(), rows.begin(), rows.end());
    }
    found.table = table.text();
    return found;
}

// The rains: µs per step of each, and the table.
struct Rains {
    double book_400 = 0.0;    // 5.1
    double fast_400 = 0.0;    // 5.2, bounding circles
    double grid_400 = 0.0;    // 5.2, grid
    double grid_1000 = 0.0;   // 5.2, grid
    double box2d_1000 = 0.0;  // 0 without Box2D
    double seconds = 0.0;
    std::string table;
};

Rains rains(const StudyContext& context, const BookLoop& book_loop, StudyResult& result) {
    Rains found;
    found.seconds = context.quick ? kQuickRainSeconds : kRainSeconds;
    MarkdownTable table({"scene", "stage", "µs/step", "times as fast as 5.1", "passes per step", "exact tests per step",
                         "exact tests skipped", "ns per computed pair per pass", "ns per candidate pair per pass",
                         "overlap max (px)"});
    struct RainRun {
        int shapes;
        Contender contender;
    };
    const std::array<RainRun, 5> runs{RainRun{400, book_loop[0]}, RainRun{400, book_loop[1]},
                                      RainRun{400, {Stage::s5_2, BroadPhase::grid, "5.2 grid"}},
                                      RainRun{1000, {Stage::s5_2, BroadPhase::grid, "5.2 grid"}},
                                      RainRun{1000, {Stage::s5_3, std::nullopt, "5.3 (grid)"}}};
    for (const RainRun& run : runs) {
        const SceneDescription scene = scenes::rain(run.shapes);
        const std::string name = "rain_" + std::to_string(run.shapes);
        const long steps = steps_for(found.seconds, scene.world.dt);
        const Row row = stage_row(
            {"speed", name, scene}, setting_for(run.contender, scene.world, run.contender.name), context.repeats,
            [steps](BenchWorld& world, const WorldDescription&) { return rain_metrics(world, steps); });
        const bool grid = run.contender.broad_phase == BroadPhase::grid;
        if (run.shapes == 400 && run.contender.stage == Stage::s5_1) found.book_400 = row.cost_us;
        if (run.shapes == 400 && run.contender.broad_phase == BroadPhase::bounding_circle) found.fast_400 = row.cost_us;
        if (run.shapes == 400 && grid) found.grid_400 = row.cost_us;
        if (run.shapes == 1000 && grid) found.grid_1000 = row.cost_us;
        table.add(rain_cells(name, run.contender.name, row, run.shapes == 400 ? found.book_400 : 0.0));
        result.rows.push_back(row);
    }
    const SceneDescription rain1000 = scenes::rain(1000);
    const long box2d_steps = steps_for(found.seconds, rain1000.world.dt);
    if (const auto box2d = box2d_row(
            {"speed", "rain_1000", rain1000}, context.repeats,
            [box2d_steps](BenchWorld& world, const WorldDescription&) { return rain_metrics(world, box2d_steps); })) {
        found.box2d_1000 = box2d->cost_us;
        table.add(rain_cells("rain_1000", box2d->setting, *box2d, 0.0));
        result.rows.push_back(*box2d);
    }
    found.table = table.text();
    return found;
}

// What reading 5.7's events costs: per solver, the step with events read against the
// step without, in per cent.
struct EventCosts {
    std::vector<std::pair<std::string, double>> extra;  // solver, per cent
    static std::string signed_percent(double extra) { return bench::percent(std::optional<double>(extra / 100.0)); }
    std::string table;
};

EventCosts event_costs(const StudyContext& context, StudyResult& result) {
    EventCosts found;
    const SceneDescription scene = scenes::rain(1000);
    const long steps = steps_for(context.quick ? kQuickRainSeconds : kRainSeconds, scene.world.dt);
    MarkdownTable table({"scene", "stage", "solver", "µs/step, events not read", "µs/step, events read", "difference",
                         "events read per step (begins, ends, hits)", "overlap max (px), not read and read"});
    for (const Solver solver : {Solver::book, Solver::sequential_impulse}) {
        const std::string name(solver == Solver::book ? "book's passes" : "sequential impulse");
        std::array<Setting, 2> pair;
        for (const bool read : {false, true}) {
            WorldDescription world = scene.world;
            world.solver = solver;
            world.events = read;
            pair[read ? 1 : 0] = {Stage::s5_7, "events", name + (read ? ", events read" : ", events not read"), world};
        }
        const std::array<Row, 2> rows =
            paired_rows({"speed", "rain_1000", scene}, pair, context.repeats, steps, [](const BenchWorld& world) {
                const Penetration overlap = penetration(world.snapshot());
                return Metrics{.penetration_max = overlap.max, .penetration_mean = overlap.mean};
            });
        const double extra = 100.0 * (rows[1].cost_us / rows[0].cost_us - 1.0);
        found.extra.emplace_back(name, extra);
        const BenchWorld::EventCounts read = rows[1].events.value_or(BenchWorld::EventCounts{});
        table.add({"rain_1000", stage_name(Stage::s5_7), name, figure(rows[0].cost_us), figure(rows[1].cost_us),
                   EventCosts::signed_percent(extra),
                   figure(read.begins) + ", " + figure(read.ends) + ", " + figure(read.hits),
                   figure(rows[0].metrics.penetration_max) + ", " + figure(rows[1].metrics.penetration_max)});
        result.rows.insert(result.rows.end(), rows.begin(), rows.end());
    }
    found.table = table.text();
    return found;
}

}  // namespace

StudyResult speed_study(const StudyContext& context) {
    StudyResult result;
    const BookLoop book_loop{Contender{Stage::s5_1, std::nullopt, "5.1, the book"},
                             Contender{Stage::s5_2, BroadPhase::bounding_circle, "5.2 bounding_circle"},
                             Contender{Stage::s5_3, BroadPhase::bounding_circle, "5.3 bounding_circle"}};
    const BoundTests bound = bound_tests(context, book_loop, result);
    const Rains rain = rains(context, book_loop, result);
    const EventCosts events = event_costs(context, result);

    const double speedup = rain.book_400 / rain.fast_400;
    const double grid_per_js = kBookJsPer51 * rain.book_400 / rain.grid_400;
    const std::array<double, 3>& ns_per_test = bound.ns_per_test;
    std::string key = "Speed (targets in bench/README.md): a bound test costs " + figure(ns_per_test[0]) +
                      " ns on 5.1 and " + figure(ns_per_test[1]) + " ns on 5.2 (target " + figure(kBoundTestTarget) +
                      "); rain of 400 with the book's bounding circles: 5.2 is " + figure(speedup) +
                      " times as fast as 5.1 (target " + figure(kRain400Target) + ", " +
                      against(speedup, kRain400Target, false) + "); with the grid, " + figure(grid_per_js) +
                      " times the book's JavaScript by 5.1's measured ratio (target " + figure(kBookJsTarget) + ", " +
                      against(grid_per_js, kBookJsTarget, false) + ")";
    if (rain.box2d_1000 > 0) {
        const double ratio = rain.grid_1000 / rain.box2d_1000;
        key += "; rain of 1000 with the grid: " + figure(rain.grid_1000) + " µs per step against Box2D 2.4's " +
               figure(rain.box2d_1000) + " (" + figure(ratio) + " times Box2D's cost; target " + figure(kBox2dTarget) +
               ", " + against(ratio, kBox2dTarget, true) + ")";
    }
    result.key_figures.push_back(key + ".");
    std::string events_key =
        "Events (5.7): on the rain of 1000, a game reading every step's collision events "
        "makes a step cost";
    for (std::size_t k = 0; k < events.extra.size(); ++k) {
        const double extra = events.extra[k].second;
        events_key +=
            std::string(k == 0 ? " " : ", and ") + EventCosts::signed_percent(extra) + " with the " +
            events.extra[k].first + " (target at most +" + figure(kEventsTarget) + "%, " +
            (extra <= kEventsTarget ? std::string("met") : "missed by " + figure(extra - kEventsTarget) + " points") +
            ")";
    }
    result.key_figures.push_back(events_key + ".");
    result.markdown =
        "## Speed: the book's method, fast\n\n"
        "Stage 5.2 computes what 5.1 computes, bit for bit (`ctest -L identity`), in less time. The bound test: " +
        std::to_string(bound.shapes) +
        " discs spread so that no two touch, with the book's bounding circles, no pass and 1 (a pass that "
        "finds nothing ends the step on 5.2); the difference over the " +
        figure(bound.pairs_per_pass) + " pairs of the pass is the cost of one test, its loop included.\n\n" +
        bound.table + "\nThe rains run " + figure(rain.seconds) +
        " s of simulated time (the pile forms). Per step, every pass "
        "counted: the passes run (5.2 ends a step after a pass that changed nothing), the exact tests computed, "
        "and the share of the exact tests the skip rule saved (a pair found apart whose shapes no resolution has "
        "touched since, broad_phase.h); then the step's whole cost over the pairs whose exact test was computed "
        "and over the candidate pairs the broad phase handed on. 5.1 counts no pairs. The book's JavaScript is "
        "not run here: against 5.1 it was measured by hand at " +
        figure(kBookJsPer51) +
        " times 5.1's cost "
        "on the rain of 400.\n\n" +
        rain.table + "\nWhat 5.7's collision events cost (issue 37: at most " + figure(kEventsTarget) +
        "% more a step): the same rain of 1000 on 5.7, its own world (sleeping and continuous collision on), with "
        "no one reading its events, when the step keeps none, and with a game reading them after every step, going "
        "through the step's list and counting each event by kind. The two worlds take turns " +
        std::to_string(kTurnSteps) +
        " steps at a time, so that a busy moment of the machine falls on both alike; each cost is the median of " +
        std::to_string(context.repeats) + (context.repeats == 1 ? " run" : " runs") +
        ". Reading them changes no shape's motion: the overlaps are the same.\n\n" + events.table;
    return result;
}

}  // namespace bench
