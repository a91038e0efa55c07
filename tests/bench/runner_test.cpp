// Rows from runs: the steps and repeats they took, the pairs per step they counted.
#include <catch2/catch.hpp>

#include "runner.h"
#include "scene_maker.h"

namespace {

bench::Measure run_steps(long steps, int* calls) {
    return [steps, calls](bench::BenchWorld& world, const browser::WorldSettings&) {
        ++*calls;
        world.run(steps);
        bench::Metrics metrics;
        metrics.top_drift = 1.5;
        return metrics;
    };
}

}  // namespace

TEST_CASE("median: the middle value, or the mean of the middle two") {
    CHECK(bench::median({5.0, 1.0, 3.0}) == 3.0);
    CHECK(bench::median({4.0, 1.0, 3.0, 10.0}) == 3.5);
    CHECK_THROWS_AS(bench::median({}), std::invalid_argument);
}

TEST_CASE("engine_row: the setting's world, the steps of a run, one run per repeat") {
    const browser::SceneDescription scene = bench::scenes::pair(bench::scenes::PairKind::rect_circle);
    browser::WorldSettings world = scene.world;
    world.relaxation_iterations = 4;
    int calls = 0;
    const bench::Row row =
        bench::engine_row({"pairs", "pair", scene}, {"relaxation_iterations", "passes 4", world}, 3, run_steps(50, &calls));
    CHECK(calls == 3);
    CHECK(row.repeats == 3);
    CHECK(row.steps == 50);
    CHECK(row.world.relaxation_iterations == 4);
    CHECK(row.setting == "passes 4");
    CHECK(row.bodies == 2);
    CHECK(row.cost_us > 0);
    CHECK(row.metrics.top_drift == 1.5);
    // One pair, looked at in each of the 4 passes; the disc rests on the box, so their
    // bounding circles overlap and every look goes on to the exact test.
    REQUIRE(row.candidate_pairs);
    CHECK(*row.candidate_pairs == 4.0);
    CHECK(*row.narrow_tests == 4.0);
}

TEST_CASE("engine_row: sub-steps repeat the passes within a step") {
    const browser::SceneDescription scene = bench::scenes::pair(bench::scenes::PairKind::rect_rect);
    browser::WorldSettings world = scene.world;
    world.relaxation_iterations = 3;
    world.substeps = 2;
    int calls = 0;
    const bench::Row row = bench::engine_row({"pairs", "pair", scene}, {"substeps", "substeps 2", world}, 1,
                                             run_steps(10, &calls));
    CHECK(*row.candidate_pairs == 6.0);
}

TEST_CASE("box2d_row: Box2D's row where this build has Box2D") {
    const browser::SceneDescription scene = bench::scenes::pair(bench::scenes::PairKind::rect_rect);
    int calls = 0;
    const std::optional<bench::Row> row = bench::box2d_row({"pairs", "pair", scene}, 2, run_steps(20, &calls));
#if BENCH_HAS_BOX2D
    REQUIRE(row);
    CHECK(row->engine == bench::EngineKind::box2d);
    CHECK(row->steps == 20);
    CHECK(row->repeats == 2);
    CHECK_FALSE(row->candidate_pairs);
#else
    CHECK_FALSE(row);
    CHECK(calls == 0);
#endif
}
