// Stage 5.6: continuous collision (continuous.h). The sweep's time of impact for each
// pair of shape kinds against a time worked out by hand; the fast-shape rule at its
// edge; shots through a 2 px wall at 20,000 px/s, on both solvers, none through (and
// most through with it off, so the test can fail); a bullet against a thin plank that
// is free to move. With "continuous": false the stage is 5.5 bit for bit (the identity
// feature test); with it on, a world with no fast shape moves exactly as with it off.
// 5.5's own tests run on this stage too, continuous on (s5_6.s5_5_stage).
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <numbers>
#include <optional>
#include <string>

#include "circle.h"
#include "continuous.h"
#include "expect.h"
#include "near.h"
#include "page_world.h"
#include "random.h"
#include "rectangle.h"
#include "same_state.h"
#include "scene_io.h"
#include "scratch_folder.h"
#include "stage_program.h"
#include "thin_shots.h"
#include "world_fixture.h"
#include "world_from_scene.h"

namespace s5_6_test {

using engine::Vec2;
using engine::WorldSettings;
namespace fs = std::filesystem;

namespace {

constexpr engine::SolverKind kBothSolvers[] = {engine::SolverKind::book, engine::SolverKind::sequential_impulse};
constexpr double kDepth = engine::kImpactDepth;  // 0.5 px: every shape below is large enough for the whole of it

// The motion of `shape` as it stands by `offset` and `turn`.
engine::StepMotion motionOf(const engine::RigidShape& shape, Vec2 offset, double turn = 0.0) {
    return {.start = engine::outlineOf(shape), .offset = offset, .turn = turn};
}

std::optional<double> impactOf(const engine::RigidShape& shape, Vec2 offset, const engine::RigidShape& obstacle,
                               double turn = 0.0) {
    return engine::timeOfImpact(motionOf(shape, offset, turn), engine::outlineOf(obstacle), kDepth);
}

// The world of the shots: no gravity, nothing removed at the canvas's edge (a shot
// bounced back at thousands of px/s leaves it within a step or two).
WorldSettings shootingWorld(engine::SolverKind solver, bool continuous) {
    WorldSettings world = engine::kBookWorld;
    world.gravity = {0, 0};
    world.remove_out_of_bounds = false;
    world.solver = solver;
    world.continuous = continuous;
    return world;
}

constexpr double kShotSpeed = 20000.0;  // px/s: 333 px a step
constexpr double kWallX = 400.0;        // the centre of the 2 px wall
constexpr double kWallThickness = 2.0;

double uniform(browser::Random& random, double low, double high) { return low + (high - low) * random.next(); }

// One shot from x = 100 at the wall, a circle or a rectangle of random size, turned and
// spinning at random, flying within 45 degrees of straight at it. True when, ten steps
// later, its centre is past the wall's middle.
bool shotGoesThrough(engine::SolverKind solver, bool continuous, browser::Random& random, bool circle) {
    test::WorldFixture page(shootingWorld(solver, continuous));
    page.core.add(engine::Rectangle({kWallX, 225}, kWallThickness, 8000, {.mass = 0}));
    engine::RigidShape& shot =
        circle ? static_cast<engine::RigidShape&>(page.core.add(engine::Circle({100, 225}, uniform(random, 4, 20))))
               : page.core.add(engine::Rectangle({100, 225}, uniform(random, 4, 40), uniform(random, 4, 40)));
    shot.rotate(uniform(random, -std::numbers::pi, std::numbers::pi));
    const double heading = uniform(random, -std::numbers::pi / 4, std::numbers::pi / 4);
    shot.setVelocity(Vec2{std::cos(heading), std::sin(heading)} * kShotSpeed);
    shot.setAngularVelocity(uniform(random, -30, 30));
    page.steps(10);
    return shot.center().x > kWallX;
}

int shotsThrough(engine::SolverKind solver, bool continuous, int shots) {
    browser::Random random(56);
    int through = 0;
    for (int i = 0; i < shots; ++i) through += shotGoesThrough(solver, continuous, random, i % 2 == 0) ? 1 : 0;
    return through;
}

}  // namespace

TEST_CASE("s5_6: continuous collision is on unless the scene turns it off; a body's bullet flag is read") {
    CHECK(engine::kBookWorld.continuous);
    CHECK_FALSE(test::worldFromScene(R"({"continuous": false})").continuous);
    const test::ScratchFolder folder("s5_6-bullet");
    const engine::Scene scene = engine::loadScene(folder.write("scene.json", R"({"bodies": [
        {"shape": "circle", "center": [10, 10], "radius": 2, "bullet": true},
        {"shape": "circle", "center": [30, 10], "radius": 2}]})"));
    test::WorldFixture page(scene.world);
    engine::buildScene(page.core, scene.bodies);
    CHECK(page.core.object(0).isBullet());
    CHECK_FALSE(page.core.object(1).isBullet());
}

// =================================================================================
// The sweep, pair kind by pair kind. Each shot flies straight and does not turn, so
// conservative advancement closes the gap in one advance and lands on the time by hand:
// the moment the shape is kDepth (0.5 px) into the obstacle.

TEST_CASE("s5_6: time of impact, circle against circle: touching at centres 15 px apart, then 0.5 px deeper") {
    const engine::Circle shot({0, 0}, 10);
    const engine::Circle obstacle({60, 0}, 5);
    // 10 + 5 = 15 px apart when the shot's centre is at x = 45: t = 45 / 100; 0.5 px on.
    CHECK_THAT(*impactOf(shot, {100, 0}, obstacle), test::near(45.5 / 100, 1e-12));
}

TEST_CASE("s5_6: time of impact, circle against rectangle: its rim meets the wall's face") {
    const engine::Circle shot({0, 0}, 10);
    const engine::Rectangle wall({0, 100}, 200, 2);  // its top face at y = 99
    // The rim at y + 10 reaches 99 at y = 89: t = 89 / 200; 0.5 px on.
    CHECK_THAT(*impactOf(shot, {0, 200}, wall), test::near(89.5 / 200, 1e-12));
}

TEST_CASE("s5_6: time of impact, rectangle against rectangle: face to face, and corner first") {
    const engine::Rectangle wall({50, 0}, 2, 200);  // its left face at x = 49
    SECTION("face to face") {
        const engine::Rectangle shot({0, 0}, 20, 20);
        // The right face at x + 10 reaches 49 at x = 39: t = 39 / 100; 0.5 px on.
        CHECK_THAT(*impactOf(shot, {100, 0}, wall), test::near(39.5 / 100, 1e-12));
    }
    SECTION("corner first") {
        engine::Rectangle shot({0, 0}, 20, 20);
        shot.rotate(std::numbers::pi / 4);
        // The corner is 10 sqrt 2 ahead of the centre. Pulled in by 0.5 px on both sides,
        // it is 0.5 sqrt 2 less ahead: the stopped corner is 0.5 sqrt 2 px into the wall.
        const double corner_ahead = (10 - 0.5) * std::numbers::sqrt2;
        CHECK_THAT(*impactOf(shot, {100, 0}, wall), test::near((49 - corner_ahead) / 100, 1e-12));
    }
}

TEST_CASE("s5_6: time of impact, rectangle against circle: its face meets the rim") {
    const engine::Rectangle shot({0, 0}, 20, 20);
    const engine::Circle obstacle({50, 0}, 5);
    // The right face at x + 10 reaches the rim at 45 when x = 35: t = 35 / 100; 0.5 px on.
    CHECK_THAT(*impactOf(shot, {100, 0}, obstacle), test::near(35.5 / 100, 1e-12));
}

TEST_CASE("s5_6: time of impact: nothing when the shot misses or stops short, 0 when it already touches") {
    const engine::Rectangle wall({50, 0}, 2, 200);
    const engine::Circle shot({0, 0}, 10);
    CHECK_FALSE(impactOf(shot, {0, 100}, wall));  // flies along the wall, 39 px from it
    CHECK_FALSE(impactOf(shot, {38, 0}, wall));   // its rim stops 1 px short of x = 49
    const engine::Circle touching({40, 0}, 10);   // 1 px into the wall already: at once
    CHECK(impactOf(touching, {100, 0}, wall) == 0.0);
}

TEST_CASE("s5_6: time of impact of a spinning rectangle: stopped in the wall, by no more than its corner's depth") {
    // Grazing and turning, the advances are many and short; where they end, the outline
    // is in the wall (the narrow phase finds it) by at most 0.5 sqrt 2 px (a corner).
    browser::Random random(3);
    for (int shot = 0; shot < 200; ++shot) {
        engine::Rectangle rectangle({0, 0}, uniform(random, 4, 40), uniform(random, 4, 40));
        rectangle.rotate(uniform(random, -3, 3));
        const engine::Rectangle wall({300, 0}, 2, 2000);
        const double turn = uniform(random, -2, 2);
        const Vec2 offset{500, uniform(random, -300, 300)};
        const std::optional<double> t = impactOf(rectangle, offset, wall, turn);
        INFO("shot " << shot);
        test::requireEqual("a time of impact found for the turning rectangle swept at the 2 px wall", true,
                           t.has_value());
        rectangle.move(offset * *t);
        rectangle.rotate(turn * *t);
        const std::optional<engine::CollisionInfo> info = rectangle.collisionTest(wall);
        test::requireEqual("a collision of the rectangle and the wall at the time of impact", true, info.has_value());
        test::expectAtMost("the depth at the time of impact, px: within the sweep's target, times sqrt 2",
                           kDepth * std::numbers::sqrt2 + 1e-9, info->depth());
    }
}

// =================================================================================
// The fast-shape rule: more than half the smallest extent in a step.

TEST_CASE("s5_6: a shape is fast when its farthest point moves more than half its smallest extent") {
    const engine::Circle ball({0, 0}, 10);  // extent 10: fast beyond 5 px
    CHECK_FALSE(engine::isFast(ball, {3, 4}, 0.0));
    CHECK(engine::isFast(ball, {3, 4.01}, 0.0));
    CHECK_FALSE(engine::isFast(ball, {0, 0}, 100.0));  // a circle's spin moves no outline

    const engine::Rectangle plank({0, 0}, 40, 10);  // extent 5: fast beyond 2.5 px
    test::expectEqual("the 40 x 10 plank's smallest extent, px: half its thickness", 5.0,
                      engine::smallestExtent(plank));
    test::expectEqual("fast (swept) at 2.5 px a step: half its extent, not more", false,
                      engine::isFast(plank, {2.5, 0}, 0.0));
    test::expectEqual("fast (swept) at 2.51 px a step", true, engine::isFast(plank, {2.51, 0}, 0.0));
    // Its corners are sqrt(20^2 + 5^2) = 20.6 px out: a turn of 0.12 rad moves them 2.47
    // px, of 0.125 rad 2.58 px.
    test::expectEqual("fast (swept) turning 0.12 rad a step: its corners move 2.47 px", false,
                      engine::isFast(plank, {0, 0}, 0.12));
    test::expectEqual("fast (swept) turning 0.125 rad a step: its corners move 2.58 px", true,
                      engine::isFast(plank, {0, 0}, 0.125));
}

// =================================================================================
// The world: shots, the plank, the identity.

TEST_CASE("s5_6: 0 of 400 shots at 20,000 px/s through a 2 px wall, circles and rectangles, both solvers") {
    for (engine::SolverKind solver : kBothSolvers) {
        INFO("solver " << static_cast<int>(solver));
        CHECK(shotsThrough(solver, true, 400) == 0);
        // Off, the same shots mostly tunnel: the wall does stop nothing by itself.
        CHECK(shotsThrough(solver, false, 400) > 300);
    }
}

namespace {

// A ball of radius 3 to 10 px shot at 20,000 px/s from 300 px away, within 57 degrees
// of straight, at a 2 px plank of mass 1 (the ball's mass too) that slides along its
// length at up to 600 px/s. The world does not turn (rotation off): a plank spun by an
// off-centre hit would swing past balls it never let through. True when, at the end of
// any of ten steps, the ball is past the plank and not beyond either of its ends.
bool shotThroughPlank(browser::Random& random, bool bullet) {
    WorldSettings world = shootingWorld(engine::SolverKind::book, true);
    world.rotation = false;
    test::WorldFixture page(world);
    const Vec2 middle{kWallX, 225};
    engine::Rectangle& plank = page.core.add(engine::Rectangle(middle, kWallThickness, 400));
    plank.setVelocity({0, uniform(random, -600, 600)});
    const double angle = uniform(random, -1, 1);
    const Vec2 toward{std::cos(angle), std::sin(angle)};
    engine::Circle& ball = page.core.add(engine::Circle(middle - toward * 300, uniform(random, 3, 10)));
    ball.setBullet(bullet);
    ball.setVelocity(toward * kShotSpeed);
    for (int step = 0; step < 10; ++step) {
        page.steps(1);
        const Vec2 from_middle = ball.center() - plank.center();
        if (from_middle.x > 0 && std::abs(from_middle.y) < plank.height() / 2) return true;
    }
    return false;
}

}  // namespace

TEST_CASE("s5_6: a bullet does not pass a 2 px plank that is free to move; a fast shape that is no bullet does") {
    browser::Random bullets(7), shapes(7);
    int through_as_bullet = 0, through_as_shape = 0;
    for (int shot = 0; shot < 200; ++shot) {
        through_as_bullet += shotThroughPlank(bullets, true) ? 1 : 0;
        through_as_shape += shotThroughPlank(shapes, false) ? 1 : 0;
    }
    test::expectEqual("shots of 200 through the 2 px plank as bullets", 0, through_as_bullet);
    test::expectAbove("shots of 200 through the plank as shapes that are no bullets", 150, through_as_shape);
}

// =================================================================================
// Thin and spinning shapes (issue 36): the sweep's bounds come from the shape's own
// extent, its reach (a plate's half diagonal) and its thinness (half its shorter side).

TEST_CASE("s5_6: issue 36's spinning plate does not pass the 2 px wall on the sequential impulse solver") {
    // A 10 x 1 px plate at 0.67 rad, (999, 46) px/s, 100 rad/s, restitution 1, at a 2 x
    // 450 px static wall whose middle is at x = 799. The solver left it 0.26 px deep in
    // the wall, over half its thinness (0.5 px), and its spin then swung it through.
    WorldSettings world = engine::kBookWorld;
    world.solver = engine::SolverKind::sequential_impulse;
    world.remove_out_of_bounds = false;
    test::WorldFixture page(world);
    page.core.add(engine::Rectangle({799, 225}, 2, 450, {.mass = 0}));
    engine::Rectangle& plate = page.core.add(engine::Rectangle({414.4, 268.8}, 10, 1, {.restitution = 1}));
    plate.rotate(0.67);
    plate.setVelocity({999, 46});
    plate.setAngularVelocity(100);
    for (int step = 1; step <= 60; ++step) {
        page.steps(1);
        INFO("step " << step);
        REQUIRE(plate.center().x < 799);
    }
}

TEST_CASE("s5_6: a plate crossing a thin wall like an X overlaps it, though no corner of either is in the other") {
    // A 10 x 0.04 plate turned upright, crossing a 0.01 px wall near its end: its corners
    // are 0.07 px either side of the wall, the wall's corners 500 px away.
    engine::Rectangle plate({399.98, 225}, 0.04, 10);
    plate.rotate(0.01);
    const engine::Rectangle wall({400, 0}, 0.01, 1000);
    CHECK(engine::gap(engine::outlineOf(plate), engine::outlineOf(wall)) == 0.0);
    // Moved 1 px to the left, it is clear by 1 px less the corner's 0.07 and the wall's half.
    plate.move({-1, 0});
    const double corner_x = 0.02 * std::cos(0.01) + 5 * std::sin(0.01);
    CHECK_THAT(engine::gap(engine::outlineOf(plate), engine::outlineOf(wall)),
               test::near(400 - 0.005 - (398.98 + corner_x), 1e-9));
}

TEST_CASE(
    "s5_6: a plate deeper than three quarters of its thinness stops a quarter of its thinness short of the wall") {
    // A 0.04 x 10 px plate (thinness 0.02) turned 0.01 rad, its centre 0.05 px before the
    // face at x = 399.995: its corner is 0.07 - 0.05 = 0.02 px in, and the outline pulled
    // in by 0.015 px (three quarters) still 0.0049 px in. Flying 1 px a step straight at
    // the wall, its centre would enter at t = 0.05; it stops 0.005 px (a quarter) before.
    engine::Rectangle plate({399.945, 225}, 0.04, 10);
    plate.rotate(0.01);
    const engine::Rectangle wall({400, 0}, 0.01, 1000);
    const double extent = engine::smallestExtent(plate);
    REQUIRE(extent == 0.02);
    REQUIRE(engine::gap(engine::shrunk(engine::outlineOf(plate), 0.75 * extent), engine::outlineOf(wall)) == 0.0);
    const std::optional<double> t = engine::impactAgainst(motionOf(plate, {1, 0}), engine::outlineOf(wall), extent);
    REQUIRE(t);
    CHECK_THAT(*t, test::near(0.05 - 0.005, 1e-12));
    // Flying along the wall instead, its centre never enters: nothing stops it.
    CHECK_FALSE(engine::impactAgainst(motionOf(plate, {0, 1}), engine::outlineOf(wall), extent));
}

TEST_CASE(
    "s5_6: none of a slice of the thin-shape grid passes: plates, needles, spinning rectangles, walls to 0.01 px") {
    // Every ninth shot of the grid the bench runs whole (bench/thin_shots_study.cpp):
    // shapes of 10 x 1, 40 x 2, 20 x 0.05, 5 x 0.01, 8 x 4 and 6 x 6 px, eight turns,
    // spins of 0 to 10,000 rad/s, speeds of 300 to 1,000,000 px/s, walls of 2, 0.1 and
    // 0.01 px, three headings, two restitutions, both solvers.
    // Under the sanitizers, which look for memory errors rather than counts, every 27th.
    const std::vector<thin_shots::Shot> grid = thin_shots::grid();
    const std::size_t every = test::underAddressSanitizer ? 27 : 9;
    int tried = 0, through = 0, held = 0;
    for (std::size_t i = 0; i < grid.size(); i += every) {
        const thin_shots::Outcome outcome = thin_shots::shoot(grid[i]);
        ++tried;
        through += outcome.through ? 1 : 0;
        held += outcome.held ? 1 : 0;
        if (outcome.through) {
            const thin_shots::Shot& s = grid[i];
            UNSCOPED_INFO("through: " << s.width << " x " << s.height << " px, wall " << s.wall << " px, angle "
                                      << s.angle << ", spin " << s.spin << ", speed " << s.speed << ", heading "
                                      << s.heading << ", e " << s.restitution << ", solver "
                                      << static_cast<int>(s.solver));
        }
    }
    CHECK(tried == static_cast<int>((grid.size() + every - 1) / every));
    CHECK(grid.size() == 27648);
    CHECK(through == 0);
    // The sweep may keep a shape pressed into the wall where it is (the README's
    // envelope); in this slice that never lasts ten steps.
    CHECK(held == 0);
}

TEST_CASE("s5_6: none of 3,000 random shots passes a thin wall: sizes from 0.01 px, spins to 10,000 rad/s") {
    int through = 0, held = 0;
    for (const thin_shots::Shot& shot : thin_shots::randomShots(test::underAddressSanitizer ? 1000 : 3000, 36)) {
        const thin_shots::Outcome outcome = thin_shots::shoot(shot);
        through += outcome.through ? 1 : 0;
        held += outcome.held ? 1 : 0;
    }
    CHECK(through == 0);
    CHECK(held <= 3);  // 0.1 %; the bench counts 200,000 (README)
}

TEST_CASE("s5_6: with no fast shape, continuous on moves every shape exactly as with it off") {
    for (engine::SolverKind solver : kBothSolvers) {
        for (const char* name : {"book_demo.json", "pyramid.json", "rain.json", "heavy_on_light.json"}) {
            INFO(name << ", solver " << static_cast<int>(solver));
            engine::Scene scene = engine::loadScene(fs::path(SCENE_LIBRARY_DIR) / name);
            scene.world.solver = solver;
            WorldSettings off_world = scene.world;
            off_world.continuous = false;
            test::WorldFixture on(scene.world), off(off_world);
            engine::buildScene(on.core, scene.bodies);
            engine::buildScene(off.core, scene.bodies);
            int first_sweep = 0;
            for (int step = 1; step <= 600 && first_sweep == 0; ++step) {
                on.steps(1);
                off.steps(1);
                if (on.core.continuous().sweeps().empty()) {
                    test::requireSameState(off.core, on.core, name, step);
                } else {
                    first_sweep = step;
                }
            }
            // The rain's small shapes fall fast enough in the end (from 2 s on); the others'
            // shapes never move half their size in a step.
            if (std::string(name) == "rain.json") {
                CHECK(first_sweep > 2 * 60);
            } else {
                CHECK(first_sweep == 0);
            }
        }
    }
}

TEST_CASE("s5_6: the rest of the impact's step is lost: the bounce lags the analytic one by (1 - t) v dt") {
    // A ball of radius 10 at x = 100 flies at 6,000 px/s (100 px a step) at a wall whose
    // face is at x = 400; e = 1, no friction. Its rim touches the face when its centre
    // is at 390, 2.9 steps in: t = 0.9 of step 3. The analytic ball is back at 390 - (100
    // n - 290) after n steps. The swept one stops at the touch (0.5 px deeper), loses
    // the last 0.1 of step 3, is pushed out and bounced in step 4, and from then on runs
    // (1 - 0.9) x 100 = 10 px behind, at the right speed.
    WorldSettings world = shootingWorld(engine::SolverKind::book, true);
    test::WorldFixture page(world);
    page.core.add(engine::Rectangle({401, 225}, 2, 400, {.mass = 0, .friction = 0, .restitution = 1}));
    engine::Circle& ball = page.core.add(engine::Circle({100, 225}, 10, {.mass = 1, .friction = 0, .restitution = 1}));
    ball.setVelocity({6000, 0});
    page.steps(3);
    CHECK_THAT(ball.center().x, test::near(390.5, 1e-9));  // stopped at its time of impact
    page.steps(3);
    const double analytic = 390 - (100 * 6 - 290);
    CHECK_THAT(ball.center().x, test::near(analytic + 10, 1e-6));
    CHECK_THAT(ball.velocity().x, test::near(-6000, 1e-9));
}

TEST_CASE("s5_6: P turns continuous collision off and on live; the section beyond the book says so") {
    test::WorldFixture page(shootingWorld(engine::SolverKind::book, true));
    // The setting and its key are in the section beyond the book, under the page
    // (Document::beyond_echo); the book's lines in the panel never carry them.
    const auto frame = [&page] {
        page.window.clock.advanceFrame();
        page.core.runGameLoop();
        const browser::Document& document = page.window.document;
        CHECK(document.beyond_echo.find("  P: Continuous [On/Off]\n") != std::string::npos);
        CHECK(document.ui_echo.find("Continuous") == std::string::npos);
        return document.beyond_echo;
    };
    CHECK(frame().find("  Continuous: true\n") != std::string::npos);
    page.press(browser::Key::P);
    CHECK_FALSE(page.core.settings().continuous);
    CHECK(frame().find("  Continuous: false\n") != std::string::npos);
    page.press(browser::Key::P);
    CHECK(page.core.settings().continuous);
    CHECK(frame().find("  Continuous: true\n") != std::string::npos);
}

}  // namespace s5_6_test

namespace s5_6_test {

namespace {

// Issue 36's scene: 2,500 bullets, plates of 5 x 1 px at 1e6 px/s spinning at 1e4 rad/s,
// in rows. Every sweep of every bullet against every shape measures gaps again and
// again: about 5.7 s of CPU a step, and the budget, which counted no sweep, let
// --frames 1590 through: some 2.5 hours.
std::string spinningBullets(bool continuous) {
    std::string text = R"({"world": {"continuous": )";
    text += continuous ? "true" : "false";
    text += R"(}, "bodies": [)";
    for (int i = 0; i < 2500; ++i) {
        text += i == 0 ? "" : ",";
        text += R"({"shape": "rectangle", "width": 5, "height": 1, "velocity": [1e6, 0], "angular_velocity": 1e4, )";
        text += R"("bullet": true, "center": [)" + std::to_string(20 + (i % 50) * 15) + ", " +
                std::to_string(20 + (i / 50) * 8) + "]}";
    }
    return text + "]}";
}

browser::WorldCost costOf(const engine::Scene& scene) {
    test::WorldFixture page(scene.world);
    engine::buildScene(page.core, scene.bodies);
    return engine::worldCost(page.core, browser::KeyScript());
}

}  // namespace

TEST_CASE("s5_6: the run's budget counts the sweeps: 2,500 spinning bullets are refused up front (issue 36)") {
    const test::ScratchFolder folder("s5_6-sweep-budget");
    const fs::path scene = folder.write("bullets.json", spinningBullets(true));
    test::checkRefused(
        folder,
        "--frames 3 --every 0 --no-gif --scene " + test::quoted(scene) + " --out " + test::quoted(folder.path / "out"),
        "the run is too long: 3 frames of up to 2500 shapes may cost ");

    // What the sweeps add to a step: each of the 2,500 bullets swept against each of the
    // 2,500 shapes, every one of those up to kMaxAdvances gaps measured, each dearer than a
    // pair test.
    const browser::WorldCost on = costOf(engine::readScene(spinningBullets(true), "on"));
    const browser::WorldCost off = costOf(engine::readScene(spinningBullets(false), "off"));
    CHECK(on.step_work - off.step_work >= 2500.0 * 2500.0 * engine::kMaxAdvances);
    // With continuous collision off the same 3 frames fit the budget: 0.04 s a step.
    browser::Options three;
    three.frames = 3;
    three.frame_ms = 1000.0 / 60.0;
    CHECK(browser::work_bound(off, three) <= browser::kMaxWork);
    CHECK(browser::work_bound(on, three) > browser::kMaxWork);
}

}  // namespace s5_6_test
