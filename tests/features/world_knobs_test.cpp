// The knobs of stage 5.3 on (world_settings.h): each one held to what it promises.
// Sub-steps must be the same as a shorter step; the integrators, the friction models,
// and rotation and friction off are judged against mechanics worked out by hand.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "circle.h"
#include "closed_box.h"
#include "expect.h"
#include "near.h"
#include "random_scene.h"
#include "same_state.h"
#include "rectangle.h"
#include "scene_file.h"
#include "scene_io.h"
#include "stage_program.h"
#include "world_fixture.h"
#include "world_from_scene.h"

namespace world_knobs_test {

namespace fs = std::filesystem;
using browser::Key;
using engine::BodyDescription;
using engine::ShapeType;
using engine::Vec2;
using engine::WorldSettings;

namespace {

// ---------------------------------------------------------------------------------
// Worlds for the hand calculations

// The demo's world without its removal of shapes that leave the canvas, and with the
// knobs a test sets.
WorldSettings demoWorld() {
    WorldSettings world = engine::kBookWorld;
    world.remove_out_of_bounds = false;
    return world;
}

constexpr double kG = engine::kGravity.y;  // 20 px/s^2, down

// An 800 px static floor with its top face at y = 390, gripping as hard as anything
// on it (the pair takes the smaller friction) and not bouncing at all.
constexpr double kFloorTop = 390.0;
engine::Rectangle& addFloor(engine::Core& core) {
    return core.add(engine::Rectangle({400, kFloorTop + 10}, 800, 20, {.mass = 0, .friction = 1, .restitution = 0}));
}

// A 20 px box of mass 1 standing on that floor (touching it: no overlap yet), sliding
// to the right at `speed`.
engine::Rectangle& addSlidingBox(engine::Core& core, double speed, double friction) {
    engine::Rectangle& box =
        core.add(engine::Rectangle({100, kFloorTop - 10}, 20, 20, {.mass = 1, .friction = friction, .restitution = 0}));
    box.setVelocity({speed, 0});
    return box;
}

// Steps until the box stops (at most `limit` steps); how far it slid.
double slideUntilStopped(test::WorldFixture& page, const engine::RigidShape& box, int limit) {
    const double start = box.center().x;
    for (int step = 0; step < limit && box.velocity().x > 0; ++step) page.steps(1);
    return box.center().x - start;
}

}  // namespace

// =================================================================================
// Every knob, read from a scene file

TEST_CASE("world knobs: a scene file that sets no knob gets the book's engine") {
    const WorldSettings world = test::worldFromScene("{}");
    test::expectEqual("a scene file that sets no knob: the book's world (kBookWorld), every setting", true,
                      world == engine::kBookWorld);
    test::expectEqual("its substeps: the book's one step", 1, world.substeps);
    test::expectEqual("its integrator: the book's symplectic Euler", engine::Integrator::symplectic, world.integrator);
    test::expectEqual("its friction model: the book's", engine::FrictionModel::book, world.friction_model);
    test::expectEqual("its rotation switch: on", true, world.rotation);
    test::expectEqual("its friction switch: on", true, world.friction);
}

TEST_CASE("world knobs: substeps is a whole number from 1 to 1000") {
    for (const char* accepted : {"1", "2", "1000"}) {
        INFO("substeps " << accepted);
        CHECK(test::worldFromScene(std::string(R"({"substeps": )") + accepted + "}").substeps == std::stoi(accepted));
    }
    for (const char* refused : {"0", "1001", "2.5", "-1"}) {
        INFO("substeps " << refused);
        CHECK_THROWS_AS(test::worldFromScene(std::string(R"({"substeps": )") + refused + "}"), browser::SceneError);
    }
}

TEST_CASE("world knobs: the scene file's substeps and integrator, against the closed forms of a fall") {
    // A ball falls from rest under g = 30 px/s^2 for 20 steps of dt = 1/60 s, each run
    // as k sub-steps of h = dt / k: m = 20 k steps of h in all. After m steps of h the
    // velocity is g m h either way; symplectic Euler has moved g h^2 m (m + 1) / 2,
    // explicit Euler g h^2 m (m - 1) / 2.
    for (const int substeps : {1, 3}) {
        for (const char* integrator : {"symplectic", "explicit"}) {
            INFO(substeps << " sub-steps, " << integrator << " Euler");
            const WorldSettings world =
                test::worldFromScene(std::string(R"({"movement": true, "gravity": [0, 30], "substeps": )") +
                                     std::to_string(substeps) + R"(, "integrator": ")" + integrator + "\"}");
            REQUIRE(world.substeps == substeps);
            const bool symplectic = std::string(integrator) == "symplectic";
            REQUIRE(world.integrator ==
                    (symplectic ? engine::Integrator::symplectic : engine::Integrator::explicit_euler));
            test::WorldFixture page(world);
            engine::Circle& ball = page.core.add(engine::Circle({100, 100}, 5));
            page.steps(20);
            const double m = 20.0 * substeps;
            const double h = world.dt / substeps;
            // 1e-12: 60 roundings of numbers near 100 px.
            CHECK_THAT(ball.velocity().y, test::near(30 * m * h, 1e-12));
            CHECK_THAT(ball.center().y, test::near(100 + 30 * h * h * m * (symplectic ? m + 1 : m - 1) / 2, 1e-12));
        }
    }
}

TEST_CASE("world knobs: the scene file's friction_model, rotation and friction, one hit worked out by hand") {
    // A ball of radius 10 and mass 1 (a solid disc: 1/I = 2 / (m r^2) = 0.02), falling at
    // 60 px/s and sliding right at 40 px/s, 1 px into a static floor; e = 0.5 and mu = 0.5
    // for the pair. No gravity, movement and positional correction off: only the first
    // pass's impulses act (after it the contact separates).
    //   normal (0, -1), arm (0, 10) down to the contact: r x n = 0, so
    //     jN = (1 + e) 60 / (1/m) = 90, and the ball leaves the floor at 30 px/s;
    //   tangent (-1, 0), against the slide of 40 px/s: r x t = 10, so the response is
    //     1/m + 10^2 0.02 = 3 with rotation, 1/m = 1 without (zero arms);
    //   book:    jT = min((1 + e) mu 40 / response, jN): 10 with rotation, 30 without;
    //   Coulomb: jT = min(40 / response, mu jN = 45):  40/3 with rotation, 40 without;
    //   then vx = 40 - jT and w = (r x t) jT / I = 0.2 jT with rotation.
    // friction: false leaves the slide alone.
    struct Case {
        const char* knobs;
        double vx, w;
    };
    const Case cases[] = {
        {"", 30, 2},
        {R"(, "rotation": false)", 10, 0},
        {R"(, "friction_model": "coulomb")", 40 - 40.0 / 3, 0.2 * 40 / 3},
        {R"(, "friction_model": "coulomb", "rotation": false)", 0, 0},
        {R"(, "friction": false)", 40, 0},
        {R"(, "friction": false, "friction_model": "coulomb")", 40, 0},
    };
    for (const Case& c : cases) {
        INFO("knobs" << c.knobs);
        const WorldSettings world = test::worldFromScene(
            std::string(R"({"movement": false, "gravity": [0, 0], "positional_correction": false)") + c.knobs + "}");
        test::WorldFixture page(world);
        page.core.add(engine::Rectangle({100, 110}, 200, 20, {.mass = 0, .friction = 1, .restitution = 0.5}));
        engine::Circle& ball =
            page.core.add(engine::Circle({100, 91}, 10, {.mass = 1, .friction = 0.5, .restitution = 0.5}));
        ball.setVelocity({40, 60});
        page.steps(1);
        // 1e-12: a handful of operations on numbers below 100.
        CHECK_THAT(ball.velocity(), test::near(Vec2{c.vx, -30}, 1e-12));
        CHECK_THAT(ball.angularVelocity(), test::near(c.w, 1e-12));
    }
}

// =================================================================================
// Sub-steps

TEST_CASE("world knobs: 4 sub-steps of a 1/64 s step are 4 steps of 1/256 s, bit for bit") {
    // 1/64 / 4 = 1/256 exactly in binary, so each sub-step does the very operations a
    // step of 1/256 s does. Shapes fall off the canvas and are removed here too.
    const engine::Scene scene = engine::loadScene(fs::path(SCENE_LIBRARY_DIR) / "book_demo.json");
    WorldSettings coarse = scene.world;
    coarse.dt = 1.0 / 64;
    coarse.substeps = 4;
    WorldSettings fine = scene.world;
    fine.dt = 1.0 / 256;
    test::WorldFixture sub_stepped(coarse);
    test::WorldFixture stepped(fine);
    engine::buildScene(sub_stepped.core, scene.bodies);
    engine::buildScene(stepped.core, scene.bodies);
    long listened = 0;
    sub_stepped.core.onStep([&] { ++listened; });
    for (int step = 1; step <= 400; ++step) {
        sub_stepped.steps(1);
        stepped.steps(4);
        test::requireSameState(stepped.core, sub_stepped.core, "sub-steps", step);
    }
    // Whole steps are counted, and heard, once each.
    CHECK(sub_stepped.core.stepCount() == 400);
    CHECK(listened == 400);
    CHECK(stepped.core.objectCount() < scene.bodies.size());  // some did fall off
}

TEST_CASE("world knobs: with sub-steps the loop still runs one step per dt of time") {
    // A ball falls from rest for 1 s of frames of dt = 1/64 s: the timer must run 64
    // steps, each of 4 sub-steps of 1/256 s. Symplectic Euler after n = 256 sub-steps of
    // h: v = g n h = 20 px/s and y = g h^2 n (n + 1) / 2 = 20 * 257 / 512 px below the
    // start. Every number here is exact in binary.
    WorldSettings world = demoWorld();
    world.dt = 1.0 / 64;
    world.substeps = 4;
    test::WorldFixture page(world);
    engine::Circle& ball = page.core.add(engine::Circle({100, 100}, 5));
    for (int frame = 0; frame < 64; ++frame) {
        page.window.clock.advanceFrame();
        page.core.runGameLoop();
    }
    test::expectEqual("steps in 64 frames", 64, page.core.stepCount());
    test::expectEqual("the ball's vy after 64 steps of 4 sub-steps, px/s: g for one second", kG, ball.velocity().y);
    test::expectEqual("the ball's y after 64 steps of 4 sub-steps, px: symplectic Euler over 256 sub-steps",
                      100 + kG * 257 / 512, ball.center().y);
}

TEST_CASE("world knobs: with sub-steps a shape is removed after the sub-step that takes it off the canvas") {
    // dt = 1/30 s in 2 sub-steps of 1/60 s, no gravity. Ball A (radius 10) leaves the
    // canvas through its left edge, at 60 px/s: 1 px a sub-step, from x = 0.5 to -0.5.
    // Ball B, 3 px behind it, chases it at 300 px/s: 5 px a sub-step, and after the
    // first sub-step the two overlap by 1 px. A is off the canvas by then and removed
    // at once, so in the second sub-step B meets nothing and keeps its speed. (Were A
    // removed only at the end of the whole step, B would hit it first.)
    WorldSettings world = demoWorld();
    world.remove_out_of_bounds = true;
    world.gravity = {0, 0};
    world.dt = 1.0 / 30;
    world.substeps = 2;
    test::WorldFixture page(world);
    page.core.add(engine::Circle({0.5, 200}, 10)).setVelocity({-60, 0});
    engine::Circle& chaser = page.core.add(engine::Circle({23.5, 200}, 10));
    chaser.setVelocity({-300, 0});
    page.steps(1);
    test::requireEqual("objects after the step: ball A removed after the sub-step that took it off the canvas", 1,
                       page.core.objectCount());
    test::expectEqual("ball B's velocity, px/s: it met nothing in the second sub-step", Vec2{-300, 0},
                      chaser.velocity());
    CHECK_THAT(chaser.center(), test::near(Vec2{13.5, 200}, 1e-12));  // two moves of 5 px
}

// =================================================================================
// Integrators

TEST_CASE("world knobs: symplectic and explicit Euler miss the exact parabola by +-g dt^2 n / 2") {
    // A ball thrown up and to the right, nothing to hit. The exact path has
    // y(t) = y0 + vy0 t + g t^2 / 2. After n steps, with v_k = vy0 + k g dt:
    //   symplectic (moves with the new velocity): y = y0 + dt (v_1 + ... + v_n)
    //     = y0 + vy0 n dt + g dt^2 n (n + 1) / 2, that is g dt^2 n / 2 below the exact;
    //   explicit (moves with the old velocity): y = y0 + dt (v_0 + ... + v_(n-1))
    //     = y0 + vy0 n dt + g dt^2 n (n - 1) / 2, that is g dt^2 n / 2 above it.
    // (+y is down.) Both get x and the velocity exact: no acceleration across, and the
    // same v += g dt.
    const Vec2 start{100, 300};
    const Vec2 throw_velocity{50, -120};
    const double dt = engine::kFrameTime;
    for (const auto integrator : {engine::Integrator::symplectic, engine::Integrator::explicit_euler}) {
        INFO((integrator == engine::Integrator::symplectic ? "symplectic" : "explicit"));
        WorldSettings world = demoWorld();
        world.integrator = integrator;
        test::WorldFixture page(world);
        engine::Circle& ball = page.core.add(engine::Circle(start, 5));
        ball.setVelocity(throw_velocity);
        const double sign = integrator == engine::Integrator::symplectic ? 1.0 : -1.0;
        for (int n = 1; n <= 120; ++n) {
            page.steps(1);
            const double t = n * dt;
            const double exact_y = start.y + throw_velocity.y * t + kG * t * t / 2;
            INFO("step " << n);
            CHECK_THAT(ball.center().y - exact_y, test::near(sign * kG * dt * dt * n / 2, 1e-9));
            CHECK_THAT(ball.center().x, test::near(start.x + throw_velocity.x * t, 1e-9));
            CHECK_THAT(ball.velocity().y, test::near(throw_velocity.y + kG * t, 1e-9));
        }
    }
}

// =================================================================================
// Friction models

TEST_CASE("world knobs: Coulomb friction stops a sliding box after v0^2 / (2 mu g); the book's after v0^2 / (2 g)") {
    // Rotation off, so the box cannot tip and the contact is worked out by hand. The box
    // (mass 1, e = 0) starts touching the floor: step 1 finds no overlap, and gravity
    // sinks it g dt^2 into the floor at g dt. From then on each step's first pass finds
    // it sinking at g dt, and the normal impulse jN = m g dt stops that (the later passes
    // find it at rest, jN = 0). Coulomb's friction impulse is at most mu jN = mu m g dt:
    // the box loses mu g dt of speed a step, a steady deceleration mu g, and a box that
    // slows at a from v0 stops after v0^2 / (2 a). Moving with the new velocity each step
    // (symplectic Euler) it slides that far, give or take v0 dt / 2: the tolerance is one
    // step's travel, v0 dt.
    //
    // The book's model caps its friction impulse at jN, not at mu jN, and (1 + e) mu
    // times the sliding is larger than that at any speed above g dt / mu: so the box
    // slows at g whatever mu, and stops after v0^2 / (2 g). (collision_impulse_test
    // measures that deceleration with rotation on.)
    constexpr double kSpeed = 60.0;
    const double tolerance = kSpeed * engine::kFrameTime;
    for (double mu : {0.25, 0.5, 1.0}) {
        for (const auto model : {engine::FrictionModel::coulomb, engine::FrictionModel::book}) {
            INFO("mu = " << mu << ", " << (model == engine::FrictionModel::book ? "book" : "coulomb"));
            WorldSettings world = demoWorld();
            world.rotation = false;
            world.friction_model = model;
            test::WorldFixture page(world);
            addFloor(page.core);
            const engine::Rectangle& box = addSlidingBox(page.core, kSpeed, mu);
            const double slid = slideUntilStopped(page, box, 1200);
            const double deceleration = model == engine::FrictionModel::coulomb ? mu * kG : kG;
            CHECK_THAT(box.velocity().x, test::near(0, 1e-9));
            CHECK_THAT(slid, test::near(kSpeed * kSpeed / (2 * deceleration), tolerance));
        }
    }
}

// =================================================================================
// Rotation and friction off

TEST_CASE("world knobs: rotation off keeps every angle and angular velocity at exactly 0") {
    // Boxes and discs dropped from different heights onto a tilted slab and a peg, and
    // onto each other: with rotation they tumble (checked, so the scene does test
    // something); without it nothing turns, ever.
    std::vector<BodyDescription> bodies{
        {.shape = ShapeType::Rectangle, .center = {400, 300}, .width = 500, .height = 20, .mass = 0, .angle = 0.3},
        {.shape = ShapeType::Circle, .center = {250, 200}, .radius = 15, .mass = 0},
    };
    test::RandomShapes random(11);
    for (int i = 0; i < 12; ++i) {
        const Vec2 center{random.uniform(200, 600), random.uniform(20, 180)};
        if (i % 2 == 0) {
            bodies.push_back({.shape = ShapeType::Rectangle,
                              .center = center,
                              .width = random.uniform(10, 40),
                              .height = random.uniform(10, 40),
                              .mass = random.uniform(1, 10)});
        } else {
            bodies.push_back({.shape = ShapeType::Circle, .center = center, .radius = random.uniform(5, 20)});
        }
    }
    for (const bool rotation : {true, false}) {
        INFO("rotation " << rotation);
        WorldSettings world = demoWorld();
        world.rotation = rotation;
        test::WorldFixture page(world);
        engine::buildScene(page.core, bodies);
        double most_turned = 0.0;
        for (int step = 0; step < 300; ++step) {
            page.steps(1);
            for (std::size_t i = 2; i < page.core.objectCount(); ++i) {
                const engine::RigidShape& shape = page.core.object(i);
                most_turned = std::max({most_turned, std::abs(shape.angle()), std::abs(shape.angularVelocity())});
            }
        }
        if (rotation) {
            CHECK(most_turned > 0.1);
        } else {
            CHECK(most_turned == 0.0);
        }
        CHECK(page.core.object(0).angle() == 0.3);  // the slab, static, keeps its tilt either way
    }
}

TEST_CASE("world knobs: rotation off does not turn a shape that was given a spin") {
    // No rotation integration at all: the angular velocity a scene gives stays as it is,
    // and the angle with it.
    WorldSettings world = demoWorld();
    world.rotation = false;
    test::WorldFixture page(world);
    engine::Rectangle& box = page.core.add(engine::Rectangle({300, 100}, 30, 20));
    box.setAngularVelocity(2.0);
    page.steps(60);
    test::expectEqual("the box's angle after 60 steps with rotation off, rad", 0.0, box.angle());
    test::expectEqual("the box's angular velocity with rotation off, rad/s: kept, never applied", 2.0,
                      box.angularVelocity());
    CHECK_THAT(box.velocity().y, test::near(kG, 1e-9));  // still falling for 1 s
}

TEST_CASE("world knobs: friction off lets a box slide along a flat floor without losing speed") {
    // Only a tangent impulse could slow the box: gravity is vertical, and the floor's
    // normal impulse is too. With friction on, the same box is slowed (so the test can
    // tell the two apart).
    for (const bool friction : {false, true}) {
        INFO("friction " << friction);
        WorldSettings world = demoWorld();
        world.friction = friction;
        test::WorldFixture page(world);
        addFloor(page.core);
        const engine::Rectangle& box = addSlidingBox(page.core, 60.0, 0.8);
        page.steps(120);
        if (friction) {
            CHECK(box.velocity().x < 30);
            continue;
        }
        CHECK_THAT(box.velocity().x, test::near(60.0, 1e-9));
        CHECK_THAT(box.center().x, test::near(100 + 60.0 * 120 * engine::kFrameTime, 1e-9));
        // On the floor all along, neither sunk into it nor tipped over.
        CHECK_THAT(box.center().y, test::near(kFloorTop - 10, 0.5));
        CHECK_THAT(box.angle(), test::near(0, 0.01));
    }
}

// =================================================================================
// Static bodies

TEST_CASE("world knobs: a static body at rest stays put; one given a velocity moves as in the book") {
    // Gravity does not act on a static body (its 1/m is 0), so at rest it never moves,
    // outline included. One that a user set moving keeps its velocity, unaccelerated:
    // after n steps it has moved n v dt and turned n w dt.
    WorldSettings world = demoWorld();
    test::WorldFixture page(world);
    engine::Rectangle& resting = page.core.add(engine::Rectangle({300.3, 200.7}, 170.1, 20.9, {.mass = 0}));
    resting.rotate(0.7);
    engine::Rectangle& moving = page.core.add(engine::Rectangle({100, 100}, 40, 20, {.mass = 0}));
    const Vec2 velocity{30, -12};
    const double spin = 0.5;
    moving.setVelocity(velocity);
    moving.setAngularVelocity(spin);
    const auto corners = resting.vertices();
    const Vec2 resting_center = resting.center();
    constexpr int kSteps = 60;
    page.steps(kSteps);
    CHECK(resting.center() == resting_center);
    CHECK(resting.vertices() == corners);
    CHECK(resting.angle() == 0.7);
    CHECK(resting.velocity() == Vec2{});
    const double t = kSteps * engine::kFrameTime;
    CHECK_THAT(moving.center().x, test::near(100 + velocity.x * t, 1e-9));
    CHECK_THAT(moving.center().y, test::near(100 + velocity.y * t, 1e-9));
    CHECK_THAT(moving.angle(), test::near(spin * t, 1e-12));
    CHECK(moving.velocity() == velocity);
    CHECK(moving.angularVelocity() == spin);
}

// =================================================================================
// Friction models, in a closed box

TEST_CASE("world knobs: with Coulomb friction a rough box bouncing in a closed box never gains energy") {
    // friction_model "coulomb" takes the sliding after the normal impulse and at most
    // stops it, so every friction impulse takes energy away (rounding: 1e-9 of E0). The
    // book's model gains energy in this very box (extremes_test).
    WorldSettings world = demoWorld();
    world.gravity = {0, 0};
    world.friction_model = engine::FrictionModel::coulomb;
    const double peak = test::roughBoxEnergyPeak(world);
    WARN("rough box, e = 1, coulomb friction: energy at most " << peak << " of the start");
    test::expectAtMost(
        "the rough box's kinetic energy at its peak, as a share of the start: Coulomb friction never makes energy",
        1 + 1e-9, peak);
}

TEST_CASE("world knobs: 1000 sub-steps of 1000 passes at dt 1e-5 are refused as a run without end (issue 15)") {
    // One frame of 1000/60 ms is 1,667 steps of 1e-5 s, each 1000 sub-steps of 1000
    // passes: 1.7e9 passes over the pairs of even a few shapes, for every frame.
    const test::ScratchFolder folder("knobs-budget");
    folder.write("scene.json", R"({"world": {"substeps": 1000, "relaxation_iterations": 1000, "dt": 1e-5},
        "bodies": [{"shape": "circle", "center": [100, 100], "radius": 10},
                   {"shape": "circle", "center": [130, 100], "radius": 10},
                   {"shape": "circle", "center": [160, 100], "radius": 10}]})");
    const test::ProgramRun run =
        test::runStageProgram(folder, "--frames 1 --keys '' --scene " + test::quoted(folder.path / "scene.json") +
                                          " --out " + test::quoted(folder.path / "out"));
    test::expectEqual("the program's exit status for a run over its budget: 2, refused", 2, run.status);
    // 1,667 steps x 1000 sub-steps x (1000 x 3 pairs + 3 moves) = 5.006e9 pair tests.
    CHECK(run.error_text ==
          "the run is too long: 1 frame of up to 3 shapes may cost 5.01e+09 pair tests, more than the 5e+09 a run may "
          "(fewer --frames, key presses, shapes, passes or sub-steps, or a longer dt)\n");
    CHECK(folder.files() == std::vector<std::string>{"scene.json", "stderr.txt", "stdout.txt"});
}

}  // namespace world_knobs_test
