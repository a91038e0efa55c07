// Collision impulses (every stage from 4.3 on): bounces against Newton's law of
// restitution and conservation of momentum worked out by hand, rest and stability,
// and the quirks of the book's response that we keep.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

#include "book_scene.h"
#include "circle.h"
#include "closed_box.h"
#include "expect.h"
#include "my_game.h"
#include "near.h"
#include "rectangle.h"
#include "stage_fixture.h"
#include "world_fixture.h"
#include "world_measures.h"

namespace collision_impulse_test {

using browser::Key;
using engine::Vec2;

namespace {

constexpr double kDt = 1.0 / 60.0;
constexpr double kG = engine::kGravity.y;  // the book's gravity, px/s^2 down (10 in chapter 4, 20 in the demo)
constexpr Vec2 kNoGravity{0, 0};

// Two circles of radius 10 on the x axis, 1 px into each other, about to meet head on
// (no friction, so only the normal impulse acts).
struct HeadOn {
    HeadOn(double mass_a, double mass_b, double restitution, Vec2 va, Vec2 vb)
        : page(test::world(true, kNoGravity)),
          a(page.core.add(engine::Circle({100, 100}, 10, {mass_a, 0.0, restitution}))),
          b(page.core.add(engine::Circle({119, 100}, 10, {mass_b, 0.0, restitution}))) {
        a.setVelocity(va);
        b.setVelocity(vb);
    }
    test::WorldFixture page;
    engine::Circle& a;
    engine::Circle& b;
};

void requireConserved(Vec2 before, Vec2 after) {
    test::expectEqual("the pair's momentum along x after the step, mass px/s: as before (m v conserved)",
                      Approx(before.x).epsilon(1e-9), after.x);
    // Rounding: 1e-9 of the momentum.
    CHECK_THAT(after.y, test::near(before.y, 1e-9 * before.length()));
}

}  // namespace

TEST_CASE("collision impulse: equal circles, e = 1: they swap velocities, momentum is kept") {
    HeadOn pair(2, 2, 1.0, {60, 0}, {-20, 0});
    const Vec2 momentum = test::linearMomentum(pair.page.core);  // 2 * 60 - 2 * 20 = 80
    pair.page.steps(1);
    test::expectEqual("circle a's vx after the head-on hit, px/s: equal masses, e = 1, they swap (b's -20)",
                      Approx(-20).epsilon(1e-12), pair.a.velocity().x);
    test::expectEqual("circle b's vx after the head-on hit, px/s: a's 60", Approx(60).epsilon(1e-12),
                      pair.b.velocity().x);
    test::expectEqual("circle a's vy, px/s: the hit is along x", 0, pair.a.velocity().y);
    requireConserved(momentum, test::linearMomentum(pair.page.core));
    pair.page.steps(30);  // they fly apart, untouched
    test::expectEqual("circle a's vx 30 steps later, px/s: flying apart, untouched", Approx(-20).epsilon(1e-12),
                      pair.a.velocity().x);
    test::expectAbove("the distance between the centres 30 steps later, px: above the radii's 20, apart", 20,
                      pair.b.center().x - pair.a.center().x);
}

TEST_CASE("collision impulse: equal circles, e = 0: they go on together, momentum is kept") {
    // A perfectly inelastic collision leaves both at the centre-of-mass velocity:
    // (2 * 60 + 2 * -20) / 4 = 20.
    HeadOn pair(2, 2, 0.0, {60, 0}, {-20, 0});
    const Vec2 momentum = test::linearMomentum(pair.page.core);
    pair.page.steps(1);
    test::expectEqual(
        "circle a's vx after the hit, px/s: e = 0, both at the centre-of-mass velocity (2 x 60 - 2 x 20) / 4",
        Approx(20).epsilon(1e-12), pair.a.velocity().x);
    test::expectEqual("circle b's vx after the hit, px/s: the same 20", Approx(20).epsilon(1e-12), pair.b.velocity().x);
    requireConserved(momentum, test::linearMomentum(pair.page.core));
    pair.page.steps(30);
    // Touching, side by side: the passes left 1 px * 0.2^15 = 3e-11 px of overlap.
    CHECK_THAT(pair.b.center().x - pair.a.center().x, test::near(20, 1e-10));
    requireConserved(momentum, test::linearMomentum(pair.page.core));
}

TEST_CASE("collision impulse: a head-on hit at any angle has no friction, however grippy") {
    // A circle meets a static one head on along 64 directions around the clock. Nothing
    // slides, so friction (mu = 1) must do nothing: the circle leaves along the line it
    // came on at e = 0.5 times its speed. Off the axes the sliding left after taking the
    // normal part away is rounding noise in a third of these directions; a tangent made
    // from that noise kicks the circle sideways, or along the normal, by up to jN.
    for (int k = 0; k < 64; ++k) {
        const double angle = 2 * std::acos(-1.0) * k / 64 + 0.1;
        const Vec2 direction{std::cos(angle), std::sin(angle)};
        test::WorldFixture page(test::world(true, kNoGravity));
        const Vec2 wall_center{300, 300};
        page.core.add(engine::Circle(wall_center, 10, {0.0, 1.0, 0.5}));
        engine::Circle& ball = page.core.add(engine::Circle(wall_center - direction * 19, 10, {1.0, 1.0, 0.5}));
        ball.setVelocity(direction * 100);
        page.steps(1);
        INFO("direction " << k << " of 64: (" << direction.x << ", " << direction.y << ")");
        const Vec2 velocity = ball.velocity();
        // Along the line: -e * 100 = -50. Across it: nothing, to rounding (1e-9 of 100).
        CHECK_THAT(velocity.dot(direction), test::near(-50, 1e-7));
        CHECK_THAT(velocity.cross(direction), test::near(0, 1e-7));
    }
}

TEST_CASE("collision impulse: a 1:1000 mass ratio follows the one-dimensional collision formulas") {
    // Textbook head-on collision with restitution e:
    //   va' = ((ma - e mb) va + (1 + e) mb vb) / (ma + mb)
    //   vb' = ((mb - e ma) vb + (1 + e) ma va) / (ma + mb)
    // For ma << mb the light one bounces off the heavy one as off a wall moving at vb.
    const double ma = 1, mb = 1000, va = 60, vb = -20;
    for (double e : {1.0, 0.5, 0.0}) {
        INFO("e = " << e);
        HeadOn pair(ma, mb, e, {va, 0}, {vb, 0});
        const Vec2 momentum = test::linearMomentum(pair.page.core);
        pair.page.steps(1);
        test::expectEqual("the light circle's vx after the hit, px/s: ((ma - e mb) va + (1 + e) mb vb) / (ma + mb)",
                          Approx(((ma - e * mb) * va + (1 + e) * mb * vb) / (ma + mb)).epsilon(1e-12),
                          pair.a.velocity().x);
        test::expectEqual("the heavy circle's vx after the hit, px/s: ((mb - e ma) vb + (1 + e) ma va) / (ma + mb)",
                          Approx(((mb - e * ma) * vb + (1 + e) * ma * va) / (ma + mb)).epsilon(1e-12),
                          pair.b.velocity().x);
        requireConserved(momentum, test::linearMomentum(pair.page.core));
    }
}

TEST_CASE("collision impulse: a ball dropped on a static floor rebounds at e times its speed") {
    // The impulse turns the ball's velocity v into exactly -e v. But the step that does
    // so then adds gravity's g dt, and the speed before was read a step earlier, so the
    // measured ratio is e - g dt / v: below e by g dt / v, 0.4% for the 40 px/s at which
    // an 80 px drop lands.
    for (double e : {0.2, 0.6, 1.0}) {
        INFO("e = " << e);
        test::WorldFixture page(test::world(true));
        page.core.add(engine::Rectangle({400, 400}, 800, 20, {.mass = 0, .restitution = 1.0}));
        engine::Circle& ball = page.core.add(engine::Circle({400, 300}, 10, {.mass = 1, .restitution = e}));
        double falling = 0;
        for (int step = 0; step < 600 && ball.velocity().y >= 0; ++step) {
            falling = ball.velocity().y;
            page.steps(1);
        }
        const double rising = -ball.velocity().y;
        if (!test::expectAbove("the ball's upward speed after the bounce, px/s: it rebounds", 0, rising)) return;
        const double tolerance = kG * kDt / falling * (1 + 1e-9);
        test::expectAtMost("|rebound ratio - e|: within g dt / (the speed it hit at)", tolerance,
                           std::abs(rising / falling - e));
        test::expectEqual("the rebound ratio (speed up / speed down): e - g dt / v",
                          Approx(e - kG * kDt / falling).epsilon(1e-9), rising / falling);
        test::expectEqual("the ball's vx after a straight drop, px/s", 0, ball.velocity().x);
        WARN("dropped 80 px, hit at " << falling << " px/s, e = " << e << ": rebound ratio " << rising / falling);
    }
}

TEST_CASE("collision impulse: separating shapes are still pushed apart, in every pass (book's order, kept)") {
    // The book corrects the positions before it asks whether the pair is already
    // moving apart, so a separating pair is pushed apart by all 15 passes too, and its
    // velocities are left alone. Movement off: only the passes move anything.
    test::WorldFixture page(test::world(false, kNoGravity));
    engine::Circle& a = page.core.add(engine::Circle({100, 100}, 10));
    engine::Circle& b = page.core.add(engine::Circle({115, 100}, 10));
    a.setVelocity({-10, 0});
    b.setVelocity({10, 0});
    page.steps(1);
    // 1e-12 px: one step's rounding near 100 px, far below the last pass's 6.6e-10 px.
    CHECK_THAT(b.center().x - a.center().x, test::near(20 - 5 * std::pow(0.2, 15), 1e-12));
    test::expectEqual("circle a's velocity, px/s: a separating pair gets no impulse", Vec2{-10, 0}, a.velocity());
    test::expectEqual("circle b's velocity, px/s: a separating pair gets no impulse", Vec2{10, 0}, b.velocity());
}

TEST_CASE("collision impulse: a sliding box slows at about g whatever its friction (book's model, kept)") {
    // Coulomb friction would slow a box sliding on a floor at mu g: 1, 5 and 10 px/s^2
    // for mu = 0.1, 0.5 and 1. The book's friction impulse is mu (1 + e) times the one
    // that stops the slide, capped at jN. Resting on the floor, jN only cancels the
    // g dt that gravity adds each step, so the cap decides, and the box loses g dt of
    // speed a step: it slows at g, whatever mu (docs/errata.md, "Friction").
    for (double mu : {0.1, 0.5, 1.0}) {
        INFO("mu = " << mu);
        test::WorldFixture page(test::world(true));
        page.core.add(engine::Rectangle({400, 400}, 800, 20, {.mass = 0, .friction = 1, .restitution = 0}));
        engine::Rectangle& box = page.core.add(engine::Rectangle({100, 380}, 20, 20, {1, mu, 0}));
        box.setVelocity({100, 0});
        page.steps(60);
        const double deceleration = 100 - box.velocity().x;  // over 1 s
        test::expectEqual(
            "the sliding box's deceleration over 1 s, px/s^2: about g (the book's friction, capped at jN)",
            Approx(kG).epsilon(0.05), deceleration);
        WARN("mu = " << mu << ": the box slows at " << deceleration << " px/s^2 (Coulomb: " << mu * kG << ")");
    }
}

TEST_CASE("collision impulse: a box resting on a static floor stays put for 10,000 steps") {
    test::WorldFixture page(test::world(true));
    page.core.add(engine::Rectangle({400, 400}, 800, 20, {.mass = 0}));
    engine::Rectangle& box = page.core.add(engine::Rectangle({300, 380}, 40, 20));
    page.steps(60);  // a second to settle into its resting overlap
    const Vec2 settled = box.center();
    double drift = 0, turn = 0;
    for (int step = 0; step < 10'000; ++step) {
        page.steps(1);
        drift = std::max(drift, box.center().distance(settled));
        turn = std::max(turn, std::abs(box.angle()));
    }
    test::expectBelow("how far the resting box drifted in 10,000 steps, px", 0.1, drift);
    WARN("resting box: drifted at most " << drift << " px and turned at most " << turn << " rad in 10,000 steps");
}

TEST_CASE(
    "collision impulse: 10,000 steps of the book's scene with shapes everywhere end finite, on the canvas, at rest") {
    // Twelve shapes made across the canvas in three rows (inside the chapter 4 borders),
    // kicked at up to 250 px/s by H, then 10,000 steps (167 s). Every number stays finite;
    // every shape stays on the canvas (chapter 4's borders hold them; the demo removes
    // the ones that fall off); and the impulses take the kick's energy away until every
    // shape rests. A resting shape sinks g dt^2 into what holds it each step and is
    // pushed back out, so it never quite stops: measured, the fastest of them moves at
    // 0.43 px/s after 10,000 steps, and the kinetic energy left is a millionth of the
    // most there was. The bounds are 1 px/s and 1e-5 of it.
    test::WorldFixture page(test::world(true), 7);
    test::buildBookScene(page.core, page.random);
    page.press(Key::Digit0);
    page.press(Key::A, 30);  // the cursor (the demo: the long slide) to x = 100
    for (int row = 0; row < 3; ++row) {
        for (int column = 0; column < 4; ++column) {  // x = 100, 250, 400 and 550
            page.press(column % 2 ? Key::F : Key::G);
            page.press(Key::D, 15);
        }
        page.press(Key::A, 60);
        page.press(Key::W, 5);  // the next row 50 px higher
    }
    page.press(Key::H);
    double most_energy = 0;
    for (int step = 1; step <= 10'000; ++step) {
        page.steps(1);
        if (const auto bad = test::firstNotFinite(page.core))
            FAIL("step " << step << ": shape " << *bad << " is not finite");
        most_energy = std::max(most_energy, test::kineticEnergy(page.core));
    }
    if (!test::expectAbove("the most kinetic energy in 10,000 steps: H set the shapes moving", 0, most_energy)) return;
    double fastest = 0;
    for (std::size_t i = 0; i < page.core.objectCount(); ++i) {
        const engine::RigidShape& shape = page.core.object(i);
        INFO("object " << i);
        test::expectEqual("how far its centre is off the canvas after 10,000 steps, px", 0,
                          test::outside(shape.center(), 0, page.core.width(), 0, page.core.height()));
        fastest = std::max(fastest, shape.velocity().length());
    }
    const double energy_left = test::kineticEnergy(page.core);
    WARN("after 10,000 steps: " << page.core.objectCount() << " shapes, the fastest at " << fastest
                                << " px/s, kinetic energy " << energy_left / most_energy << " of its most");
    test::expectBelow("the fastest shape's speed after 10,000 steps, px/s: at rest", 1, fastest);
    test::expectBelow("the kinetic energy left after 10,000 steps: below 1e-5 of its most", 1e-5 * most_energy,
                      energy_left);
}

TEST_CASE("collision impulse: the frame no longer draws the collision info") {
    // From 4.3 on the book's pass has its drawing call commented out: the shapes alone.
    test::StageFixture page;
    page.core.add(engine::Rectangle({700, 400}, 3, 3, {.mass = 0}));
    page.core.add(engine::Circle({100, 100}, 20));
    page.core.add(engine::Circle({130, 100}, 20));  // 10 px deep
    page.frame();
    REQUIRE_FALSE(page.core.physics().collisions().empty());
    const browser::Image& pixels = page.window.document.canvas.pixels();
    int orange = 0;
    for (int y = 0; y < pixels.height; ++y) {
        for (int x = 0; x < pixels.width; ++x) orange += pixels.at(x, y) == browser::colors::kOrange ? 1 : 0;
    }
    test::expectEqual("orange pixels of the frame: from 4.3 on the book no longer draws the collision info", 0, orange);
}

}  // namespace collision_impulse_test
