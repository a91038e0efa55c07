// Speed: what the book's method costs as the book writes it (5.1) and as 5.2 runs it,
// the very same computation, and where a step's time goes. Three measures:
//  - the bounding-circle test: discs spread so that no two touch, run with 1 pass and
//    with 5; the difference over the 4 extra passes and the n (n - 1) / 2 pairs a pass
//    tests is the cost of one test (its loop included);
//  - a rain of 400 on 5.1 and on 5.2 with the book's bounding circles and with the
//    grid, and a rain of 1000 on 5.2 against Box2D: microseconds per step;
//  - the share of a step spent in the broad phase, the narrow phase and the resolution
//    (BenchWorld::time_phases says how they are taken apart).

#include <array>
#include <optional>

#include "markdown.h"
#include "measures.h"
#include "scene_maker.h"
#include "sweep_study.h"

namespace bench {
namespace {

constexpr int kSpreadShapes = 1000;
constexpr int kQuickSpreadShapes = 100;
constexpr int kFewPasses = 1;
constexpr int kManyPasses = 5;
constexpr long kSpreadSteps = 10;
constexpr double kRainSeconds = 3.0;  // the pile forms: falling, landing, settling
constexpr double kQuickRainSeconds = 0.1;
constexpr long kShareSteps = 30;  // after the timed run, on the pile as it then is
constexpr long kQuickShareSteps = 2;
constexpr double kBoundTestTarget = 1.0;  // ns
constexpr double kRain400Target = 3.0;    // times as fast as 5.1

struct Contender {
    Stage stage;
    std::optional<BroadPhase> broad_phase;  // unset: the stage's only way (5.1) or its default
    const char* name;
};

Setting setting_for(const Contender& contender, WorldDescription world, const std::string& label) {
    if (contender.broad_phase) world.broad_phase = *contender.broad_phase;
    return {contender.stage, contender.broad_phase ? "broad_phase" : "", label, world};
}

struct Shares {
    double broad = 0.0;
    double narrow = 0.0;
    double resolution = 0.0;
};

// A rain, timed, then taken apart (first run only).
Measure rain_measure(long steps, long share_steps, std::optional<Shares>& shares) {
    return [steps, share_steps, &shares](BenchWorld& world, const WorldDescription&) {
        world.run(steps);
        if (!shares) {
            if (const auto seconds = world.time_phases(share_steps); seconds && seconds->step > 0) {
                shares = Shares{seconds->broad / seconds->step, (seconds->narrow - seconds->broad) / seconds->step,
                                (seconds->step - seconds->narrow) / seconds->step};
            }
        }
        const Penetration overlap = penetration(world.snapshot());
        Metrics metrics;
        metrics.penetration_max = overlap.max;
        metrics.penetration_mean = overlap.mean;
        return metrics;
    };
}

std::string percent(double share) { return figure(100.0 * share, 2) + "%"; }

}  // namespace

StudyResult speed_study(const StudyContext& context) {
    StudyResult result;
    const std::array<Contender, 3> book_loop{Contender{Stage::s5_1, std::nullopt, "5.1, the book"},
                                             Contender{Stage::s5_2, BroadPhase::bounding_circle, "5.2 bounding_circle"},
                                             Contender{Stage::s5_3, BroadPhase::bounding_circle, "5.3 bounding_circle"}};

    // The bounding-circle test.
    const int spread_shapes = context.quick ? kQuickSpreadShapes : kSpreadShapes;
    const SceneDescription spread = scenes::spread(spread_shapes);
    const double pairs_per_pass = spread_shapes * (spread_shapes - 1) / 2.0;
    MarkdownTable bound({"stage", "µs/step, 1 pass", "µs/step, 5 passes", "ns per bound test"});
    std::array<double, 3> ns_per_test{};
    for (std::size_t c = 0; c < book_loop.size(); ++c) {
        std::array<Row, 2> rows;
        for (int k = 0; k < 2; ++k) {
            WorldDescription world = spread.world;
            world.relaxation_iterations = k == 0 ? kFewPasses : kManyPasses;
            const std::string label = std::string(book_loop[c].name) + ", passes " +
                                      std::to_string(world.relaxation_iterations);
            rows[k] = stage_row({"speed", "spread_" + std::to_string(spread_shapes), spread},
                                setting_for(book_loop[c], world, label), context.repeats,
                                [](BenchWorld& w, const WorldDescription&) {
                                    w.run(kSpreadSteps);
                                    return Metrics{};
                                });
        }
        ns_per_test[c] = (rows[1].cost_us - rows[0].cost_us) * 1000.0 / (kManyPasses - kFewPasses) / pairs_per_pass;
        bound.add({book_loop[c].name, figure(rows[0].cost_us), figure(rows[1].cost_us), figure(ns_per_test[c])});
        result.rows.insert(result.rows.end(), rows.begin(), rows.end());
    }

    // Rains.
    const double seconds = context.quick ? kQuickRainSeconds : kRainSeconds;
    const long share_steps = context.quick ? kQuickShareSteps : kShareSteps;
    MarkdownTable rains({"scene", "stage", "µs/step", "times as fast as 5.1", "broad phase", "narrow phase",
                         "resolution and the rest", "overlap max (px)"});
    struct RainRun {
        int shapes;
        Contender contender;
    };
    const std::array<RainRun, 5> runs{RainRun{400, book_loop[0]}, RainRun{400, book_loop[1]},
                                      RainRun{400, {Stage::s5_2, BroadPhase::grid, "5.2 grid"}},
                                      RainRun{1000, {Stage::s5_2, BroadPhase::grid, "5.2 grid"}},
                                      RainRun{1000, {Stage::s5_3, std::nullopt, "5.3 (grid)"}}};
    double rain400_book = 0.0;
    double rain400_fast = 0.0;
    double rain1000_grid = 0.0;
    for (const RainRun& run : runs) {
        const SceneDescription scene = scenes::rain(run.shapes);
        const std::string name = "rain_" + std::to_string(run.shapes);
        std::optional<Shares> shares;
        const Row row = stage_row({"speed", name, scene}, setting_for(run.contender, scene.world, run.contender.name),
                                  context.repeats,
                                  rain_measure(steps_for(seconds, scene.world.dt), share_steps, shares));
        if (run.shapes == 400 && run.contender.stage == Stage::s5_1) rain400_book = row.cost_us;
        if (run.shapes == 400 && run.contender.broad_phase == BroadPhase::bounding_circle) rain400_fast = row.cost_us;
        if (run.shapes == 1000 && run.contender.broad_phase == BroadPhase::grid) rain1000_grid = row.cost_us;
        const std::string speedup = run.shapes == 400 ? figure(rain400_book / row.cost_us) : "";
        rains.add({name, run.contender.name, figure(row.cost_us), speedup, shares ? percent(shares->broad) : "",
                   shares ? percent(shares->narrow) : "", shares ? percent(shares->resolution) : "",
                   figure(row.metrics.penetration_max)});
        result.rows.push_back(row);
    }
    const SceneDescription rain1000 = scenes::rain(1000);
    std::optional<Shares> no_shares;
    double box2d_cost = 0.0;
    if (const auto box2d = box2d_row({"speed", "rain_1000", rain1000}, context.repeats,
                                     rain_measure(steps_for(seconds, rain1000.world.dt), 0, no_shares))) {
        box2d_cost = box2d->cost_us;
        rains.add({"rain_1000", box2d->setting, figure(box2d->cost_us), "", "", "", "",
                   figure(box2d->metrics.penetration_max)});
        result.rows.push_back(*box2d);
    }

    const double speedup = rain400_book / rain400_fast;
    std::string key = "Speed (targets in bench/README.md): a bound test costs " + figure(ns_per_test[0]) +
                      " ns on 5.1 and " + figure(ns_per_test[1]) + " ns on 5.2 (target " + figure(kBoundTestTarget) +
                      "); rain of 400 with the book's bounding circles: 5.2 is " + figure(speedup) +
                      " times as fast as 5.1 (target " + figure(kRain400Target) + ")";
    if (box2d_cost > 0) {
        key += "; rain of 1000 with the grid: " + figure(rain1000_grid) + " µs per step against Box2D 2.4's " +
               figure(box2d_cost) + " (" + figure(rain1000_grid / box2d_cost) + " times Box2D's cost; target 1)";
    }
    result.key_figures.push_back(key + ".");
    result.markdown =
        "## Speed: the book's method, fast\n\n"
        "Stage 5.2 computes what 5.1 computes, bit for bit (`ctest -L identity`), in less time. The bound test: " +
        std::to_string(spread_shapes) +
        " discs spread so that no two touch, with the book's bounding circles, 1 pass and 5; the difference over "
        "the 4 extra passes and the " + figure(pairs_per_pass) + " pairs of a pass is the cost of one test, its "
        "loop included.\n\n" + bound.text() +
        "\nThe rains run " + figure(seconds) + " s of simulated time (the pile forms). Then, on the pile as it "
        "is, " + std::to_string(share_steps) + " more steps are taken apart: before each, its relaxation passes "
        "run once with the broad phase alone and once with the narrow phase too, changing nothing, then the step "
        "itself; the differences are the shares (the rest of a step, moving the shapes, counts with the "
        "resolution).\n\n" + rains.text();
    return result;
}

}  // namespace bench
