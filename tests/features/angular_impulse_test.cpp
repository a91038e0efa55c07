// Angular impulses (every stage from 4.4 on): spin from off-centre hits against the
// impulse formulas worked by hand and the conservation of linear and angular
// momentum, the corrected inertia of a disc, and the quirks of the book's response
// that we keep (the lever arms, the tangent from before the normal impulse, one contact
// point per pair).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <source_location>
#include <numbers>

#include "circle.h"
#include "expect.h"
#include "near.h"
#include "rectangle.h"
#include "world_fixture.h"

namespace angular_impulse_test {

using engine::Vec2;

namespace {

constexpr Vec2 kNoGravity{0, 0};
// px/s and rad/s: hand-worked values of 1 to 100, each a few dozen operations from
// numbers near 100 px, round by about 1e-13.
constexpr double kHandWorked = 1e-9;

// A world without gravity (unless given) and with positional correction on or off.
engine::WorldSettings world(bool positional_correction, Vec2 gravity = kNoGravity) {
    engine::WorldSettings settings = test::world(true, gravity);
    settings.positional_correction = positional_correction;
    return settings;
}

void requireConserved(double before, double after, std::source_location where = std::source_location::current()) {
    test::checkedAt(where, "the angular momentum about a fixed point after the step: as before (conserved)",
                    after == Approx(before).epsilon(1e-9),
                    "expected " + test::shown(before) + " (to 1e-9 of it), got " + test::shown(after));
}

// A ball of radius 10 and mass 3 (mu 0.5, e 0) sliding onto a static floor at (30, 60)
// px/s, 1 px deep already, not turning; one step of the world later.
struct BallSlidingOntoFloor {
    explicit BallSlidingOntoFloor(bool positional_correction)
        : page(world(positional_correction)),
          floor(page.core.add(engine::Rectangle({100, 110}, 200, 20, {.mass = 0, .friction = 1, .restitution = 0}))),
          ball(page.core.add(engine::Circle({100, 91}, 10, {3, 0.5, 0}))) {
        ball.setVelocity({30, 60});
        page.steps(1);
    }
    test::WorldFixture page;
    engine::Rectangle& floor;
    engine::Circle& ball;
};

}  // namespace

TEST_CASE("angular impulse: an off-centre hit sets a free box spinning; both momenta are kept") {
    // A 40 x 20 box of mass 2 at rest; a circle of radius 10 and mass 1 flies into its
    // right face 5 px above the centre, 1 px deep. No friction matters: the contact
    // moves straight along the normal (1, 0). e = 0.5.
    test::WorldFixture page(world(true));
    engine::Rectangle& box = page.core.add(engine::Rectangle({200, 200}, 40, 20, {2, 0.5, 0.5}));
    engine::Circle& ball = page.core.add(engine::Circle({229, 195}, 10, {1, 0.5, 0.5}));
    ball.setVelocity({-50, 0});
    const Vec2 about{37, -11};  // any fixed point will do
    const Vec2 momentum = test::linearMomentum(page.core);
    const double spin_momentum = test::angularMomentum(page.core, about);
    page.steps(1);

    // By hand. The contact lies between the circle's rim (219, 195) and the box's face
    // (220, 195), 2/3 of the way to the rim (weights 1/m): (219 1/3, 195). The first
    // pass's correction, 0.8 px, moves the box 0.8 / 3 px left first, so its arm is
    // rA = (219 1/3 - 199 11/15, -5) = (19.6, -5), and rA x n = 5. The circle's arm lies
    // along n: it gets no spin. With 1/I = 12 / (2 (40^2 + 20^2)) = 0.003:
    //   jN = (1 + e) 50 / (1/2 + 1/1 + 5^2 0.003) = 75 / 1.575
    const double jN = 75 / 1.575;
    test::expectEqual("the box's vx after the off-centre hit, px/s: -jN / m, jN = (1 + e) 50 / (1/2 + 1/1 + 5^2 0.003)",
                      Approx(-jN / 2).epsilon(1e-12), box.velocity().x);
    test::expectEqual("the ball's vx after the hit, px/s: -50 + jN / m", Approx(-50 + jN).epsilon(1e-12),
                      ball.velocity().x);
    // The box turns the other way from the clock on screen: w = -(rA x n) jN / I.
    test::expectEqual("the box's angular velocity after the hit, rad/s: -(rA x n) jN / I",
                      Approx(-5 * jN * 0.003).epsilon(1e-12), box.angularVelocity());
    test::expectEqual("the ball's angular velocity, rad/s: its arm lies along the normal", 0, ball.angularVelocity());

    const Vec2 after = test::linearMomentum(page.core);
    test::expectEqual("the shapes' momentum along x after the hit, mass px/s: as before (conserved)",
                      Approx(momentum.x).epsilon(1e-9), after.x);
    CHECK_THAT(after.y, test::near(momentum.y, 1e-9 * momentum.length()));
    requireConserved(spin_momentum, test::angularMomentum(page.core, about));
    page.steps(60);  // apart now: free flight keeps both
    test::expectEqual("the pair apart 60 steps later, in free flight", true, page.core.physics().collisions().empty());
    requireConserved(spin_momentum, test::angularMomentum(page.core, about));
}

TEST_CASE("angular impulse: oblique hits with friction keep both momenta") {
    // An impulse pair acting at one point, +j on one shape and -j on the other, leaves
    // m v and m (c x v) + I w unchanged, however big j is: so any hit conserves both.
    // (Positional correction is off: moving a shape sideways of its velocity would move
    // its angular momentum about a fixed point, and is no impulse.)
    test::WorldFixture page(world(false));
    engine::Rectangle& box = page.core.add(engine::Rectangle({200, 200}, 40, 20, {2, 0.7, 0.3}));
    box.rotate(0.4);
    box.setAngularVelocity(0.5);
    engine::Circle& ball = page.core.add(engine::Circle({224, 178}, 10, {1.5, 0.9, 0.6}));
    ball.setVelocity({-40, 25});
    ball.setAngularVelocity(-2);
    engine::Rectangle& other = page.core.add(engine::Rectangle({180, 224}, 30, 16, {3, 0.4, 0.2}));
    other.setVelocity({15, -30});
    const Vec2 about{400, 50};
    const Vec2 momentum = test::linearMomentum(page.core);
    const double spin_momentum = test::angularMomentum(page.core, about);
    int collided = 0;
    for (int step = 0; step < 60; ++step) {
        page.steps(1);
        collided += static_cast<int>(page.core.physics().collisions().size());
    }
    if (!test::expectAbove("collisions in 60 steps: the shapes did hit", 0, collided)) return;
    const Vec2 after = test::linearMomentum(page.core);
    test::expectEqual("the shapes' momentum along x after the hits, mass px/s: as before (conserved)",
                      Approx(momentum.x).epsilon(1e-9), after.x);
    test::expectEqual("the shapes' momentum along y after the hits, mass px/s: as before (conserved)",
                      Approx(momentum.y).epsilon(1e-9), after.y);
    requireConserved(spin_momentum, test::angularMomentum(page.core, about));
    test::expectEqual("the box's angular velocity changed by the hits (from 0.5 rad/s)", true,
                      box.angularVelocity() != 0.5);
}

TEST_CASE("angular impulse: a ball sliding onto a floor spins up as a solid disc would (inertia fix)") {
    // Floor static, e = 0, mu = 0.5; ball radius 10, mass 3, 1 px deep, moving (30, 60),
    // not turning; positional correction off, so the arm is exactly (0, 10) down to the
    // contact at the ball's lowest point. With a solid disc's I = m r^2 / 2:
    //   normal (0, -1):  r x n = 0, jN = (1 + e) 60 / (1/m) = 180: the fall stops.
    //   tangent (-1, 0), against the slide; r x t = 10:
    //     jT = (1 + e) 30 mu / (1/m + 10^2 2 / (m r^2)) = 15 m / 3 = 15   (< jN)
    //   v = 30 - jT / m = 25,  w = (r x t) jT / I = 10 15 2 / (3 100) = 1 rad/s,
    // clockwise on screen, as a ball rolling to the right turns. (The book's m r^2 / 12,
    // used as if it were 1/I, would give jT = 15 / (1/3 + 100 25) and w = 1.5 rad/s.)
    const BallSlidingOntoFloor slide(false);
    const engine::Circle& ball = slide.ball;
    CHECK_THAT(ball.velocity().x, test::near(25, kHandWorked));
    CHECK_THAT(ball.velocity().y, test::near(0, kHandWorked));
    CHECK_THAT(ball.angularVelocity(), test::near(1, kHandWorked));
    test::expectEqual("the ball's inverse inertia 1/I: a solid disc, 2 / (m r^2)",
                      Approx(2.0 / (3 * 100)).epsilon(1e-15), ball.invInertia());
}

TEST_CASE("angular impulse: lever arms reach from the corrected centre to the uncorrected contact (kept)") {
    // The same ball with positional correction on. The first pass moves it 0.8 of its
    // 1 px overlap up before the impulse, but the contact point stays where the
    // collision test found it, at the old lowest point: the arm is (0, 10.8), not
    // (0, 10). So jT = 15 / (1/3 + 10.8^2 2 / 300) and w = 10.8 jT 2 / 300.
    const BallSlidingOntoFloor slide(true);
    const engine::Circle& ball = slide.ball;
    const double arm = 10.8;
    const double jT = 15 / (1.0 / 3 + arm * arm * 2 / 300);
    CHECK_THAT(ball.velocity().x, test::near(30 - jT / 3, kHandWorked));
    CHECK_THAT(ball.angularVelocity(), test::near(arm * jT * 2 / 300, kHandWorked));
    // measurably not the exact arm's 1 rad/s
    test::expectAbove("|w - 1 rad/s|: measurably not the exact arm's 1 rad/s (the arm reaches the uncorrected contact)",
                      0.02, std::abs(ball.angularVelocity() - 1));
}

TEST_CASE("angular impulse: friction uses the slide from before the normal impulse (kept)") {
    // A 20 x 20 box of mass 1 turned by pi/6 lands on a static floor on its lowest
    // corner, at r = (10 (sqrt 3 - 1) / 2, 10 (sqrt 3 + 1) / 2) from its centre, 0.5 px
    // deep, moving (20, 30), not turning. e = 0.5, mu = 0.5, 1/I = 12 / 800;
    // positional correction off, so the arm is exactly r.
    const double sqrt3 = std::sqrt(3.0);
    const Vec2 arm{10 * (sqrt3 - 1) / 2, 10 * (sqrt3 + 1) / 2};
    const double inv_inertia = 12.0 / 800, e = 0.5, mu = 0.5;
    test::WorldFixture page(world(false));
    page.core.add(engine::Rectangle({100, 110}, 200, 20, {.mass = 0, .friction = 1, .restitution = 1}));
    engine::Rectangle& box = page.core.add(engine::Rectangle({100, 100.5 - arm.y}, 20, 20, {1, mu, e}));
    box.rotate(std::numbers::pi / 6);
    box.setVelocity({20, 30});
    page.steps(1);

    // Normal n = (0, -1): r x n = -r.x.
    const double jN = (1 + e) * 30 / (1 + arm.x * arm.x * inv_inertia);
    const double w_after_normal = -arm.x * jN * inv_inertia;
    // Tangent t = (-1, 0): r x t = r.y. The book slides at 20 px/s, the contact's
    // speed along the floor before the normal impulse ...
    const double response = 1 + arm.y * arm.y * inv_inertia;
    const double jT = (1 + e) * 20 * mu / response;
    CHECK_THAT(box.velocity().x, test::near(20 - jT, kHandWorked));
    CHECK_THAT(box.angularVelocity(), test::near(w_after_normal + arm.y * jT * inv_inertia, kHandWorked));
    // ... while after it the corner slides at 20 - w r.y, more than twice as fast,
    // which would have called for a much larger friction impulse.
    const double slide_after = 20 - w_after_normal * arm.y;
    const double jT_after = (1 + e) * slide_after * mu / response;
    test::expectAbove("the corner's sliding speed after the normal impulse, px/s", 40, slide_after);
    test::expectAbove("how far the box's vx is from the friction the later slide would call for, px/s", 5,
                      std::abs(box.velocity().x - (20 - jT_after)));
}

TEST_CASE("angular impulse: a disc rolls down a slope at 2/3 g sin(slope), making no energy") {
    // Rolling without slipping, a solid disc (I = m r^2 / 2) speeds up at
    // g sin(a) / (1 + I / (m r^2)) = 2/3 g sin(a), and friction does no work. With mu = 1
    // and e = 0 the book's friction impulse is exactly the one that stops the slip, so
    // the ball rolls. Gravity 100 px/s^2 to roll far enough in 3 s.
    constexpr double kSlope = 0.3, kGravity = 100, kRadius = 20, kMass = 2;
    test::WorldFixture page(world(true, {0, kGravity}));
    const engine::PhysicalAttributes grippy_dead_static{.mass = 0, .friction = 1, .restitution = 0};
    engine::Rectangle& slope = page.core.add(engine::Rectangle({400, 300}, 800, 20, grippy_dead_static));
    slope.rotate(kSlope);
    const Vec2 up_out{std::sin(kSlope), -std::cos(kSlope)};  // the slope's top face normal
    const Vec2 downhill{std::cos(kSlope), std::sin(kSlope)};
    const Vec2 start = Vec2{400, 300} + up_out * (10 + kRadius - 0.01) - downhill * 200;
    engine::Circle& ball = page.core.add(engine::Circle(start, kRadius, {kMass, 1, 0}));

    // A solid disc's inertia, worked out here rather than read from the engine: the
    // energy must add up with the true one.
    const double inertia = kMass * kRadius * kRadius / 2;
    const auto energy = [&] {
        const Vec2 v = ball.velocity();
        const double w = ball.angularVelocity();
        // +y is down, so height is -y.
        return kMass * v.dot(v) / 2 + inertia * w * w / 2 - kMass * kGravity * ball.center().y;
    };
    const double start_energy = energy();
    double most_gained = 0;
    double speed_at_1s = 0;
    for (int step = 1; step <= 180; ++step) {
        page.steps(1);
        most_gained = std::max(most_gained, energy() - start_energy);
        if (step == 60) speed_at_1s = ball.velocity().dot(downhill);
    }
    const double speed_at_3s = ball.velocity().dot(downhill);
    const double acceleration = (speed_at_3s - speed_at_1s) / 2;
    test::expectEqual("the rolling disc's acceleration down the slope, px/s^2: 2/3 g sin(slope)",
                      Approx(2.0 / 3 * kGravity * std::sin(kSlope)).epsilon(0.01), acceleration);
    // rolling, not sliding
    test::expectEqual("w r at 3 s, px/s: the speed down the slope (rolling, not sliding)",
                      Approx(speed_at_3s).epsilon(0.01), ball.angularVelocity() * kRadius);
    // Energy made would be a bug; the passes' small position fixes may shift a little.
    const double height_lost = (ball.center() - start).dot(downhill) * std::sin(kSlope);
    test::expectAtMost("the most energy gained while rolling: at most 1e-3 of the energy released",
                       1e-3 * kMass * kGravity * height_lost, most_gained);
    WARN("rolling disc: " << acceleration << " px/s^2 (2/3 g sin a = " << 2.0 / 3 * kGravity * std::sin(kSlope)
                          << "), most energy gained " << most_gained << " of " << kMass * kGravity * height_lost
                          << " released");
}

TEST_CASE("angular impulse: a resting box rocks a little and never quite settles (one contact point, kept)") {
    // The collision test gives one contact point, at the deepest corner, so every
    // normal impulse on a resting box also turns it a little, and the next step the
    // other corner is deepest. The turns stay tiny, but they do not die out.
    test::WorldFixture page(test::world(true));
    page.core.add(engine::Rectangle({400, 400}, 800, 20, {.mass = 0}));
    engine::Rectangle& box = page.core.add(engine::Rectangle({300, 380}, 40, 20));
    page.steps(9'000);
    double turn = 0, spin = 0;
    for (int step = 0; step < 1'000; ++step) {
        page.steps(1);
        turn = std::max(turn, std::abs(box.angle()));
        spin = std::max(spin, std::abs(box.angularVelocity()));
    }
    // rad: a twentieth of a degree, invisible
    test::expectBelow("the resting box's largest |angle| over 1,000 steps, rad: below a twentieth of a degree", 1e-3,
                      turn);
    // rad/s: still rocking after 150 s
    test::expectAbove("the resting box's largest |angular velocity|, rad/s: still rocking after 150 s", 1e-6, spin);
    WARN("resting box after 150 s: angle up to " << turn << " rad, angular velocity up to " << spin << " rad/s");
}

}  // namespace angular_impulse_test
