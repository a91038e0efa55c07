// The tunnelling search against the speed worked out by hand.
#include <catch2/catch.hpp>

#include "scene_maker.h"
#include "study.h"
#include "tunnel_search.h"

namespace {

// The ball (radius 5) starts 1 px in front of the wall (4 px thick). It is looked at
// once per sub-step of dt / k, before it moves. If it moves less than 1 px per look it
// is seen touching the wall's near side and bounces back; up to 1 + 5 + 2 = 8 px, the
// first look that finds it inside the wall finds its centre short of the wall's middle,
// and the correction pushes it back out of the near side; beyond 8 px the first look
// inside finds its centre past the middle, and the correction pushes it on, out of the
// far side. So the slowest speed that gets through is 8 px per sub-step: 8 k / dt.
double by_hand(double dt, int substeps) {
    const double per_look =
        bench::scenes::kWallGap + bench::scenes::kWallBallRadius + bench::scenes::kWallThickness / 2;
    return per_look * substeps / dt;
}

// The wall at this dt, with this many sub-steps asked for (stage 5.3's key).
bench::SceneDescription wall(double dt, int substeps) {
    bench::SceneDescription scene = bench::scenes::thin_wall();
    scene.world.dt = dt;
    scene.world.substeps = substeps;
    return scene;
}

constexpr bench::Stage kSubsteps = bench::Stage::s5_3;

}  // namespace

TEST_CASE("ball_passes: a slow ball bounces off the wall, a fast one gets through") {
    const bench::SceneDescription scene = wall(1.0 / 60, 1);
    CHECK_FALSE(bench::ball_passes(kSubsteps, scene, 100.0));  // 1.7 px a step
    CHECK_FALSE(bench::ball_passes(kSubsteps, scene, 420.0));  // 7 px a step: caught short of the middle
    CHECK(bench::ball_passes(kSubsteps, scene, 540.0));        // 9 px a step: caught past the middle
    CHECK(bench::ball_passes(kSubsteps, scene, 6000.0));       // 100 px a step: never caught at all
}

TEST_CASE("slowest_passing_speed: 8 px per sub-step, for every dt and number of sub-steps") {
    for (const auto& [dt, substeps] :
         std::vector<std::pair<double, int>>{{1.0 / 60, 1}, {1.0 / 30, 1}, {1.0 / 60, 4}}) {
        INFO("dt " << dt << ", substeps " << substeps);
        const double found = bench::slowest_passing_speed(kSubsteps, wall(dt, substeps), 1e-4);
        // The search returns a speed that passes, at most 0.01% above the threshold.
        CHECK(found >= by_hand(dt, substeps) * (1 - 1e-9));
        CHECK(found <= by_hand(dt, substeps) * (1 + 1e-4) + 1e-9);
    }
}

TEST_CASE("slowest_passing_speed: the book's 5.1 looks once per step, as 5.3 does with one sub-step") {
    const bench::SceneDescription book = bench::scenes::thin_wall();
    const double found = bench::slowest_passing_speed(bench::Stage::s5_1, book, 1e-4);
    CHECK(found >= by_hand(book.world.dt, 1) * (1 - 1e-9));
    CHECK(found <= by_hand(book.world.dt, 1) * (1 + 1e-4) + 1e-9);
}

TEST_CASE("tunnelling_study: one row per dt and sub-steps, each with its speed") {
    const bench::StudyContext context{.quick = true, .repeats = 1, .scenes_dir = BENCH_SCENES_DIR};
    const bench::StudyResult result = bench::tunnelling_study(context);
    REQUIRE(result.rows.size() == 2);                   // quick: dt 1/60 with 1 and 2 sub-steps
    CHECK(result.rows[0].stage == bench::Stage::s5_1);  // one look per step: the book's
    CHECK(result.rows[1].stage == bench::Stage::s5_3);  // sub-steps: 5.3's
    for (const bench::Row& row : result.rows) {
        REQUIRE(row.metrics.tunnel_speed);
        const double expected = by_hand(row.world.dt, bench::substeps_of(row.world));
        CHECK(*row.metrics.tunnel_speed == Approx(expected).epsilon(1.1e-3));
    }
    REQUIRE(result.figures.size() == 1);
    CHECK(result.figures[0].file == "tunnelling.png");
}

TEST_CASE("trajectory_study: both integrators are off the parabola by g t dt / 2") {
    // Gravity 100 px/s^2 for t = 2 s: 100 px/s of error per second of dt, 3.33 px at
    // dt 1/30 and 1.67 px at 1/60.
    const bench::StudyContext context{.quick = true, .repeats = 1, .scenes_dir = BENCH_SCENES_DIR};
    const bench::StudyResult result = bench::trajectory_study(context);
    REQUIRE(result.rows.size() == 4);
    for (const bench::Row& row : result.rows) {
        INFO(row.setting);
        REQUIRE(row.metrics.trajectory_error);
        CHECK(*row.metrics.trajectory_error == Approx(bench::scenes::kProjectileGravity * 2.0 * row.world.dt / 2));
    }
    CHECK(result.rows[0].world.integrator == bench::Integrator::symplectic);
    CHECK(result.rows[3].world.integrator == bench::Integrator::explicit_euler);
}
