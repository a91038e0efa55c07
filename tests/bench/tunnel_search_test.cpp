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
    const double per_look = bench::scenes::kWallGap + bench::scenes::kWallBallRadius +
                            bench::scenes::kWallThickness / 2;
    return per_look * substeps / dt;
}

browser::SceneDescription wall(double dt, int substeps) {
    browser::SceneDescription scene = bench::scenes::thin_wall();
    scene.world.dt = dt;
    scene.world.substeps = substeps;
    return scene;
}

}  // namespace

TEST_CASE("ball_passes: a slow ball bounces off the wall, a fast one gets through") {
    const browser::SceneDescription scene = wall(1.0 / 60, 1);
    CHECK_FALSE(bench::ball_passes(scene, 100.0));  // 1.7 px a step
    CHECK_FALSE(bench::ball_passes(scene, 420.0));  // 7 px a step: caught short of the middle
    CHECK(bench::ball_passes(scene, 540.0));        // 9 px a step: caught past the middle
    CHECK(bench::ball_passes(scene, 6000.0));       // 100 px a step: never caught at all
}

TEST_CASE("slowest_passing_speed: 8 px per sub-step, for every dt and number of sub-steps") {
    for (const auto& [dt, substeps] : std::vector<std::pair<double, int>>{{1.0 / 60, 1}, {1.0 / 30, 1}, {1.0 / 60, 4}}) {
        INFO("dt " << dt << ", substeps " << substeps);
        const double found = bench::slowest_passing_speed(wall(dt, substeps), 1e-4);
        // The search returns a speed that passes, at most 0.01% above the threshold.
        CHECK(found >= by_hand(dt, substeps) * (1 - 1e-9));
        CHECK(found <= by_hand(dt, substeps) * (1 + 1e-4) + 1e-9);
    }
}

TEST_CASE("tunnelling_study: one row per dt and sub-steps, each with its speed") {
    const bench::StudyContext context{.quick = true, .repeats = 1, .scenes_dir = BENCH_SCENES_DIR};
    const bench::StudyResult result = bench::tunnelling_study(context);
    REQUIRE(result.rows.size() == 2);  // quick: dt 1/60 with 1 and 2 sub-steps
    for (const bench::Row& row : result.rows) {
        REQUIRE(row.metrics.tunnel_speed);
        CHECK(*row.metrics.tunnel_speed == Approx(by_hand(row.world.dt, row.world.substeps)).epsilon(1.1e-3));
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
    CHECK(result.rows[0].world.integrator == browser::Integrator::symplectic);
    CHECK(result.rows[3].world.integrator == browser::Integrator::explicit_euler);
}
