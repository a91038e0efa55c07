// Rows from runs: the steps and repeats they took, the pairs per step they counted.
#include <catch2/catch.hpp>

#include <chrono>
#include <thread>

#include "runner.h"
#include "scene_maker.h"
#include "thread_clock.h"

namespace {

bench::Measure run_steps(long steps, int* calls) {
    return [steps, calls](bench::BenchWorld& world, const bench::WorldDescription&) {
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

TEST_CASE("stage_row: the setting's stage and world, the steps of a run, one run per repeat") {
    const bench::SceneDescription scene = bench::scenes::pair(bench::scenes::PairKind::rect_circle);
    bench::WorldDescription world = scene.world;
    world.relaxation_iterations = 4;
    int calls = 0;
    const bench::Row row =
        bench::stage_row({"pairs", "pair", scene}, {bench::Stage::s5_2, "relaxation_iterations", "passes 4", world}, 3,
                         run_steps(50, &calls));
    CHECK(calls == 3);
    CHECK(row.repeats == 3);
    CHECK(row.steps == 50);
    CHECK(row.stage == bench::Stage::s5_2);
    CHECK(row.world.relaxation_iterations == 4);
    CHECK(row.world.broad_phase == bench::BroadPhase::grid);  // 5.2's own default, written out
    CHECK_FALSE(row.world.substeps);                          // not a key of 5.2's
    CHECK(row.setting == "passes 4");
    CHECK(row.bodies == 2);
    CHECK(row.cost_us > 0);
    CHECK(row.metrics.top_drift == 1.5);
    // One pair, looked at in each pass; the disc rests on the box, so their bounding
    // circles overlap and every look goes on to the exact test, never skipped (every pass
    // resolves the pair). All 4 passes run in every step but perhaps the first: the
    // disc starts just touching the box, which the exact test counts as apart, and a pass
    // that resolves nothing ends a step. So 1 + 49 * 4 passes over the 50 steps at least.
    REQUIRE(row.candidate_pairs);
    REQUIRE(row.passes);
    CHECK(*row.passes <= 4.0);
    CHECK(*row.passes >= (1 + 49 * 4) / 50.0);
    CHECK(*row.candidate_pairs == *row.passes);
    CHECK(*row.narrow_tests == *row.passes);
    CHECK(*row.skipped_tests == 0.0);
}

TEST_CASE("stage_row: the book's 5.1 counts no pairs") {
    const bench::SceneDescription scene = bench::scenes::pair(bench::scenes::PairKind::rect_circle);
    int calls = 0;
    const bench::Row row = bench::stage_row({"pairs", "pair", scene}, {bench::Stage::s5_1, "", "scene", scene.world}, 1,
                                            run_steps(5, &calls));
    CHECK(row.stage == bench::Stage::s5_1);
    CHECK_FALSE(row.candidate_pairs);
    CHECK_FALSE(row.narrow_tests);
    CHECK_FALSE(row.world.broad_phase);
}

TEST_CASE("stage_row: sub-steps repeat the passes within a step") {
    const bench::SceneDescription scene = bench::scenes::pair(bench::scenes::PairKind::rect_rect);
    bench::WorldDescription world = scene.world;
    world.relaxation_iterations = 3;
    world.substeps = 2;
    int calls = 0;
    const bench::Row row = bench::stage_row(
        {"pairs", "pair", scene}, {bench::Stage::s5_3, "substeps", "substeps 2", world}, 1, run_steps(10, &calls));
    CHECK(*row.candidate_pairs == 6.0);
}

TEST_CASE("stage_row: a stage refuses a key it does not read, naming itself and the key") {
    const bench::SceneDescription scene = bench::scenes::pair(bench::scenes::PairKind::rect_rect);
    bench::WorldDescription world = scene.world;
    world.substeps = 2;
    int calls = 0;
    CHECK_THROWS_WITH(bench::stage_row({"pairs", "pair", scene}, {bench::Stage::s5_2, "substeps", "substeps 2", world},
                                       1, run_steps(10, &calls)),
                      Catch::StartsWith("stage 5.2: the bench's scene: world.substeps: unknown key"));
    CHECK(calls == 0);
}

TEST_CASE("box2d_row: Box2D's row where this build has Box2D") {
    const bench::SceneDescription scene = bench::scenes::pair(bench::scenes::PairKind::rect_rect);
    int calls = 0;
    const std::optional<bench::Row> row = bench::box2d_row({"pairs", "pair", scene}, 2, run_steps(20, &calls));
#if BENCH_HAS_BOX2D
    REQUIRE(row);
    CHECK(row->stage == bench::Stage::box2d);
    CHECK(row->steps == 20);
    CHECK(row->repeats == 2);
    CHECK_FALSE(row->candidate_pairs);
#else
    CHECK_FALSE(row);
    CHECK(calls == 0);
#endif
}

TEST_CASE("thread_cpu_seconds: a thread that waits uses no processor time") {
    // The bench's clock leaves out the time a run waits: a thread asleep for 200 ms,
    // as a run waits for a core, has used a few microseconds of processor time, not
    // 200 ms. The wall clock would show the whole wait.
    const double before = bench::thread_cpu_seconds();
    std::this_thread::sleep_for(std::chrono::milliseconds(200));
    const double waited = bench::thread_cpu_seconds() - before;
    CHECK(waited >= 0.0);
    CHECK(waited < 0.05);
}
