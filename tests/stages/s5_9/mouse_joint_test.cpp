// Stage 5.9's mouse joint (mouse_joint.h, README.md "The mouse"): a press grabs a shape
// that forces move and no other, the pull of one step is an implicit damped spring's,
// capped in proportion to the mass, the grabbed point closes in on the pointer in both
// solvers, and a scripted drag replays to the same dump, byte for byte.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdlib>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "rectangle.h"
#include "scratch_folder.h"
#include "stage_program.h"
#include "world_fixture.h"

namespace s5_9_mouse_test {

using engine::MouseJoint;
using engine::SolverKind;
using engine::Vec2;

namespace {

constexpr int kStepsPerSecond = 60;

engine::WorldSettings world(SolverKind solver, Vec2 gravity = engine::kGravity) {
    engine::WorldSettings settings = test::world(true, gravity);
    settings.solver = solver;
    return settings;
}

// A floor (object 0), a 40 x 40 box of mass 2 resting on it about x = 300 (object 1), a
// kinematic plank turning in the air (object 2).
struct Room {
    explicit Room(SolverKind solver) : page(world(solver)) {
        page.core.add(engine::Rectangle({400, 440}, 800, 20, {.mass = 0}));
        page.core.add(engine::Rectangle({300, 410}, 40, 40, {.mass = 2}));
        page.core.add(engine::Rectangle({600, 200}, 100, 10)).makeKinematic();
        page.core.object(2).setAngularVelocity(1.0);
    }
    double pull() const {
        const engine::MouseJoint& mouse = page.core.mouse();
        return mouse.grabbedPoint(page.core.object(1)).distance(mouse.target());
    }
    test::WorldFixture page;
};

}  // namespace

TEST_CASE("s5_9: a press grabs a shape that forces move, and never a static or kinematic one", "[mouse]") {
    Room room(SolverKind::book);
    engine::Core& core = room.page.core;
    CHECK_FALSE(core.grab({100, 435}));  // the floor: static
    CHECK_FALSE(core.mouse().holding());
    CHECK_FALSE(core.grab({600, 200}));  // the turning plank: kinematic
    CHECK_FALSE(core.grab({300, 300}));  // nothing there
    CHECK_FALSE(core.mouse().holding());
    REQUIRE(core.grab({310, 400}));  // the box, 10 px right of and above its centre
    CHECK(core.mouse().body() == core.object(1).id());
    CHECK(core.mouse().grabbedPoint(core.object(1)) == Vec2{310, 400});
    core.letGo();
    CHECK_FALSE(core.mouse().holding());
}

TEST_CASE("s5_9: one step's pull is an implicit damped spring's, capped at 20000 px/s^2", "[mouse]") {
    // A free box of mass 2 in no gravity, held at its centre (no arm, no turn), the
    // pointer x px to its right. The soft constraint is the spring m w^2, damper
    // 2 m zeta w, integrated by implicit Euler: m (v' - v) = -h (k (x + h v') + c v'),
    // so from rest v' = h w^2 x / (1 + 2 zeta w h + w^2 h^2), mass aside: for w = 10 pi,
    // zeta = 0.7, h = 1/60, v' = 16.4493 x / 2.00720 = 8.19516 x px/s.
    const double h = 1.0 / kStepsPerSecond;
    const double w = 2 * std::numbers::pi * MouseJoint::kHertz;
    const double per_px = h * w * w / (1 + 2 * MouseJoint::kDampingRatio * w * h + w * w * h * h);
    CHECK(per_px == Approx(8.19516).epsilon(1e-5));
    for (const SolverKind solver : {SolverKind::book, SolverKind::sequential_impulse}) {
        for (const double x : {1.0, 3.0}) {
            test::WorldFixture page(world(solver, {}));
            page.core.add(engine::Rectangle({200, 200}, 40, 40, {.mass = 2}));
            REQUIRE(page.core.grab({200, 200}));
            page.core.dragTo({200 + x, 200});
            page.steps(1);
            CHECK(page.core.object(0).velocity().x == Approx(per_px * x).epsilon(1e-12));
            CHECK(page.core.object(0).velocity().y == 0.0);
            CHECK(page.core.object(0).angularVelocity() == 0.0);
        }
        // 1000 px away the spring would ask for 8195 px/s in one step; the cap allows the
        // mass times 20000 px/s^2 for 1/60 s: 333 px/s, whatever the mass.
        test::WorldFixture page(world(solver, {}));
        page.core.add(engine::Rectangle({200, 200}, 40, 40, {.mass = 2}));
        REQUIRE(page.core.grab({200, 200}));
        page.core.dragTo({1200, 200});
        page.steps(1);
        CHECK(page.core.object(0).velocity().x == Approx(MouseJoint::kMaxPullAcceleration * h).epsilon(1e-12));
    }
}

// A box spinning at 2 rad/s in no gravity, held at its centre with the pointer there: the
// pull has no arm and no error, so only the spin's damping acts, dividing the spin by
// 1 + h 1.2 = 1.02 each step: after a second 2 / 1.02^60 = 0.6096 rad/s. Let go, it spins
// on undamped; never grabbed, it keeps its 2 rad/s.
TEST_CASE("s5_9: a held shape's spin is damped by 1 + h 1.2 a step, and only while held", "[mouse]") {
    const double h = 1.0 / kStepsPerSecond;
    const double after_second = 2.0 / std::pow(1.0 + h * MouseJoint::kSpinDamping, kStepsPerSecond);
    CHECK(after_second == Approx(0.6096).epsilon(1e-4));
    for (const SolverKind solver : {SolverKind::book, SolverKind::sequential_impulse}) {
        test::WorldFixture page(world(solver, {}));
        engine::RigidShape& box = page.core.add(engine::Rectangle({200, 200}, 40, 40, {.mass = 2}));
        box.setAngularVelocity(2.0);
        REQUIRE(page.core.grab({200, 200}));
        page.steps(kStepsPerSecond);
        CHECK(box.angularVelocity() == Approx(after_second).epsilon(1e-12));
        CHECK(box.center().distance({200, 200}) < 1e-9);
        page.core.letGo();
        page.steps(kStepsPerSecond);
        CHECK(box.angularVelocity() == Approx(after_second).epsilon(1e-12));

        test::WorldFixture free(world(solver, {}));
        engine::RigidShape& spinner = free.core.add(engine::Rectangle({200, 200}, 40, 40, {.mass = 2}));
        spinner.setAngularVelocity(2.0);
        free.steps(kStepsPerSecond);
        CHECK(spinner.angularVelocity() == 2.0);
    }
}

// On the sequential impulses the pull is solved in the iterations with the contacts, so
// it sees what it pulls against. A box of mass 2 held at its centre, with a second box of
// mass 2 resting on it (overlapping by 0.1 px, under the 0.15 px slop: no push apart), in
// no gravity; the pointer 3 px above the grabbed point. The spring is the held box's,
// k = m w^2 and c = 2 m zeta w, but it now moves 2 m: the implicit step gives both boxes
// v = h k C / (2 m + h c + h^2 k) = h w^2 C / (2 + 2 zeta w h + w^2 h^2) = 16.449 x 3 /
// 3.0072 = 16.410 px/s up. Pulled first and alone, as the book's passes pull, the held
// box would get h w^2 C / 2.0072 = 24.59 px/s and share it with the other: 12.29 px/s.
TEST_CASE("s5_9: on the sequential impulses the pull is solved with the contacts: a box lifts the one on it",
          "[mouse]") {
    const double h = 1.0 / kStepsPerSecond;
    const double w = 2 * std::numbers::pi * MouseJoint::kHertz;
    const double zeta = MouseJoint::kDampingRatio;
    const double together = h * w * w * 3.0 / (2.0 + 2.0 * zeta * w * h + w * w * h * h);
    const double alone_then_shared = h * w * w * 3.0 / (1.0 + 2.0 * zeta * w * h + w * w * h * h) / 2.0;
    CHECK(together == Approx(16.410).epsilon(1e-4));
    CHECK(alone_then_shared == Approx(12.293).epsilon(1e-4));
    const auto lift = [](SolverKind solver) {
        test::WorldFixture page(world(solver, {}));
        const engine::PhysicalAttributes box{.mass = 2, .restitution = 0};
        engine::RigidShape& held = page.core.add(engine::Rectangle({200, 200}, 40, 40, box));
        engine::RigidShape& load = page.core.add(engine::Rectangle({200, 160.1}, 40, 40, box));
        REQUIRE(page.core.grab({200, 200}));
        page.core.dragTo({200, 197});
        page.steps(1);
        return std::pair{held.velocity(), load.velocity()};
    };
    const auto [held, load] = lift(SolverKind::sequential_impulse);
    CHECK(-held.y == Approx(together).epsilon(0.01));
    CHECK(-load.y == Approx(together).epsilon(0.01));
    CHECK(held.x == Approx(0.0).margin(1e-9));
}

TEST_CASE("s5_9: a dragged box follows the pointer, in both solvers", "[mouse]") {
    for (const SolverKind solver : {SolverKind::book, SolverKind::sequential_impulse}) {
        INFO("solver " << (solver == SolverKind::book ? "book" : "sequential_impulse"));
        Room room(solver);
        engine::Core& core = room.page.core;
        REQUIRE(core.grab({310, 400}));
        core.dragTo({360, 250});  // 158 px up and to the right
        const double start = room.pull();
        CHECK(start == Approx(std::hypot(50.0, 150.0)));
        double before = start;
        // The grabbed point closes in on the pointer, each tenth of a second nearer, and
        // then hangs there, swinging less and less.
        for (int tenth = 0; tenth < 3; ++tenth) {
            room.page.steps(kStepsPerSecond / 10);
            INFO("after " << tenth + 1 << " tenths of a second");
            CHECK(room.pull() < before);
            before = room.pull();
        }
        // Held 10 px off its centre, the box swings below the pointer as a pendulum, its
        // spin damped (kSpinDamping), and the spring gives a little to the swing: within
        // 2 % of the 158 px it started from.
        room.page.steps(kStepsPerSecond);
        CHECK(room.pull() < 0.02 * start);
        CHECK(core.object(1).center().distance({360, 250}) < 25.0);  // hanging from its grabbed point
        // Let go, nothing pulls it any more: one step adds gravity's g dt and no more.
        core.letGo();
        CHECK_FALSE(core.mouse().holding());
        const double falling = core.object(1).velocity().y;
        room.page.steps(1);
        CHECK(core.object(1).velocity().y == Approx(falling + engine::kGravity.y / kStepsPerSecond).epsilon(1e-12));
    }
}

TEST_CASE("s5_9: a scripted drag replays to the same dump, byte for byte", "[mouse]") {
    const test::ScratchFolder folder("s5_9-mouse-replay");
    const std::string scene = folder
                                  .write("room.json", R"({"world": {"solver": "sequential_impulse"}, "bodies": [
        {"shape": "rectangle", "center": [400, 440], "width": 800, "height": 20, "mass": 0},
        {"shape": "rectangle", "center": [300, 410], "width": 40, "height": 40},
        {"shape": "circle", "center": [500, 410], "radius": 20}]})")
                                  .string();
    const std::string drag = "drag:305,405*5/320,380/340,350/360,320/380,300/400,280*40@10";
    const auto run = [&](const std::string& name) {
        const test::ProgramRun result = test::runStageProgram(
            folder, "--scene " + test::quoted(scene) + " --keys '" + drag + "' --frames 70 --every 0 --no-gif --dump " +
                        test::quoted(folder.path / (name + ".csv")) + " --out " + test::quoted(folder.path / name));
        REQUIRE(result.status == 0);
        return test::readText(folder.path / (name + ".csv"));
    };
    const std::string first = run("first");
    const std::string second = run("second");
    CHECK(first == second);
    // And the drag did something: the box is off the floor by step 50, near the pointer.
    const std::size_t row = first.find("\n50,1,");
    REQUIRE(row != std::string::npos);
    std::istringstream fields(first.substr(row + 1, first.find('\n', row + 1) - row - 1));
    std::string field;
    std::vector<double> numbers;
    while (std::getline(fields, field, ',')) numbers.push_back(std::atof(field.c_str()));
    REQUIRE(numbers.size() >= 6);
    CHECK(Vec2{numbers[4], numbers[5]}.distance({400, 280}) < 40.0);
    // Without the drag the box stays on the floor.
    const test::ProgramRun still = test::runStageProgram(
        folder, "--scene " + test::quoted(scene) + " --frames 70 --every 0 --no-gif --dump " +
                    test::quoted(folder.path / "still.csv") + " --out " + test::quoted(folder.path / "still"));
    REQUIRE(still.status == 0);
    CHECK(test::readText(folder.path / "still.csv") != first);
}

}  // namespace s5_9_mouse_test
