// Motion (every stage from 4.1 on): symplectic Euler under gravity against its closed
// form, the movement flag, mass, inertia and the other attributes, and the keys that
// change them.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <string>

#include "circle.h"
#include "expect.h"
#include "near.h"
#include "rectangle.h"
#include "world_fixture.h"
#include "world_from_scene.h"

namespace movement_test {

using browser::Key;
using engine::Vec2;

namespace {
constexpr double kDt = 1.0 / 60.0;
constexpr double kG = engine::kGravity.y;  // the book's gravity, px/s^2 down (10 in chapter 4, 20 in the demo)
constexpr double kExact = 1e-9;            // px: positions a few hundred px, a few hundred steps
}  // namespace

TEST_CASE("movement: free fall follows the symplectic Euler closed form") {
    // v_k = v0 + k g dt, and each step moves by the *new* velocity, so after n steps
    // y_n = y0 + dt (v_1 + ... + v_n) = y0 + n dt v0 + dt^2 g n (n + 1) / 2.
    test::WorldFixture page(test::world(true));
    const Vec2 start{100, 50}, v0{3, -20};
    engine::Circle& ball = page.core.add(engine::Circle(start, 5, {.mass = 2}));
    ball.setVelocity(v0);
    for (int n = 1; n <= 300; ++n) {
        page.steps(1);
        const double y = start.y + n * kDt * v0.y + kDt * kDt * kG * n * (n + 1) / 2.0;
        const double x = start.x + n * kDt * v0.x;
        REQUIRE_THAT(ball.center().x, test::near(x, kExact));
        REQUIRE_THAT(ball.center().y, test::near(y, kExact));
        REQUIRE_THAT(ball.velocity().y, test::near(v0.y + n * kG * kDt, kExact));
    }
}

TEST_CASE("movement: explicit Euler would land on the other side of the exact parabola") {
    test::WorldFixture page(test::world(true));
    const double y0 = 100, v0 = -30;
    engine::Rectangle& box = page.core.add(engine::Rectangle({200, y0}, 10, 10));
    box.setVelocity({0, v0});
    constexpr int kSteps = 240;
    page.steps(kSteps);

    // Explicit Euler moves with the velocity from the start of each step.
    double explicit_y = y0, explicit_v = v0;
    for (int n = 0; n < kSteps; ++n) {
        explicit_y += explicit_v * kDt;
        explicit_v += kG * kDt;
    }
    const double t = kSteps * kDt;
    const double exact = y0 + v0 * t + kG * t * t / 2;
    // Symplectic Euler runs ahead of the true fall by g dt^2 n / 2 = 0.333 px after 4 s;
    // explicit Euler lags behind by exactly as much: a different answer, off the exact
    // parabola by the same amount the other way. With a constant force neither is worse;
    // the difference that matters shows with forces that change with position (next test).
    const double half_gap = kG * kDt * kDt * kSteps / 2;
    CHECK_THAT(box.center().y - exact, test::near(half_gap, kExact));
    CHECK_THAT(explicit_y - exact, test::near(-half_gap, kExact));
    CHECK_THAT(box.center().y - explicit_y, test::near(2 * half_gap, kExact));
}

TEST_CASE("movement: why symplectic: on a spring the engine's step keeps the energy within w dt of the start") {
    // The book has no springs, but a shape's update() takes the world's gravity as its
    // acceleration: setting it to -w^2 x before every step makes the engine's own
    // integrator run a spring, x'' = -w^2 x, here at 1 Hz about x = 100, for 10 s.
    // Symplectic Euler keeps a slightly tilted energy exactly, so the true energy only
    // wobbles, by about w dt / 2 of itself. Explicit Euler, moving with the velocity from
    // before the step, multiplies it by exactly 1 + w^2 dt^2 every step: 695 times the
    // start after 600 steps. That is the instability the book warns about.
    const double w = 2 * std::numbers::pi;
    engine::WorldSettings world = test::world(true, {0, 0});
    engine::Circle ball({101, 100}, 5);
    const auto energy = [&] {
        const double x = ball.center().x - 100;
        const double v = ball.velocity().x;
        return (v * v + w * w * x * x) / 2;
    };
    const double start = energy();
    double worst = 0;
    for (int n = 0; n < 600; ++n) {
        world.gravity = {-w * w * (ball.center().x - 100), 0};
        ball.update(world);
        worst = std::max(worst, std::abs(energy() / start - 1));
    }
    WARN("spring, symplectic Euler: energy within " << worst << " of the start over 600 steps (w dt = " << w * kDt
                                                    << "; explicit Euler: x" << std::pow(1 + w * w * kDt * kDt, 600)
                                                    << ")");
    test::expectBelow(
        "the spring's energy error, its largest share over 600 steps: below w dt (symplectic Euler keeps it bounded)",
        w * kDt, worst);
    // it does wobble: the spring really ran
    test::expectAbove("the spring's energy error, its largest share: above w dt / 4, so the spring really ran",
                      w * kDt / 4, worst);
}

TEST_CASE("movement: a spinning shape turns by w dt each step") {
    test::WorldFixture page(test::world(true, {0, 0}));
    engine::Rectangle& box = page.core.add(engine::Rectangle({300, 200}, 40, 20));
    box.setAngularVelocity(0.5);
    page.steps(120);
    const engine::Rectangle once = [] {
        engine::Rectangle turned({300, 200}, 40, 20);
        turned.rotate(120 * kDt * 0.5);
        return turned;
    }();
    CHECK_THAT(box.angle(), test::near(1.0, 1e-12));
    for (int i = 0; i < 4; ++i) {
        CHECK_THAT(box.vertices()[i].x, test::near(once.vertices()[i].x, 1e-9));
        CHECK_THAT(box.vertices()[i].y, test::near(once.vertices()[i].y, 1e-9));
    }
}

TEST_CASE("movement: nothing moves while the flag is off; comma toggles it") {
    test::WorldFixture page(test::world(false));
    engine::Circle& ball = page.core.add(engine::Circle({100, 100}, 10));
    ball.setVelocity({30, 0});
    page.steps(10);
    test::expectEqual("the ball's centre after 10 steps with movement off, px", Vec2{100, 100}, ball.center());
    // gravity waits too
    test::expectEqual("the ball's velocity after 10 steps with movement off, px/s: gravity waits too", Vec2{30, 0},
                      ball.velocity());
    page.press(Key::Comma);
    test::expectEqual("movement after the comma key (WorldSettings::movement)", true, page.core.settings().movement);
    page.steps(1);
    CHECK_THAT(ball.center().x, test::near(100 + 30 * kDt, 1e-12));  // one step: rounding of 100 px
    page.press(Key::Comma);
    const Vec2 stopped = ball.center();
    page.steps(10);
    test::expectEqual("the ball's centre after 10 more steps with movement off again, px", stopped, ball.center());
}

TEST_CASE("movement: a static body feels no gravity") {
    test::WorldFixture page(test::world(true));
    engine::Rectangle& floor = page.core.add(engine::Rectangle({400, 440}, 800, 20, {.mass = 0}));
    page.steps(60);
    test::expectEqual("the static floor's centre after 60 steps under gravity, px", Vec2{400, 440}, floor.center());
    test::expectEqual("the static floor's velocity, px/s: 1/m = 0, gravity cannot move it", Vec2{0, 0},
                      floor.velocity());
}

TEST_CASE("movement: the keys set a static body moving, and it moves as in the book, unaccelerated") {
    // The keys act on whatever is selected, a static body too. Gravity cannot move it
    // (1/m is 0), but the velocity the keys give it does, as the book integrates it:
    // L three times is 3 px/s to the right, O twice 0.2 rad/s, so 60 steps of 1/60 s
    // later it has moved 3 px and turned 0.2 rad, and its velocities are unchanged.
    test::WorldFixture page(test::world(true));
    engine::Rectangle& wall = page.core.add(engine::Rectangle({100, 200}, 10, 100, {.mass = 0}));
    page.press(Key::Digit0);
    page.press(Key::L, 3);
    page.press(Key::O, 2);
    page.steps(60);
    CHECK_THAT(wall.center(), test::near(Vec2{103, 200}, kExact));
    CHECK_THAT(wall.angle(), test::near(0.2, 1e-12));
    test::expectEqual("the static wall's velocity after L three times and 60 steps, px/s", Vec2{3, 0}, wall.velocity());
    CHECK_THAT(wall.angularVelocity(), test::near(0.2, 1e-15));
}

TEST_CASE("movement: the world's dt is both the integration step and the loop's fixed step") {
    // dt = 1/30 s with 60 Hz frames: an update every second frame, each moving the
    // ball by its new velocity times 1/30 s.
    engine::WorldSettings settings = test::world(true);
    settings.dt = 1.0 / 30.0;
    browser::Window window(1000.0 / 60.0);
    engine::Core core(window, settings);
    engine::Circle& ball = core.add(engine::Circle({100, 100}, 10));
    for (int k = 0; k < 10; ++k) {
        window.clock.advanceFrame();
        core.runGameLoop();
    }
    test::requireEqual("updates in 10 frames of 1000/60 ms with dt = 1/30 s", 5, core.stepCount());
    const double dt = settings.dt;
    CHECK_THAT(ball.center().y, test::near(100 + dt * dt * kG * 5 * 6 / 2, kExact));
}

TEST_CASE("movement: the scene file's gravity pulls along both axes, in its own direction") {
    // Symplectic Euler from rest: after n steps v = g n dt and the shape has moved
    // g dt^2 n (n + 1) / 2, along each axis with that axis's component.
    const engine::WorldSettings world = test::worldFromScene(R"({"movement": true, "gravity": [3, -7]})");
    test::requireEqual("the scene's gravity, as read, px/s^2", Vec2{3, -7}, world.gravity);
    test::WorldFixture page(world);
    engine::Circle& ball = page.core.add(engine::Circle({400, 225}, 5));
    for (int n = 1; n <= 60; ++n) {
        page.steps(1);
        const double fallen = kDt * kDt * n * (n + 1) / 2.0;
        REQUIRE_THAT(ball.center(), test::near(Vec2{400 + 3 * fallen, 225 - 7 * fallen}, kExact));
        REQUIRE_THAT(ball.velocity(), test::near(Vec2{3 * n * kDt, -7 * n * kDt}, kExact));
    }
}

TEST_CASE("movement: the scene file's dt is both the loop's fixed step and the integration step") {
    // dt = 0.025 s: twelve frames of 1000/60 ms are 200 ms, eight steps, each adding
    // g dt to the velocity and moving by the new velocity times 0.025 s.
    const engine::WorldSettings world = test::worldFromScene(R"({"movement": true, "dt": 0.025})");
    test::requireEqual("the scene's dt, as read, s", 0.025, world.dt);
    browser::Window window(1000.0 / 60.0);
    engine::Core core(window, world);
    engine::Circle& ball = core.add(engine::Circle({100, 100}, 10));
    for (int frame = 0; frame < 12; ++frame) {
        window.clock.advanceFrame();
        core.runGameLoop();
    }
    test::requireEqual("updates in 12 frames of 1000/60 ms with the scene's dt = 0.025 s", 8, core.stepCount());
    CHECK_THAT(ball.velocity().y, test::near(kG * 8 * 0.025, kExact));
    CHECK_THAT(ball.center().y, test::near(100 + 0.025 * 0.025 * kG * 8 * 9 / 2, kExact));
}

TEST_CASE("movement: the scene file's movement flag starts the world moving or still") {
    for (const bool moving : {true, false}) {
        INFO("movement " << moving);
        const engine::WorldSettings world =
            test::worldFromScene(std::string(R"({"movement": )") + (moving ? "true" : "false") + "}");
        test::requireEqual("the scene's movement flag, as read", moving, world.movement);
        test::WorldFixture page(world);
        engine::Circle& ball = page.core.add(engine::Circle({100, 100}, 10));
        ball.setVelocity({30, 0});
        page.steps(1);
        if (moving) {
            CHECK_THAT(ball.center(), test::near(Vec2{100 + 30 * kDt, 100 + kG * kDt * kDt}, kExact));
        } else {
            test::expectEqual("the ball's centre after a step with movement off, px", Vec2{100, 100}, ball.center());
            test::expectEqual("the ball's velocity after a step with movement off, px/s", Vec2{30, 0}, ball.velocity());
        }
    }
}

TEST_CASE("movement: the book's default attributes, and inertia stored inverted") {
    const engine::Rectangle box({0, 0}, 30, 40);
    test::expectEqual("a rectangle's mass by default (PhysicalAttributes: the book's 1)", 1, box.mass());
    test::expectEqual("its inverse mass 1/m", 1, box.invMass());
    test::expectEqual("a rectangle's friction by default (the book's 0.8)", 0.8, box.friction());
    test::expectEqual("a rectangle's restitution by default (the book's 0.2)", 0.2, box.restitution());
    test::expectEqual("a new rectangle's velocity, px/s", Vec2{0, 0}, box.velocity());
    test::expectEqual("a new rectangle's angular velocity, rad/s", 0, box.angularVelocity());
    // A w x h plate: I = m (w^2 + h^2) / 12 = (900 + 1600) / 12, so 1/I = 12 / 2500.
    // 1e-16: rounding of values near 0.005.
    CHECK_THAT(box.invInertia(), test::near(12.0 / 2500, 1e-16));
    CHECK_THAT(engine::Rectangle({0, 0}, 30, 40, {.mass = 2}).invInertia(), test::near(12.0 / 5000, 1e-16));

    // A solid disc: I = m r^2 / 2 (the book's m r^2 / 12, never inverted, is a bug;
    // see docs/errata.md). m = 4, r = 10: I = 200.
    const engine::Circle ball({0, 0}, 10, {.mass = 4, .friction = 0.3, .restitution = 0.9});
    test::expectEqual("a circle of mass 4: its inverse mass 1/m", 0.25, ball.invMass());
    CHECK_THAT(ball.invInertia(), test::near(1.0 / 200, 1e-16));
    test::expectEqual("the circle's friction, as given", 0.3, ball.friction());
    test::expectEqual("the circle's restitution, as given", 0.9, ball.restitution());

    const engine::Circle fixed({0, 0}, 10, {.mass = 0});
    test::expectEqual("a circle of mass 0 is static", true, fixed.isStatic());
    test::expectEqual("a static circle's inverse mass 1/m", 0, fixed.invMass());
    test::expectEqual("a static circle's inverse inertia 1/I", 0, fixed.invInertia());
}

TEST_CASE("movement: Z down to mass 0 makes the body static and stops it; X gives it mass again") {
    test::WorldFixture page(test::world(false));
    engine::Rectangle& box = page.core.add(engine::Rectangle({100, 100}, 30, 40, {.mass = 2}));
    box.setVelocity({5, 6});
    box.setAngularVelocity(0.3);
    page.press(Key::Digit0);
    page.press(Key::Z);  // mass 1
    test::expectEqual("the box's inverse mass 1/m after Z (mass 2 - 1)", 1, box.invMass());
    CHECK_THAT(box.invInertia(), test::near(12.0 / 2500, 1e-16));  // rounding of values near 0.005
    test::expectEqual("the box's velocity after Z leaves it a mass, px/s: unchanged", Vec2{5, 6}, box.velocity());
    page.press(Key::Z);  // mass 0: static
    test::expectEqual("static once Z takes its mass to 0", true, box.isStatic());
    test::expectEqual("the box's inverse mass 1/m once static", 0, box.invMass());
    test::expectEqual("the box's inverse inertia 1/I once static", 0, box.invInertia());
    test::expectEqual("the box's velocity once static, px/s: stopped dead", Vec2{0, 0}, box.velocity());
    test::expectEqual("the box's angular velocity once static, rad/s: stopped dead", 0, box.angularVelocity());
    page.press(Key::Z);  // would be -1: stays static
    test::expectEqual("still static after Z again (mass would be -1)", true, box.isStatic());
    page.press(Key::X);  // mass 1 again
    test::expectEqual("the box's inverse mass 1/m after X (mass 1 again)", 1, box.invMass());
    CHECK_THAT(box.invInertia(), test::near(12.0 / 2500, 1e-16));
    page.press(Key::X);  // mass 2
    test::expectEqual("the box's inverse mass 1/m after X twice (mass 2)", 0.5, box.invMass());
    CHECK_THAT(box.invInertia(), test::near(12.0 / 5000, 1e-16));
}

TEST_CASE("movement: I J K L U O change the velocities; C V B N friction and restitution") {
    test::WorldFixture page(test::world(false));
    engine::Circle& ball = page.core.add(engine::Circle({100, 100}, 10, {.friction = 0.02, .restitution = 0.98}));
    page.press(Key::Digit0);
    page.press(Key::I, 3);  // up is -y
    page.press(Key::L, 2);
    page.press(Key::J);
    page.press(Key::K);
    test::expectEqual("the ball's velocity after I three times, L twice, J and K, px/s (up is -y)", Vec2{1, -2},
                      ball.velocity());
    page.press(Key::O, 3);
    page.press(Key::U);
    // 1e-15: steps of 0.1 and 0.01 added up round by an ulp or two.
    CHECK_THAT(ball.angularVelocity(), test::near(0.2, 1e-15));
    page.press(Key::V);
    CHECK_THAT(ball.friction(), test::near(0.03, 1e-15));
    page.press(Key::C, 5);  // stops at 0
    test::expectEqual("the ball's friction after C five times from 0.03: it stops at 0", 0, ball.friction());
    page.press(Key::B);
    CHECK_THAT(ball.restitution(), test::near(0.97, 1e-15));
    page.press(Key::N, 5);  // stops at 1
    test::expectEqual("the ball's restitution after N five times from 0.97: it stops at 1", 1, ball.restitution());
}

TEST_CASE("movement: H gives every non-static object a random velocity of up to kExciteSpeed a component") {
    constexpr double kKick = engine::UserControl::kExciteSpeed;  // 10 px/s in 4.1, 250 from 4.2 on
    test::WorldFixture page(test::world(false));
    engine::Rectangle& wall = page.core.add(engine::Rectangle({0, 0}, 10, 100, {.mass = 0}));
    for (int i = 0; i < 20; ++i) page.core.add(engine::Circle({100.0 + 30 * i, 100}, 10));
    page.press(Key::H);
    test::expectEqual("a static wall's velocity after H, px/s: H kicks only what can move", Vec2{0, 0},
                      wall.velocity());
    double fastest = 0;
    for (std::size_t i = 1; i < page.core.objectCount(); ++i) {
        const Vec2 v = page.core.object(i).velocity();
        test::expectAtMost(
            "the kicked circle's |vx|, px/s: at most UserControl::kExciteSpeed (10 in 4.1, 250 from 4.2 on)", kKick,
            std::abs(v.x));
        test::expectAtMost("the kicked circle's |vy|, px/s: at most UserControl::kExciteSpeed", kKick, std::abs(v.y));
        fastest = std::max({fastest, std::abs(v.x), std::abs(v.y)});
    }
    // 40 uniform draws: all below half has odds 2^-40
    test::expectAbove("the fastest component of 20 kicks, px/s: above half kExciteSpeed", kKick / 2, fastest);
    test::expectEqual("two circles kicked to different velocities", true,
                      page.core.object(1).velocity() != page.core.object(2).velocity());
}

TEST_CASE("movement: F and G spawn with mass 0..30, friction and restitution 0..1, velocity up to kSpawnSpeed") {
    constexpr double kFling = engine::UserControl::kSpawnSpeed;  // 0 in 4.1 (at rest), 150 px/s from 4.2 on
    test::WorldFixture page(test::world(false));
    page.core.add(engine::Rectangle({400, 225}, 3, 3, {.mass = 0}));
    page.press(Key::Digit0);
    double heaviest = 0;
    double fastest = 0;
    for (int i = 0; i < 50; ++i) {
        page.press(Key::F);
        page.press(Key::G);
    }
    for (std::size_t i = 1; i < page.core.objectCount(); ++i) {
        const engine::RigidShape& shape = page.core.object(i);
        test::expectAtLeast("a new shape's mass: at least 0", 0, shape.mass());
        test::expectBelow("a new shape's mass: below 30 (Math.random() * 30)", 30, shape.mass());
        test::expectAtLeast("a new shape's friction: at least 0", 0, shape.friction());
        test::expectBelow("a new shape's friction: below 1", 1, shape.friction());
        test::expectAtLeast("a new shape's restitution: at least 0", 0, shape.restitution());
        test::expectBelow("a new shape's restitution: below 1", 1, shape.restitution());
        test::expectAtMost("a new shape's |vx|, px/s: at most UserControl::kSpawnSpeed (0 in 4.1, 150 from 4.2 on)",
                           kFling, std::abs(shape.velocity().x));
        test::expectAtMost("a new shape's |vy|, px/s: at most UserControl::kSpawnSpeed", kFling,
                           std::abs(shape.velocity().y));
        test::expectEqual("a new shape's angular velocity, rad/s", 0, shape.angularVelocity());
        heaviest = std::max(heaviest, shape.mass());
        fastest = std::max({fastest, std::abs(shape.velocity().x), std::abs(shape.velocity().y)});
    }
    // 100 draws, none above 20: odds (2/3)^100
    test::expectAbove("the heaviest of 100 new shapes: above 20", 20, heaviest);
    // 200 uniform draws, all below half: odds 2^-200
    test::expectAtLeast("the fastest component of 100 new shapes, px/s: at least half kSpawnSpeed", kFling / 2,
                        fastest);
}

TEST_CASE("movement: F and G draw their random numbers in the book's order") {
    // The book's constructor arguments in order (size, mass, friction, restitution),
    // then, from 4.2 on, the velocity line that follows it: x, then y.
    constexpr std::uint64_t kSeed = 7;
    constexpr double kFling = engine::UserControl::kSpawnSpeed;
    test::WorldFixture page(test::world(false), kSeed);
    browser::Random book(kSeed);  // the same Math.random, drawn by hand
    const auto nextVelocity = [&] {
        if (kFling == 0) return Vec2{};
        const double vx = book.next() * 2 * kFling - kFling;
        const double vy = book.next() * 2 * kFling - kFling;
        return Vec2{vx, vy};
    };
    page.core.add(engine::Rectangle({400, 225}, 3, 3, {.mass = 0}));
    page.press(Key::F);
    page.press(Key::G);
    test::requireEqual("objects after F and G: the cursor, a rectangle, a circle", 3, page.core.objectCount());

    const auto& box = dynamic_cast<const engine::Rectangle&>(page.core.object(1));
    test::expectEqual("the rectangle's width, from the 1st random number (x 30 + 10)", book.next() * 30 + 10,
                      box.width());
    test::expectEqual("the rectangle's height, from the 2nd (x 30 + 10)", book.next() * 30 + 10, box.height());
    test::expectEqual("the rectangle's mass, from the 3rd (x 30)", Approx(book.next() * 30).epsilon(1e-12), box.mass());
    test::expectEqual("the rectangle's friction, the 4th", book.next(), box.friction());
    test::expectEqual("the rectangle's restitution, the 5th", book.next(), box.restitution());
    test::expectEqual("the rectangle's velocity, px/s: from 4.2 on the 6th and 7th (x 2 kSpawnSpeed - kSpawnSpeed)",
                      nextVelocity(), box.velocity());

    const auto& ball = dynamic_cast<const engine::Circle&>(page.core.object(2));
    test::expectEqual("the circle's radius, the next random number (x 10 + 20)", book.next() * 10 + 20, ball.radius());
    test::expectEqual("the circle's mass, the next (x 30)", Approx(book.next() * 30).epsilon(1e-12), ball.mass());
    test::expectEqual("the circle's friction, the next", book.next(), ball.friction());
    test::expectEqual("the circle's restitution, the next", book.next(), ball.restitution());
    test::expectEqual("the circle's velocity, px/s: from 4.2 on the next two", nextVelocity(), ball.velocity());
}

}  // namespace movement_test
