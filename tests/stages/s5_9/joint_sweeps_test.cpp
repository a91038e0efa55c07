// Stage 5.9's joints on scenes they were not built on (README.md, "What the tests show":
// the sweeps). The stage tests (s5_9_test.cpp) each take one scene at one gravity and
// one size; here every kind of joint runs a handful of points spread over gravity (50 to
// 2000 px/s^2), sizes (10 to 200 px), mass ratios (1:1 to 100:1), iterations (8 to 32)
// and the world's joint_hertz (0: hard, with the positional passes; 60 Hz: soft), and
// each point is judged against a number worked out in closed form:
//   - a pendulum's period at 5 degrees, 2 pi sqrt(I_pin / (m g d)), and its energy;
//   - a hanging chain's stretch, and the force at each pin, the weight below it;
//   - a spring's period (implicit Euler's own, in closed form) and its sag m g / k;
//   - a rope hanging at its longest, pulling with the weight below it;
//   - a slider on a slope, sliding g sin(theta) t^2 / 2 along its axis.
// Each sweep prints its table (build/s5_9_tests "[joint_sweeps]"), the README's.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

#include "circle.h"
#include "joint_measures.h"
#include "joints.h"
#include "rectangle.h"
#include "world_fixture.h"

namespace s5_9_joint_sweeps_test {

using engine::Vec2;

namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kDt = 1.0 / 60.0;  // s, the book's step
constexpr engine::PhysicalAttributes kStatic{.mass = 0.0};
// Box2D v3's soft joints (README.md, "Soft constraints"): the world's joint_hertz on.
constexpr double kSoftHertz = 60.0;

// The world of a sweep's point: the sequential impulse solver, `gravity` down, nothing
// removed at the canvas's edge, no sleep; `iterations` velocity iterations and the
// world's joints hard (joint_hertz 0) or soft.
engine::WorldSettings sweepWorld(double gravity, int iterations, double joint_hertz) {
    engine::WorldSettings world = s5_9_measures::jointWorld(gravity);
    world.velocity_iterations = iterations;
    world.joint_hertz = joint_hertz;
    return world;
}

using s5_9_measures::allFinite;
using s5_9_measures::bodyOf;
using s5_9_measures::energy;
using s5_9_measures::largestSeparation;
using s5_9_measures::separationOf;

std::string hardOrSoft(double joint_hertz) { return joint_hertz == 0.0 ? "hard" : "soft"; }

// w^2 of the spring a soft row is, w = 2 pi f, f the world's joint_hertz as the step
// caps it (jointHertz, joints.h).
double omegaSquared(double joint_hertz) {
    engine::WorldSettings world;
    world.joint_hertz = joint_hertz;
    const double w = 2 * kPi * engine::jointHertz(world, kDt);
    return w * w;
}

// How far the load of a soft chain hangs below where it was put, at rest: `links` links
// of mass 1 hung from a post, a load of mass `ratio` below. Each pin is a spring
// stretched by the weight below it over m w^2, m its row's effective mass along the
// chain (no turn: the arms are along it): 1 for the top pin (a link on the post), 1/2
// between two links, ratio / (1 + ratio) for the last.
double softChainSag(int links, double ratio, double gravity, double joint_hertz) {
    const double w2 = omegaSquared(joint_hertz);
    double sag = (links + ratio) * gravity / w2;
    for (int k = 1; k < links; ++k) sag += (links - k + ratio) * gravity / (0.5 * w2);
    return sag + ratio * gravity / (ratio / (1 + ratio) * w2);
}

}  // namespace

// ---------------------------------------------------------------------------------------
// Pendulums. A body hung from a static post by a pin d px above its centre, released at
// a = 5 degrees: at small amplitude it swings with T0 = 2 pi sqrt(I_pin / (m g d)),
// I_pin = I + m d^2 (the parallel axis theorem), and to the next order T0 (1 + a^2 / 16)
// (+0.05 % at 5 degrees). Two bobs: a disc of radius d / 4 on a massless rod (the pin d
// from its centre; I = m r^2 / 2), and a compound pendulum, a bar d x 4 px pinned at one
// end (d = its half length... here the bar is 2d long: I = m ((2d)^2 + 4^2) / 12).
//
// Tolerances. The step is symplectic Euler, whose oscillator of frequency w runs at
// w' = (2 / h) asin(w h / 2) = w (1 + (w h)^2 / 24 + ...): its period is short by
// (w h)^2 / 24 of itself (0.006 % at w = 2.2 /s, 0.17 % at w = 12 /s, the sweep's
// extremes), so the expected period is T0 (1 + a^2 / 16) (1 - (w h)^2 / 24). The period
// is read from the bob's crossings of the vertical below the pin, each interpolated
// linearly between two steps: near the bottom the bob moves in a straight line at
// nearly constant speed, so a crossing errs by well under 10^-3 of a step, 10^-5 of the
// shortest period. Each point must be within 0.02 % of it: what is left for the joint.
// The energy: symplectic Euler's swings by about w h of the swing's energy within a
// period, and the mean over the first half period and over the last shows what stays.
// One loss stays, first order in h: each step the velocity is made tangent to
// the circle where the step starts, and the step's straight line leaves it along a
// tangent turned by v h / d from the next one, so the solver takes the part of the
// velocity across it, a share (v h / d)^2 of the kinetic energy each step; summed over
// a period that is about (3 / 4) pi a^2 w h of the swing's energy (0.2 % here at most)
// (a soft pin, joint_hertz > 0, once kept a velocity g h / a2 down it, which drained a
// further u T / d a period: README.md, "Soft constraints"; no more). The bound is that
// summed over the two periods seen, doubled (it is a rough sum).
// The pin's gap: hard, under 0.01 px (the positional passes close it). Soft, the pin
// holds the bob only where it has opened to pull with its spring (k = m w^2 on the
// row's effective mass: along the arm the bob's m, across it m I / I_pin, which the
// pull across it, m g sin(theta) I / I_pin, also has), so the gap is under
// g (1 + 2 (1 - cos a) + sin a) / w^2 (weight, the swing's v^2 / d, the pull across);
// the bob is let go on a pin with no pull yet, and a spring loaded at once stretches
// to at most twice that: the bound.
TEST_CASE("s5_9: pendulums over gravity, size, shape, iterations and stiffness swing at 2 pi sqrt(I / (m g d))",
          "[joint_sweeps]") {
    struct Point {
        double gravity;  // px/s^2
        double d;        // px, from the pin to the centre of mass
        bool disc;       // a disc on a rod, or a bar pinned at its end
        int iterations;
        double joint_hertz;
    };
    const Point points[] = {
        {50, 10, true, 8, 0},
        {300, 50, true, 8, 0},
        {2000, 200, true, 8, 0},
        {300, 100, false, 8, 0},
        {2000, 10, false, 32, 0},
        {50, 100, true, 32, kSoftHertz},
        {300, 50, false, 16, kSoftHertz},
        {2000, 50, true, 8, kSoftHertz},
        {2000, 200, false, 32, kSoftHertz},
    };
    constexpr double kAmplitude = 5.0 * kPi / 180.0;
    std::printf(
        "pendulum sweep: g px/s^2, d px, bob, iterations, joints | T0 s, measured s, off T0 (1 - (w h)^2 / 24) %%, "
        "energy bound %%, drift %% of the swing, largest gap px\n");
    for (const Point& point : points) {
        INFO("g " << point.gravity << ", d " << point.d << ", " << (point.disc ? "disc" : "bar") << ", "
                  << point.iterations << " iterations, " << hardOrSoft(point.joint_hertz));
        test::WorldFixture page(sweepWorld(point.gravity, point.iterations, point.joint_hertz));
        const Vec2 pin{400, 50};
        engine::RigidShape& post = page.core.add(engine::Circle(pin, 2, kStatic));
        const Vec2 hanging = pin + Vec2{std::sin(kAmplitude), std::cos(kAmplitude)} * point.d;
        engine::RigidShape& bob =
            point.disc ? static_cast<engine::RigidShape&>(page.core.add(engine::Circle(hanging, point.d / 4)))
                       : page.core.add(engine::Rectangle(hanging, 2 * point.d, 4));
        if (!point.disc) bob.rotate(kPi / 2 - kAmplitude);  // the bar along the line to the pin
        page.core.join(engine::pinAt(engine::JointType::revolute, post, bob, pin));
        const double inertia = 1.0 / bob.invInertia() + bob.mass() * point.d * point.d;
        const double w = std::sqrt(bob.mass() * point.gravity * point.d / inertia);
        const double t0 = 2 * kPi / w * (1.0 + kAmplitude * kAmplitude / 16.0);
        const double t_step = t0 * (1.0 - (w * kDt) * (w * kDt) / 24.0);  // symplectic Euler's own
        const double loss_bound = 2.0 * 2.0 * 0.75 * kPi * kAmplitude * kAmplitude * w * kDt;
        const double gap_bound = point.joint_hertz > 0
                                     ? 2 * point.gravity * (1 + 2 * (1 - std::cos(kAmplitude)) + std::sin(kAmplitude)) /
                                           omegaSquared(point.joint_hertz)
                                     : 0.01;
        const double swing = bob.mass() * point.gravity * point.d * (1.0 - std::cos(kAmplitude));

        // Crossings of the vertical, either way: the first at T / 4, then every T / 2.
        // Five of them: two whole periods, 2.25 T of swinging.
        std::vector<double> crossings, energies;
        double last_x = bob.center().x - pin.x, worst_gap = 0.0;
        for (int step = 1; crossings.size() < 5 && step < 4 * static_cast<int>(t0 / kDt); ++step) {
            page.steps(1);
            energies.push_back(energy(page.core));
            worst_gap = std::max(worst_gap, largestSeparation(page.core));
            const double x = bob.center().x - pin.x;
            if ((last_x < 0) != (x < 0)) crossings.push_back(step - 1 + last_x / (last_x - x));
            last_x = x;
        }
        REQUIRE(crossings.size() == 5);
        const double period = (crossings.back() - crossings.front()) / 2.0 * kDt;
        const auto meanBetween = [&](double from, double to) { return s5_9_measures::meanBetween(energies, from, to); };
        const double drift = meanBetween(crossings[3], crossings[4]) - meanBetween(crossings[0], crossings[1]);
        const double off = period / t_step - 1.0;
        std::printf("  %6.0f %5.0f %-4s %2d %s | %.4f %.4f %+.3f (%.3f) %+.3f %.2e\n", point.gravity, point.d,
                    point.disc ? "disc" : "bar", point.iterations, hardOrSoft(point.joint_hertz).c_str(), t0, period,
                    off * 100, loss_bound * 100, drift / swing * 100, worst_gap);
        INFO("period " << period << " s against " << t_step << " s (" << off * 100 << " %); energy drift "
                       << drift / swing * 100 << " % of the swing's (bound " << loss_bound * 100 << " %); largest gap "
                       << worst_gap << " px");
        CHECK(std::abs(off) < 2e-4);
        CHECK(std::abs(drift) < loss_bound * swing);
        CHECK(worst_gap < gap_bound);
        CHECK(allFinite(page.core));
    }
}

// ---------------------------------------------------------------------------------------
// Hanging chains. Ten links of length l (l x l / 5 px, at least 2 px thick, mass 1 each)
// hang straight down from a static post, pinned end to end, with a disc of `ratio`
// times a link's mass (radius l / 2) pinned to the last, put where they hang and let go.
// At rest each pin holds the weight of all below it: the pin above link k (0 at the
// top) pulls with (10 - k + ratio) m g, the top pin with the whole chain's weight; a
// pin's total impulse in a step (warm started from the step before, joints.h) is that
// force times dt. The chain is put at rest with no impulse yet, so the first step's
// iterations carry only part of the load's weight up the chain (a pull crosses it one
// pin an iteration, and a heavy end needs many): the load drops, bounces, and the
// totals carried from step to step settle on the weights. Judged in the 5th second.
//
// Tolerances, from the settling each point shows (the printed table):
//   - up to 10:1, hard: each pin's force within 1 % of the weight below it, and the
//     chain's stretch (how much further the load hangs than where it was put) under
//     10^-4 of its length: at 8 iterations the forces' error falls about 6 times a
//     second (1:1: 100 times), 8e-4 and 4.9e-5 of the length in the 5th second at 10:1
//     (7.4e-4 and 4.5e-5 with the joints met in the order they were made);
//   - 100:1, hard, 32 iterations: 5 % and 3 % (2e-2 and 1.8e-2 in the 5th second): the
//     positional passes take the load's first drop back out at some 30 % a second, as
//     Gauss-Seidel on positions crosses a 100:1 chain as slowly as on velocities (at
//     8 and 16 iterations the forces are still 10 % or more out after 5 s);
//   - soft (joint_hertz 60 Hz, capped to 30, 32 iterations): forces within 1 %, and the
//     stretch within 1 % over its springs' (softChainSag: a soft pin holds its load
//     where its error pulls with it).
// And in every case the forces' error in the 5th second is under a quarter of the 2nd's:
// settling, not merely bounded.
TEST_CASE("s5_9: hanging chains over link length, mass ratio, gravity and iterations: pin forces and stretch",
          "[joint_sweeps]") {
    struct Point {
        double link;   // px
        double ratio;  // the load's mass over a link's
        double gravity;
        int iterations;
        double joint_hertz;
        double force_bound, stretch_bound;  // shares of the weight below and of 10 l
    };
    const Point points[] = {
        {10, 1, 300, 8, 0, 0.01, 1e-4},         {20, 10, 300, 8, 0, 0.01, 1e-4},    {200, 10, 50, 8, 0, 0.01, 1e-4},
        {50, 10, 2000, 16, 0, 0.01, 1e-4},      {50, 100, 2000, 32, 0, 0.05, 0.03}, {10, 100, 300, 32, 0, 0.05, 0.03},
        {50, 10, 300, 32, kSoftHertz, 0.01, 0},  // soft: the stretch bound from softChainSag
        {10, 1, 50, 32, kSoftHertz, 0.01, 0},
    };
    constexpr int kLinks = 10;
    std::printf(
        "chain sweep: link px, load ratio, g px/s^2, iterations, joints | pin forces off in the 2nd s, "
        "5th s (bound), stretch / length in the 5th s (bound)\n");
    for (const Point& point : points) {
        INFO("link " << point.link << " px, load " << point.ratio << ":1, g " << point.gravity << ", "
                     << point.iterations << " iterations, " << hardOrSoft(point.joint_hertz));
        test::WorldFixture page(sweepWorld(point.gravity, point.iterations, point.joint_hertz));
        const Vec2 top{400, 50};
        const engine::RigidShape* before = &page.core.add(engine::Circle(top, 2, kStatic));
        for (int i = 0; i < kLinks; ++i) {
            const engine::RigidShape& link = page.core.add(
                engine::Rectangle(top + Vec2{0, point.link * (i + 0.5)}, std::max(2.0, point.link / 5), point.link));
            page.core.join(engine::pinAt(engine::JointType::revolute, *before, link, top + Vec2{0, point.link * i}));
            before = &link;
        }
        const Vec2 load_start = top + Vec2{0, point.link * kLinks + point.link / 2};
        const engine::RigidShape& load =
            page.core.add(engine::Circle(load_start, point.link / 2, {.mass = point.ratio}));
        page.core.join(engine::pinAt(engine::JointType::revolute, *before, load, top + Vec2{0, point.link * kLinks}));
        REQUIRE(page.core.joints().all().size() == kLinks + 1);
        const double stretch_bound =
            point.joint_hertz > 0
                ? 1.01 * softChainSag(kLinks, point.ratio, point.gravity, point.joint_hertz) / (kLinks * point.link)
                : point.stretch_bound;
        // Each second's largest error of any pin's force, and of the load's place.
        std::vector<double> force_off(5, 0.0), stretch(5, 0.0);
        for (int step = 0; step < 5 * 60; ++step) {
            page.steps(1);
            const auto second = static_cast<std::size_t>(step / 60);
            const std::vector<engine::Joint>& pins = page.core.joints().all();
            for (std::size_t k = 0; k < pins.size(); ++k) {
                const double below = (static_cast<double>(kLinks - k) + point.ratio) * point.gravity;
                const Vec2 force = pins[k].impulses.point * (1.0 / kDt);
                force_off[second] = std::max(force_off[second], force.distance({0, -below}) / below);
            }
            stretch[second] = std::max(stretch[second], load.center().distance(load_start) / (kLinks * point.link));
        }
        std::printf("  %5.0f %5.0f %6.0f %2d %s | %.1e %.1e (%.0e) %.1e (%.0e)\n", point.link, point.ratio,
                    point.gravity, point.iterations, hardOrSoft(point.joint_hertz).c_str(), force_off[1], force_off[4],
                    point.force_bound, stretch[4], stretch_bound);
        INFO("pin forces off by " << force_off[1] << " in the 2nd second, " << force_off[4] << " in the 5th; stretch "
                                  << stretch[4] << " of the length");
        CHECK(force_off[4] < point.force_bound);
        CHECK(force_off[4] < 0.25 * force_off[1]);
        CHECK(stretch[4] < stretch_bound);
        CHECK(allFinite(page.core));
    }
}

// ---------------------------------------------------------------------------------------
// Springs. A distance joint with "hertz" f and "damping_ratio" zeta is the implicit
// spring of README.md, "Soft constraints": on its effective mass m (the mass a unit
// impulse along it sees: a disc held at its centre by a static post is its own mass m;
// two discs, the reduced mass m1 m2 / (m1 + m2)) it is k = m w^2, c = 2 m zeta w,
// w = 2 pi f. Two scenes:
//   - a disc hung from a post by a spring of rest length L, let go at that length: it
//     sags to m g / k = g / w^2 below it (independent of m: the row's mass is m);
//   - two discs in no gravity, the spring stretched by 20 px: they bounce at f at any
//     mass ratio, about a centre of mass that never moves.
// The step solves the spring exactly in its first iteration (one row, warm started or
// not: joints.h), so each step is implicit Euler's: with e the spring's stretch past its
// rest (or sag) and v its speed, v' = (v - h w^2 e) / D, e' = e + h v', D = 1 + 2 zeta w h
// + (w h)^2. That map's eigenvalues are r e^{+-i theta}, r = 1 / sqrt(D), cos theta =
// (1 + (1 - (w h)^2) / D) sqrt(D) / 2: the spring's period in the step is 2 pi h /
// theta, longer than 1 / (f sqrt(1 - zeta^2)) by about (w h)^2 / 3 (1.5 % at 2 Hz, 20 %
// at 8 Hz, which is why the bound is on the step's own period), and each period scales
// the bounce by r^(T / h).
//
// Implicit Euler damps even with zeta = 0 (r < 1): 15 % of the bounce a period at
// 0.5 Hz, half of it at 2 Hz. So the sag is read where the bounce has died out: after
// as many periods as the closed form r^(T / h) needs to leave 10^-4 of the bounce.
//
// Tolerances. The period, from the first five crossings of the rest (or sag) line, each
// interpolated between two steps: within 0.5 % of the step's closed form (the bounce is
// a sine sampled 9 to 120 times a period; a linear interpolation of a crossing errs by
// the sine's curvature there, which is zero at the crossing itself; measured 0.03 % at
// most). The sag: within 0.1 % of g / w^2, ten times what 10^-4 of the bounce leaves.
// The free discs: back at their rest length within 0.01 px (their 20 px stretch times
// 10^-4, doubled), their momentum within 1e-9 of 0 and their centre of mass within
// 1e-9 px of where it was (the joint's impulses come in equal and opposite pairs).
namespace {

struct SpringOscillator {
    double hertz;
    double damping_ratio;
    // The step's own period, s, and how much of the bounce is left after one.
    double period() const {
        const double w = 2 * kPi * hertz, wh = w * kDt;
        const double d = 1.0 + 2.0 * damping_ratio * wh + wh * wh;
        const double cos_theta = (1.0 + (1.0 - wh * wh) / d) * std::sqrt(d) / 2.0;
        return 2 * kPi * kDt / std::acos(cos_theta);
    }
    double leftAfterPeriod() const {
        const double w = 2 * kPi * hertz, wh = w * kDt;
        return std::pow(1.0 + 2.0 * damping_ratio * wh + wh * wh, -0.5 * period() / kDt);
    }
};

// The period from a signal's crossings of `level`, either way, each interpolated.
struct Crossings {
    std::vector<double> at;  // steps
    std::vector<double> values;
    double level = 0.0;
    double last = 0.0;
    void add(double value) {
        if (!values.empty() && (last < level) != (value < level)) {
            at.push_back(static_cast<double>(values.size()) - 1.0 + (level - last) / (value - last));
        }
        values.push_back(value);
        last = value;
    }
    double period() const { return (at.back() - at.front()) / static_cast<double>(at.size() - 1) * 2.0 * kDt; }
};

}  // namespace

TEST_CASE("s5_9: springs over frequency, damping, gravity, length and mass ratio: the period and the sag m g / k",
          "[joint_sweeps]") {
    struct Point {
        double hertz;
        double damping_ratio;
        double gravity;  // 0: two free discs
        double length;   // px, the rest length
        double mass;     // the hung disc's, or the first free disc's (the second's is 1)
    };
    const Point points[] = {
        {0.5, 0.0, 50, 50, 1}, {2.0, 0.05, 300, 100, 1}, {8.0, 0.0, 2000, 10, 10}, {2.0, 0.3, 2000, 200, 0.1},
        {2.0, 0.0, 0, 50, 1},  {4.0, 0.05, 0, 100, 100}, {1.0, 0.0, 0, 200, 10},
    };
    std::printf(
        "spring sweep: f Hz, zeta, g px/s^2 (0: two discs), rest px, mass | step's period s (1 / f), "
        "measured s, off %%, sag g / w^2 px, measured px, off %%, bounce left a period (closed form)\n");
    for (const Point& point : points) {
        INFO(point.hertz << " Hz, zeta " << point.damping_ratio << ", g " << point.gravity << ", rest " << point.length
                         << " px, mass " << point.mass);
        test::WorldFixture page(sweepWorld(point.gravity, 8, 0.0));
        const SpringOscillator oscillator{point.hertz, point.damping_ratio};
        const double w = 2 * kPi * point.hertz;
        const bool hung = point.gravity > 0;
        // Hung: a static post and the disc at the rest length below it. Free: the spring
        // stretched by 20 px between two discs.
        const Vec2 top{400, 50};
        const double start = hung ? point.length : point.length + 20.0;
        engine::RigidShape& a =
            page.core.add(engine::Circle(top, 4, hung ? kStatic : engine::PhysicalAttributes{.mass = point.mass}));
        engine::RigidShape& b =
            page.core.add(engine::Circle(top + Vec2{0, start}, 4, {.mass = hung ? point.mass : 1.0}));
        engine::JointDefinition spring = engine::linkBetween(a, b, {a.center(), b.center()});
        spring.length = point.length;
        spring.hertz = point.hertz;
        spring.damping_ratio = point.damping_ratio;
        page.core.join(spring);
        // The row's effective mass, and the stretch it holds g against (m g / k).
        const double row_mass = 1.0 / (a.invMass() + b.invMass());
        const double sag = hung ? row_mass * point.gravity / (row_mass * w * w) : 0.0;
        const Vec2 centre_of_mass = (a.center() * a.mass() * (hung ? 0.0 : 1.0) + b.center() * b.mass()) *
                                    (1.0 / ((hung ? 0.0 : a.mass()) + b.mass()));
        Crossings stretch{.level = sag};
        double momentum = 0.0, centre_moved = 0.0;
        const int most_steps = static_cast<int>(4.0 * oscillator.period() / kDt);
        for (int step = 0; stretch.at.size() < 5 && step < most_steps; ++step) {
            page.steps(1);
            stretch.add(b.center().distance(a.center()) - point.length);
            if (!hung) {
                momentum = std::max(momentum, (a.velocity() * a.mass() + b.velocity() * b.mass()).length());
                const Vec2 now = (a.center() * a.mass() + b.center() * b.mass()) * (1.0 / (a.mass() + b.mass()));
                centre_moved = std::max(centre_moved, now.distance(centre_of_mass));
            }
        }
        REQUIRE(stretch.at.size() == 5);
        const double period = stretch.period();
        const double period_off = period / oscillator.period() - 1.0;
        // Where the bounce ends: 10^-4 of it left, by the closed form's decay a period.
        const double periods = std::log(1e-4) / std::log(oscillator.leftAfterPeriod());
        page.steps(static_cast<int>(std::ceil(periods * oscillator.period() / kDt)));
        const double sag_seen = b.center().distance(a.center()) - point.length;
        std::printf("  %4.1f %4.2f %5.0f %4.0f %5.1f | %.4f (%.4f) %.4f %+.3f %8.3f %8.3f %+.3f %.4f\n", point.hertz,
                    point.damping_ratio, point.gravity, point.length, point.mass, oscillator.period(),
                    1.0 / point.hertz, period, period_off * 100, sag, sag_seen,
                    hung ? (sag_seen / sag - 1.0) * 100 : 0.0, oscillator.leftAfterPeriod());
        INFO("period " << period << " s against the step's " << oscillator.period() << " s (" << period_off * 100
                       << " %); sag " << sag_seen << " px against " << sag << " px");
        CHECK(std::abs(period_off) < 5e-3);
        if (hung) {
            CHECK(std::abs(sag_seen - sag) < 1e-3 * sag);
        } else {
            CHECK(std::abs(sag_seen) < 0.01);
            CHECK(momentum < 1e-9);
            CHECK(centre_moved < 1e-9);
        }
        CHECK(allFinite(page.core));
    }
}

// ---------------------------------------------------------------------------------------
// Ropes. A disc of mass 1 hangs from a post by a rope of at most L px (a distance joint
// with max_length and no spring: slack up to L), and a second disc of `ratio` times its
// mass hangs from the first by a rope of at most L; both let go with the ropes at 60 %
// of their length: they fall, the ropes catch them (a limit: it stops the ends from
// parting further, and never pulls them closer) and they hang. Hanging, each rope is at
// its longest, and pulls with the weight below it: the upper (1 + ratio) m g, the lower
// ratio m g; the rope's total impulse on its limit in a step is that force times dt.
//
// Tolerances, judged over the 5th second: the length within 0.2 px of L and the force
// within 1 % of the weight below. Up to 10:1 both are reached to rounding within 2 s;
// at 100:1 Gauss-Seidel's iterations hand the heavy disc's weight up through the light
// one slowly (a share of the light one's mass over the heavy one's an iteration), and
// the catch's jolt takes 4 s to settle at 8 iterations (0.14 px and 0.6 % left in the
// 5th second, the bounds' tightest point), 2 at 16, 1.5 at 32.
TEST_CASE("s5_9: ropes over length, mass ratio, gravity and iterations hang at their longest, pulling the weight",
          "[joint_sweeps]") {
    struct Point {
        double length;
        double ratio;
        double gravity;
        int iterations;
    };
    const Point points[] = {{10, 1, 50, 8},     {50, 10, 300, 8},  {200, 100, 2000, 8},
                            {50, 100, 300, 32}, {200, 1, 2000, 8}, {10, 100, 2000, 16}};
    std::printf(
        "rope sweep: max px, lower : upper mass, g px/s^2, iterations | in the 5th s: largest length off px, "
        "largest force off / weight below\n");
    for (const Point& point : points) {
        INFO("rope " << point.length << " px, " << point.ratio << ":1, g " << point.gravity << ", " << point.iterations
                     << " iterations");
        test::WorldFixture page(sweepWorld(point.gravity, point.iterations, 0.0));
        const Vec2 top{400, 50};
        const double radius = std::min(4.0, point.length / 4);
        const engine::RigidShape& post = page.core.add(engine::Circle(top, 2, kStatic));
        const engine::RigidShape& upper = page.core.add(engine::Circle(top + Vec2{0, 0.6 * point.length}, radius));
        const engine::RigidShape& lower =
            page.core.add(engine::Circle(top + Vec2{0, 1.2 * point.length}, radius, {.mass = point.ratio}));
        for (const auto& [from, to] : {std::pair{&post, &upper}, std::pair{&upper, &lower}}) {
            engine::JointDefinition rope = engine::linkBetween(*from, *to, {from->center(), to->center()});
            rope.length_range = engine::JointRange{0.0, point.length};
            page.core.join(rope);
        }
        page.steps(4 * 60);
        double length_off = 0.0, force_off = 0.0;
        for (int step = 0; step < 60; ++step) {
            page.steps(1);
            const std::vector<engine::Joint>& ropes = page.core.joints().all();
            length_off = std::max({length_off, std::abs(upper.center().distance(post.center()) - point.length),
                                   std::abs(lower.center().distance(upper.center()) - point.length)});
            force_off = std::max({force_off,
                                  std::abs(ropes[0].impulses.upper / kDt / ((1.0 + point.ratio) * point.gravity) - 1),
                                  std::abs(ropes[1].impulses.upper / kDt / (point.ratio * point.gravity) - 1)});
        }
        std::printf("  %4.0f %4.0f %5.0f %2d | %.1e %.1e\n", point.length, point.ratio, point.gravity, point.iterations,
                    length_off, force_off);
        INFO("ropes off their length by " << length_off << " px, forces off the weight below by " << force_off);
        CHECK(length_off < 0.2);
        CHECK(force_off < 0.01);
        CHECK(allFinite(page.core));
    }
}

// ---------------------------------------------------------------------------------------
// Sliders. A box on a prismatic joint along an axis theta below the horizontal, from a
// static post, let go at rest: the axis takes every force across it, so the box slides
// along it at g sin(theta), with no friction (a joint has none), and does not turn. The
// step's semi-implicit Euler (v += a dt, then x += v dt) has it g sin(theta) dt^2 n (n +
// 1) / 2 along after n steps: 1 s of it, the closed form's g sin(theta) / 2 times
// (1 + dt). Some boxes hang off their anchor (the axis passes through a point of the
// box away from its centre): gravity still pulls at the centre, the joint's turn row
// keeps the angle, and the slide is the same.
//
// Tolerances. Along the axis: within 1e-6 of the step's own distance (the across row
// pushes only across the axis, and the angle row only turns, so nothing in the
// iterations pushes along it: the slide is the step's, to rounding); within dt (1.7 %)
// of g sin(theta) t^2 / 2. Across the axis and the angle, hard: under 1e-6 px and 1e-6
// rad (the positional passes put the anchor back on the axis after every step). Soft:
// each row holds its force F where its error is F / (m w^2), m its own effective mass.
// The across row takes gravity's part across the axis, m g_n, at the anchor, arm r
// from the centre (c = r x n); the angle row the torque that leaves, -m g_n c. So the
// across row's error is g_n (1 + m c^2 / I) / w^2, the angle's -m g_n c / (I w^2), and
// the centre sits g_n (1 + 2 m c^2 / I) / w^2 across the axis: within 1e-3 of these.
TEST_CASE("s5_9: sliders over slope, gravity, box size, anchor and stiffness slide at g sin(theta) along the axis",
          "[joint_sweeps]") {
    struct Point {
        double degrees;
        double gravity;
        double width, height;  // px
        Vec2 anchor;           // from the box's centre, px
        int iterations;
        double joint_hertz;
    };
    const Point points[] = {
        {10, 300, 20, 10, {0, 0}, 8, 0},          {30, 50, 200, 40, {0, 0}, 8, 0},
        {60, 2000, 10, 10, {0, 0}, 32, 0},        {45, 300, 50, 20, {20, -8}, 8, 0},
        {30, 300, 40, 20, {0, 0}, 8, kSoftHertz}, {80, 2000, 100, 20, {-40, 0}, 16, kSoftHertz},
    };
    std::printf(
        "slider sweep: degrees, g px/s^2, box px, anchor px, iterations, joints | along px after 1 s "
        "(step's, g sin t^2 / 2), off step's, across px, angle rad\n");
    for (const Point& point : points) {
        INFO(point.degrees << " degrees, g " << point.gravity << ", box " << point.width << " x " << point.height
                           << ", anchor " << point.anchor.x << ", " << point.anchor.y << ", " << point.iterations
                           << " iterations, " << hardOrSoft(point.joint_hertz));
        test::WorldFixture page(sweepWorld(point.gravity, point.iterations, point.joint_hertz));
        const double theta = point.degrees * kPi / 180.0;
        const Vec2 axis{std::cos(theta), std::sin(theta)};  // y down: it slopes down to the right
        const Vec2 rail_point{200, 100};
        const engine::RigidShape& rail = page.core.add(engine::Circle(rail_point, 2, kStatic));
        const engine::RigidShape& box =
            page.core.add(engine::Rectangle(rail_point - point.anchor, point.width, point.height));
        engine::JointDefinition slider = engine::pinAt(engine::JointType::prismatic, rail, box, rail_point);
        slider.local_axis = axis;
        page.core.join(slider);
        constexpr int kSteps = 60;
        page.steps(kSteps);
        const Vec2 moved = box.center() - (rail_point - point.anchor);
        const double along = moved.dot(axis), across = moved.dot(Vec2{-axis.y, axis.x});
        const double pull = point.gravity * std::sin(theta);
        const double step_distance = pull * kDt * kDt * kSteps * (kSteps + 1) / 2.0;
        const double closed_form = pull / 2.0;  // 1 s
        std::printf("  %3.0f %5.0f %3.0fx%-3.0f (%3.0f,%3.0f) %2d %s | %9.4f (%9.4f, %9.4f) %+.1e %.1e %.1e\n",
                    point.degrees, point.gravity, point.width, point.height, point.anchor.x, point.anchor.y,
                    point.iterations, hardOrSoft(point.joint_hertz).c_str(), along, step_distance, closed_form,
                    along / step_distance - 1.0, across, box.angle());
        INFO("along " << along << " px (the step's " << step_distance << ", closed form " << closed_form << "), across "
                      << across << " px, angle " << box.angle());
        CHECK(std::abs(along / step_distance - 1.0) < 1e-6);
        CHECK(std::abs(along / closed_form - 1.0) < kDt + 1e-6);
        if (point.joint_hertz > 0) {
            const Vec2 normal{-axis.y, axis.x};
            const double g_n = point.gravity * normal.y, c = point.anchor.cross(normal);
            const double w2 = omegaSquared(point.joint_hertz), turning = box.mass() * box.invInertia();
            CHECK(across == Approx(g_n * (1 + 2 * turning * c * c) / w2).epsilon(1e-3));
            CHECK(box.angle() == Approx(-turning * g_n * c / w2).epsilon(1e-3).margin(1e-12));
        } else {
            CHECK(std::abs(across) < 1e-6);
            CHECK(std::abs(box.angle()) < 1e-6);
        }
        CHECK(allFinite(page.core));
    }
}

// ---------------------------------------------------------------------------------------
// Soft joints at rest (the world's joint_hertz > 0; README.md, "Soft constraints"). A
// soft row holds a steady load F (force) only where its error C has grown to make the
// spring's pull: in the step's fixed point the biased velocity is 0, and with the
// three numbers of `softness` that is C = F / (m w^2), m the row's effective mass and w
// = 2 pi f, f the world's joint_hertz as capped by the step (jointHertz, joints.h).
// A disc of mass m on a pin 50 px below a post: the pin's row along the rod has
// effective mass m (the arm is along it: no turn), and carries m g, so the bob hangs
// g / w^2 below the post's 50 px (0.0563 px at 2000 px/s^2 and 60 Hz, capped to 30 at
// 60 steps a second) and at rest. Before: the positional passes closed that sag after
// every step, and the bob kept g h / a2 = 0.516 px/s down the pin.
TEST_CASE("s5_9: a bob hanging at rest on a soft pin is at rest, g / w^2 below its pin", "[joint_sweeps]") {
    test::WorldFixture page(sweepWorld(2000, 8, kSoftHertz));
    const engine::RigidShape& post = page.core.add(engine::Circle({400, 50}, 2, kStatic));
    const engine::RigidShape& bob = page.core.add(engine::Circle({400, 100}, 10));
    page.core.join(engine::pinAt(engine::JointType::revolute, post, bob, {400, 50}));
    page.steps(120);
    const double sag = 2000 / omegaSquared(kSoftHertz);
    INFO("velocity " << bob.velocity().y << " px/s, y " << bob.center().y << " px, sag g / w^2 = " << sag << " px");
    // Rounding: a velocity of 1e-12 px/s moves the bob 1e-14 px a step.
    CHECK(std::abs(bob.velocity().y) < 1e-9);
    CHECK(bob.center().y - 100.0 == Approx(sag).epsilon(1e-6));
    CHECK(std::abs(bob.center().x - 400.0) < 1e-9);
}

// A chain of 10 links (10 x 50 px, mass 1) with a load of mass r below, hung at rest.
// The pins carry the weights below them, each as its spring stretched by F / (m w^2)
// along the chain: the top pin (a link on the post) has m = 1, a pin between two links
// 1/2, the last one r / (1 + r); so at rest the load hangs sum F / (m w^2) below its
// start (softChainSag). Released from rest with no impulses yet, the chain is loaded at once, and a
// spring loaded at once stretches to at most twice its rest stretch: every pin's gap
// stays under twice the largest rest stretch, 2 (10 + r) g / (w^2 / 2). Its bounce
// about that rest, the load's largest distance from it, must be smaller over the last
// 4 s than over the first 4 (the chain's slowest mode, the load on the pins in series,
// has a period of about 2 pi sqrt(2 * 10 r / (w^2)) = 2.9 s at 100:1 and 15 Hz); and a
// chain of 1:1 or 10:1 is back at rest within 1e-3 of the closed form. At 100:1 and
// 8 iterations a pull crosses the chain one pin an iteration (as a hard chain's, the
// chain sweep above), and that mode's damping ratio is the pins' zeta times its
// frequency over w (about 0.05): it is still swinging after 8 s. Swept over
// iterations 8 to 32, ratios 1:1 to 100:1 and joint_hertz 15 to 60 (30 and 60 both
// run at the cap of 30 at 60 steps a second). Before the fixes (README.md) the 10:1
// chain at 8 iterations and 60 Hz bounced ever higher: 3, 11, 46, 260 px a second.
TEST_CASE("s5_9: soft chains over iterations, mass ratio and joint_hertz hang at their springs' stretch",
          "[joint_sweeps]") {
    constexpr int kLinks = 10;
    constexpr double kLink = 50, kGravity = 300;
    std::printf(
        "soft chain sweep: iterations, load ratio, joint_hertz (used) | load's bounce about its rest in the first, "
        "last 4 s px | largest gap px (bound) | sag px (closed form)\n");
    for (const int iterations : {8, 16, 32}) {
        for (const double ratio : {1.0, 10.0, 100.0}) {
            for (const double hertz : {15.0, 30.0, 60.0}) {
                INFO(iterations << " iterations, load " << ratio << ":1, joint_hertz " << hertz);
                test::WorldFixture page(sweepWorld(kGravity, iterations, hertz));
                const Vec2 top{400, 50};
                const engine::RigidShape* before = &page.core.add(engine::Circle(top, 2, kStatic));
                for (int i = 0; i < kLinks; ++i) {
                    const engine::RigidShape& link =
                        page.core.add(engine::Rectangle(top + Vec2{0, kLink * (i + 0.5)}, kLink / 5, kLink));
                    page.core.join(engine::pinAt(engine::JointType::revolute, *before, link, top + Vec2{0, kLink * i}));
                    before = &link;
                }
                const Vec2 load_start = top + Vec2{0, kLink * kLinks + kLink / 2};
                const engine::RigidShape& load = page.core.add(engine::Circle(load_start, kLink / 2, {.mass = ratio}));
                page.core.join(
                    engine::pinAt(engine::JointType::revolute, *before, load, top + Vec2{0, kLink * kLinks}));
                const double w2 = omegaSquared(hertz);
                const double sag = softChainSag(kLinks, ratio, kGravity, hertz);
                const double gap_bound = 2 * (kLinks + ratio) * kGravity / (0.5 * w2);
                double bounce[2] = {0.0, 0.0};
                double widest = 0.0;
                for (int step = 0; step < 8 * 60; ++step) {
                    page.steps(1);
                    double& worst = bounce[step < 4 * 60 ? 0 : 1];
                    worst = std::max(worst, std::abs(load.center().y - load_start.y - sag));
                    widest = std::max(widest, largestSeparation(page.core));
                }
                const double settled = load.center().y - load_start.y;
                std::printf("  %2d %5.0f %4.0f (%2.0f) | %8.2e %8.2e | %6.3f (%6.3f) | %8.4f (%8.4f)\n", iterations,
                            ratio, hertz, std::sqrt(w2) / (2 * kPi), bounce[0], bounce[1], widest, gap_bound, settled,
                            sag);
                INFO("bounce " << bounce[0] << " px in the first 4 s, " << bounce[1] << " px in the last; largest gap "
                               << widest << " px; sag " << settled << " px (closed form " << sag << ")");
                CHECK(bounce[1] < bounce[0]);
                CHECK(widest < gap_bound);
                if (ratio <= 10) CHECK(settled == Approx(sag).epsilon(1e-3));
                CHECK(allFinite(page.core));
            }
        }
    }
}

}  // namespace s5_9_joint_sweeps_test
