// Box2D as the bench sees it: the scene's px, masses and times go in, and come back out.
#include <catch2/catch.hpp>

#include "box2d_world.h"
#include "measures.h"

#if BENCH_HAS_BOX2D

TEST_CASE("box2d_world: masses and inertias in the scene's units") {
    bench::SceneDescription scene;
    scene.bodies = {{.shape = bench::Shape::rectangle, .center = {300, 200}, .width = 40, .height = 20, .mass = 2},
                    {.shape = bench::Shape::circle, .center = {100, 100}, .radius = 15, .mass = 3},
                    {.shape = bench::Shape::rectangle, .center = {400, 400}, .width = 800, .height = 20, .mass = 0}};
    const bench::Snapshot bodies = bench::box2d_world(scene)->snapshot();
    REQUIRE(bodies.size() == 3);
    // Box2D works in single precision.
    CHECK(bodies[0].mass == Approx(2.0).epsilon(1e-5));
    // m (w^2 + h^2) / 12 of the core inside Box2D's skin of 0.01 m (0.3 px) all round.
    const double w = 40 - 0.6, h = 20 - 0.6;
    CHECK(bodies[0].inertia == Approx(2.0 * (w * w + h * h) / 12).epsilon(1e-5));
    CHECK(bodies[1].mass == Approx(3.0).epsilon(1e-5));
    CHECK(bodies[1].inertia == Approx(3.0 * 15 * 15 / 2).epsilon(1e-5));  // a solid disc: m r^2 / 2
    CHECK(bodies[2].is_static);
    CHECK(oracle::center(bodies[0].shape).x == Approx(300.0).epsilon(1e-6));
}

TEST_CASE("box2d_world: a free fall in px, s and the scene's dt") {
    // Box2D's integrator is symplectic Euler too: after n steps from rest a body has
    // fallen g dt^2 n (n + 1) / 2 = 20 / 3600 * 60 * 61 / 2 = 10.17 px for n = 60.
    bench::SceneDescription scene;
    scene.world.gravity = {0, 20};
    scene.world.dt = 1.0 / 60;
    scene.bodies = {{.shape = bench::Shape::circle, .center = {100, 100}, .radius = 10}};
    const auto world = bench::box2d_world(scene);
    world->run(60);
    const bench::Snapshot after = world->snapshot();
    CHECK(oracle::center(after[0].shape).y - 100 == Approx(20.0 / 3600 * 60 * 61 / 2).epsilon(1e-4));
    CHECK(after[0].velocity.y == Approx(20.0).epsilon(1e-4));
    CHECK(world->steps() == 60);
    CHECK_FALSE(world->pair_counts());
}

#else

TEST_CASE("box2d_world: a build without Box2D has no Box2D world") {
    CHECK_FALSE(bench::box2d_available());
    CHECK(bench::box2d_world(bench::SceneDescription{}) == nullptr);
}

#endif
