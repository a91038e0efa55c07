// The price of one pair: nanoseconds per candidate pair per relaxation pass, for each
// kind of pair. A scene of one pair in resting contact is run with 1 pass and with 30;
// everything else a step does (moving two shapes, the loop) is the same in both, so
// the difference in cost over the 29 extra passes is what a pass over the pair costs:
// the bounding-circle test, the exact test and the resolution of the contact.

#include <array>

#include "markdown.h"
#include "measures.h"
#include "scene_maker.h"
#include "sweep_study.h"

namespace bench {
namespace {

// The book's 5.1 counts no pairs; 5.2 counts them, and runs the book's pass when asked
// for the bounding circles.
constexpr Stage kCountingStage = Stage::s5_2;
constexpr int kFewPasses = 1;
constexpr int kManyPasses = 30;
constexpr long kSettleSteps = 60;  // a second for the pair to come to rest
constexpr long kSteps = 100'000;   // a few microseconds each: long runs, for a steady time
constexpr long kQuickSteps = 200;

// The overlap left at the end shows that the pair was still in contact, so every pass
// went on to resolve it.
Measure resting_steps(long steps) {
    return [steps](BenchWorld& world, const WorldDescription&) {
        world.run_untimed(kSettleSteps);
        world.run(steps);
        Metrics metrics;
        metrics.penetration_max = penetration(world.snapshot()).max;
        return metrics;
    };
}

struct Kind {
    scenes::PairKind kind;
    const char* name;
};
constexpr std::array kKinds{Kind{scenes::PairKind::rect_rect, "rect-rect"},
                            Kind{scenes::PairKind::rect_circle, "rect-circle"},
                            Kind{scenes::PairKind::circle_circle, "circle-circle"}};

}  // namespace

StudyResult pair_cost_study(const StudyContext& context) {
    const long steps = context.quick ? kQuickSteps : kSteps;
    StudyResult result;
    std::string key = "Nanoseconds per candidate pair per relaxation pass:";
    MarkdownTable summary({"pair", "µs/step, 1 pass", "µs/step, 30 passes", "exact tests per pass",
                           "ns per pair per pass", "overlap at the end (px)"});
    for (const Kind& kind : kKinds) {
        const SceneDescription scene = scenes::pair(kind.kind);
        const std::string scene_name = std::string("pair_") + kind.name;
        std::array<Row, 2> rows;
        for (int i = 0; i < 2; ++i) {
            WorldDescription world = scene.world;
            world.relaxation_iterations = i == 0 ? kFewPasses : kManyPasses;
            world.broad_phase = BroadPhase::bounding_circle;
            const Setting setting{kCountingStage, "relaxation_iterations",
                                  std::string(kind.name) + ", passes " + std::to_string(world.relaxation_iterations),
                                  world};
            rows[i] = stage_row({"pairs", scene_name, scene}, setting, context.repeats, resting_steps(steps));
        }
        const double extra_passes = kManyPasses - kFewPasses;
        const double tests_per_pass = rows[1].narrow_tests.value_or(0.0) / kManyPasses;
        const double ns = (rows[1].cost_us - rows[0].cost_us) * 1000.0 / extra_passes / tests_per_pass;
        for (Row& row : rows) row.metrics.ns_per_pair = ns;
        summary.add({kind.name, figure(rows[0].cost_us), figure(rows[1].cost_us), figure(tests_per_pass), figure(ns),
                     figure(rows[1].metrics.penetration_max)});
        key += std::string(kind.kind == scenes::PairKind::rect_rect ? " " : ", ") + kind.name + " " + figure(ns);
        result.rows.insert(result.rows.end(), rows.begin(), rows.end());
    }
    result.key_figures.push_back(key + ".");
    result.markdown =
        "## The price of a pair\n\n"
        "One pair of one kind in resting contact (a box on a static box, a disc on a static box, a "
        "disc balanced on a static disc), timed on stage " +
        stage_name(kCountingStage) + " with the book's bounding circles (5.1 does not count pairs) over " +
        std::to_string(steps) +
        " steps with 1 relaxation pass and with 30. The difference, divided by the 29 extra passes "
        "and by the pairs each pass tests exactly, is the cost of one pair in one pass: the "
        "bounding-circle test, the exact test and the resolution. Multiply by the pairs per step "
        "of a scene to see what its narrow phase costs.\n\n" +
        summary.text();
    return result;
}

}  // namespace bench
