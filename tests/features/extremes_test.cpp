// Extreme inputs for the book's finished engine (5.1 on): mass ratios of a million, shapes from
// 0.01 px to 100,000 px, speeds up to 1,000,000 px/s, steps from 1e-5 s to 0.1 s, a
// thousand shapes made at one point, 100,000 steps of the book's demo, shapes that
// coincide exactly, a world of static shapes and an empty one; then the slowest ball
// that tunnels through a thin wall.
//
// Every case runs with its numbers checked for NaN and infinity after every step, and
// states one more bound, with the physics that allows no more: kinetic energy that a
// closed system with e <= 1 cannot gain, a place a shape cannot leave (a floor, a box).
// The measured figure is printed with WARN (ctest -V shows it). Where the engine fails,
// the case pins what it does now and says so: a fix then shows up as a failing test
// to update, not as silence.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "book_scene.h"
#include "circle.h"
#include "core.h"
#include "near.h"
#include "world_measures.h"
#include "rectangle.h"
#include "closed_box.h"
#include "world_fixture.h"

namespace extremes_test {

using engine::Circle;
using engine::Rectangle;
using engine::Vec2;

namespace {

constexpr Vec2 kNoGravity{0, 0};
constexpr double kG = engine::kGravity.y;   // 20 px/s^2, down
constexpr double kDt = engine::kFrameTime;  // 1/60 s
// The book's relaxation leaves (1 - rate)^passes of an overlap that nothing else
// disturbs: 0.2^15 = 3.3e-11 of it after one step.
const double kLeftAfterOneStep = std::pow(1 - engine::kPosCorrectionRate, engine::kRelaxationCount);

// The demo's world, but every shape is kept however far it goes: these cases judge
// where shapes end up, so none may be removed on the way.
engine::WorldSettings keptWorld(Vec2 gravity, double dt = kDt) {
    engine::WorldSettings settings = engine::kBookWorld;
#if __has_include("islands.h")
    settings.sleep = false;  // 5.5: its sleep speed is in px/s, and 0.01 px balls are slow at any speed
#endif
    settings.gravity = gravity;
    settings.dt = dt;
    settings.remove_out_of_bounds = false;
    return settings;
}

// `count` steps; after each one every number must be finite, then `after_step(step)`
// may measure.
void runChecked(test::WorldFixture& page, int count, const std::function<void(int)>& after_step = {}) {
    for (int step = 1; step <= count; ++step) {
        page.steps(1);
        if (const auto bad = test::firstNotFinite(page.core)) {
            FAIL("step " << step << ": shape " << *bad << " has a NaN or an infinite number");
        }
        if (after_step) after_step(step);
    }
}

// The deepest a step can carry a falling shape into what it lands on. It arrives at
// `speed`, so its centre covers speed dt in the step that reaches the surface, plus the
// g dt^2 that gravity adds in that step. A shape that turns as it lands (the book's one
// contact point per pair tips a box onto its corner) moves no point of itself faster
// than twice its centre: a box pivoting on one corner moves the opposite corner, twice
// as far from the pivot as its centre, at twice the speed. Hence 2 speed dt + g dt^2.
double landingDepth(double speed, double dt, double g = kG) { return 2 * speed * dt + g * dt * dt; }

// The speed of a fall from rest through `height`, energy conservation: v^2 = 2 g h.
double fallSpeed(double height, double g = kG) { return std::sqrt(2 * g * height); }

// A 600 px wide floor (its top at y = 420, `floor_height` thick), a 100 x 20 slab on it
// and a 60 x 60 box on the slab, each just touching the one below; gravity 20 px/s^2.
struct Stack {
    Stack(double slab_mass, double box_mass, double floor_height = 20)
        : page(keptWorld(engine::kGravity)),
          floor(page.core.add(Rectangle({400, 420 + floor_height / 2}, 600, floor_height, {.mass = 0}))),
          slab(page.core.add(Rectangle({400, 410}, 100, 20, {.mass = slab_mass}))),
          box(page.core.add(Rectangle({400, 370}, 60, 60, {.mass = box_mass}))) {}
    test::WorldFixture page;
    Rectangle& floor;
    Rectangle& slab;
    Rectangle& box;
};

}  // namespace

// ---------------------------------------------------------------------------------------
// Mass ratios of a million, both ways round.

TEST_CASE("extremes: a light box on a heavy one (1 : 1e6) rests on the floor, both still") {
    Stack stack(1e6, 1);
    const Vec2 slab_start = stack.slab.center();
    const Vec2 box_start = stack.box.center();
    double slab_in_floor = -std::numeric_limits<double>::infinity();
    double box_in_slab = slab_in_floor;
    double drift = 0.0;
    runChecked(stack.page, 600, [&](int) {
        slab_in_floor = std::max(slab_in_floor, oracle::depth(stack.slab, stack.floor));
        box_in_slab = std::max(box_in_slab, oracle::depth(stack.box, stack.slab));
        drift = std::max({drift, stack.slab.center().distance(slab_start), stack.box.center().distance(box_start)});
    });
    // Physics: a stack at rest stays at rest, with no overlap at all. The engine lets a
    // resting shape sink one step of gravity, g dt^2 / (1 + e) = 0.0046 px (see the dt
    // case below), before the next pass pushes it out; and with one contact point per
    // pair each box rocks, which lowers one corner at a time a little further. That
    // much has no closed form. Measured: 0.021 px into the floor, 0.017 px into the
    // slab, a drift of 0.017 px in 10 s. The bounds, 0.05 px each, are about two and a
    // half times that: a guard against a change for the worse, not physics.
    WARN("1 on 1e6: slab " << slab_in_floor << " px into the floor, box " << box_in_slab << " px into the slab, drift "
                           << drift << " px in 10 s");
    CHECK(slab_in_floor <= 0.05);
    CHECK(box_in_slab <= 0.05);
    CHECK(drift <= 0.05);
}

TEST_CASE("extremes: a heavy box on a light one (1e6 : 1) falls as if the slab were not there (failure, pinned)") {
    // The book's relaxation cannot carry a load this heavy (heavy_on_light in the scene
    // library shows 100 : 1). Every pass first pushes the slab out of the floor, then
    // pushes the box and slab apart in inverse proportion to their masses: the slab
    // moves a million times further, straight back into the floor, and the box keeps
    // almost all of its speed. So the box falls as if the slab were not there, pressing
    // it into the floor until it pops out sideways, and lands on the floor. Physics: a
    // rigid slab holds any load, and nothing moves. What is pinned here is what the
    // engine does now; the bounds that hold all the same are marked as such.
    // (The fix is a solver that carries a load down a stack within one step, such as
    // impulses accumulated over the passes and clamped, not one per pair per pass.)
    Stack stack(1, 1e6);
    double slab_in_floor = -std::numeric_limits<double>::infinity();
    double box_in_floor = slab_in_floor;
    double fall_speed_after_1s = 0.0;
    runChecked(stack.page, 600, [&](int step) {
        slab_in_floor = std::max(slab_in_floor, oracle::depth(stack.slab, stack.floor));
        box_in_floor = std::max(box_in_floor, oracle::depth(stack.box, stack.floor));
        if (step == 60) fall_speed_after_1s = stack.box.velocity().y;
    });
    WARN("1e6 on 1: box falls at " << fall_speed_after_1s << " px/s after 1 s (free fall: " << kG
                                   << "); slab pressed up to " << slab_in_floor << " px into the 20 px floor; box "
                                   << box_in_floor << " px into the floor at worst");
    // Pinned failure: after 1 s the box falls at the free-fall speed g t = 20 px/s
    // (correct: 0), and the slab is pressed more than half way into the floor (correct: 0).
    CHECK(fall_speed_after_1s >= 0.99 * kG * 1.0);
    CHECK(slab_in_floor > 10);
    // Holds all the same: the slab does not pass through a 20 px floor, and the box,
    // which can fall no further than the slab's 20 px height before it meets the floor,
    // goes no deeper into the floor than landing from that fall allows.
    CHECK(slab_in_floor < 20);
    CHECK(box_in_floor <= landingDepth(fallSpeed(20), kDt));
    // How it ends is not pinned: the squeezing out is chaotic, and any change to the
    // impulses (even the friction fix that the rough box case below asks for) keeps
    // the slab pressed in instead. Now, after 10 s, both lie on the floor side by side.
    WARN("1e6 on 1 after 10 s: slab " << oracle::depth(stack.slab, stack.floor) << " px into the floor at x = "
                                      << stack.slab.center().x << ", box " << oracle::depth(stack.box, stack.floor)
                                      << " px into the floor at x = " << stack.box.center().x);
}

TEST_CASE("extremes: on a 10 px floor the 1e6 box pushes the slab right through it (failure, pinned)") {
    // The same failure with a floor thinner than the 17 px the slab is pressed in: the
    // slab comes out under the floor and falls away. Physics: it cannot pass the floor.
    Stack stack(1, 1e6, 10);
    const double floor_bottom = 430;
    runChecked(stack.page, 600);
    WARN("10 px floor: the slab's centre ends at y = " << stack.slab.center().y
                                                       << ", the floor's bottom at y = " << floor_bottom);
    CHECK(stack.slab.center().y > floor_bottom);
    CHECK(stack.slab.velocity().y > 0);
}

// ---------------------------------------------------------------------------------------
// Sizes from 0.01 px to 100,000 px.

TEST_CASE("extremes: 0.01 px shapes land on a 100,000 px box that lands on a 100,000 px floor") {
    test::WorldFixture page(keptWorld(engine::kGravity));
    const double huge = 1e5;
    const double tiny = 0.01;
    // The floor's top at y = 400; the box 1 px above it; the small shapes 1 px above the
    // box, the 10 px ball among them for scale.
    Rectangle& floor = page.core.add(Rectangle({0, 400 + huge / 2}, huge, huge, {.mass = 0}));
    const double box_top = 400 - 1 - huge;
    Rectangle& box = page.core.add(Rectangle({0, box_top + huge / 2}, huge, huge));
    Circle& dot = page.core.add(Circle({-100, box_top - 1 - tiny / 2}, tiny / 2));
    Rectangle& speck = page.core.add(Rectangle({0, box_top - 1 - tiny / 2}, tiny, tiny));
    Circle& ball = page.core.add(Circle({100, box_top - 1 - 10}, 10));
    const std::vector<engine::RigidShape*> small{&dot, &speck, &ball};
    std::vector<Vec2> start;
    for (const engine::RigidShape* shape : small) start.push_back(shape->center());

    double box_in_floor = -std::numeric_limits<double>::infinity();
    double small_in_box = box_in_floor;
    double speck_spin = 0.0;
    runChecked(page, 600, [&](int) {
        box_in_floor = std::max(box_in_floor, oracle::depth(box, floor));
        for (const engine::RigidShape* shape : small) small_in_box = std::max(small_in_box, oracle::depth(*shape, box));
        speck_spin = std::max(speck_spin, std::abs(speck.angularVelocity()));
    });
    // The box falls 1 px. The small shapes fall 1 px with it and 1 px more after it has
    // stopped, and the box may bounce up towards them at e times its landing speed:
    // they meet at no more than sqrt(2 g 2 px) + e sqrt(2 g 1 px) = 10.2 px/s.
    const double small_landing = fallSpeed(2) + engine::PhysicalAttributes{}.restitution * fallSpeed(1);
    double small_drift = 0.0;
    for (std::size_t k = 0; k < small.size(); ++k)
        small_drift = std::max(small_drift, std::abs(small[k]->center().x - start[k].x));
    WARN("sizes 0.01 to 1e5 px: box " << box_in_floor << " px into the floor (bound " << landingDepth(fallSpeed(1), kDt)
                                      << "), small shapes " << small_in_box << " px into the box (bound "
                                      << landingDepth(small_landing, kDt) << "); box turned " << box.angle()
                                      << " rad; small shapes drifted up to " << small_drift
                                      << " px; the 0.01 px square spun at up to " << speck_spin << " rad/s");
    CHECK(box_in_floor <= landingDepth(fallSpeed(1), kDt));
    CHECK(small_in_box <= landingDepth(small_landing, kDt));
    // Still on top of the box, not sunk into it: every small shape ends within a
    // resting step's sinking (g dt^2 = 0.0056 px, doubled for the rocking) of lying on it.
    for (const engine::RigidShape* shape : small) CHECK(oracle::depth(*shape, box) <= 2 * kG * kDt * kDt);
    // Resting shapes do not travel. They jitter: each step a resting contact is pushed
    // out and sinks again, at one corner of the box at a time, and the 0.01 px square is
    // flicked round by it (its spin is printed above). How far that carries them has no
    // closed form. Measured: 1.7 px in 10 s; the bound, 4 px, is a guard against a
    // change for the worse.
    CHECK(small_drift <= 4);
    // The huge box lies flat: turned by 1e-6 rad, its far edge would stand 0.05 px proud.
    CHECK(std::abs(box.angle()) <= 1e-6);
}

TEST_CASE("extremes: two 0.01 px balls meet head-on and part at e times their speed") {
    // No gravity, equal masses, a head-on hit through both centres: no spin, no friction
    // along the line. Momentum stays 0, and Newton's restitution sends them apart at e
    // times the speed they met with: each at 0.2 x 0.1 = 0.02 px/s. Each step moves
    // 0.0017 px, far less than the 0.01 px diameter, so the hit cannot be skipped.
    test::WorldFixture page(keptWorld(kNoGravity));
    Circle& left = page.core.add(Circle({400, 225}, 0.005));
    Circle& right = page.core.add(Circle({400.02, 225}, 0.005));
    left.setVelocity({0.1, 0});
    right.setVelocity({-0.1, 0});
    const double energy = test::kineticEnergy(page.core);
    double most_energy = energy;
    runChecked(page, 60, [&](int) { most_energy = std::max(most_energy, test::kineticEnergy(page.core)); });
    const double e = left.restitution();
    WARN("0.01 px balls: velocities " << left.velocity().x << " and " << right.velocity().x << " px/s");
    CHECK(left.velocity().x == Approx(-e * 0.1).epsilon(1e-6));
    CHECK(right.velocity().x == Approx(e * 0.1).epsilon(1e-6));
    CHECK(test::linearMomentum(page.core).length() <= 1e-15);
    CHECK(most_energy <= energy);
}

TEST_CASE("extremes: two 100,000 px boxes collide corner first, keeping momentum, gaining no energy") {
    // No gravity; two squares of 1e5 px side at 100 px/s each towards the other, the
    // right one 10 px lower so their faces meet off-centre. The book's single contact
    // point makes the hit turn them, so the velocities after are no round numbers; but
    // the impulses are equal and opposite (momentum kept) and e <= 1 (no energy gained).
    test::WorldFixture page(keptWorld(kNoGravity));
    const double huge = 1e5;
    Rectangle& left = page.core.add(Rectangle({0, 0}, huge, huge));
    Rectangle& right = page.core.add(Rectangle({huge + 10, 10}, huge, huge));
    left.setVelocity({100, 0});
    right.setVelocity({-100, 0});
    const double energy = test::kineticEnergy(page.core);
    double most_energy = energy;
    runChecked(page, 60, [&](int) { most_energy = std::max(most_energy, test::kineticEnergy(page.core)); });
    const Vec2 momentum = test::linearMomentum(page.core);
    WARN("1e5 px boxes: most energy " << most_energy / energy << " of the start, momentum (" << momentum.x << ", "
                                      << momentum.y << "), velocities " << left.velocity().x << " and "
                                      << right.velocity().x << " px/s");
    CHECK(most_energy <= energy * (1 + 1e-12));
    CHECK(momentum.length() <= 1e-9 * 100);
    CHECK(right.velocity().x - left.velocity().x >= 0);  // they hit and parted
}

// ---------------------------------------------------------------------------------------
// Speeds up to 1,000,000 px/s, and the energy of a closed box.

namespace {

Vec2 heading(double angle) { return {std::cos(angle), std::sin(angle)}; }

}  // namespace

TEST_CASE("extremes: at up to 1e6 px/s a closed box keeps its shapes in and its energy from growing") {
    const double speed = GENERATE(1e2, 1e4, 1e6);
    INFO("speed " << speed << " px/s");
    test::ClosedBox closed(keptWorld(kNoGravity));
    // Two rough balls and a smooth box, all of mass 1 and e = 1. (A rough box gains
    // energy: see the next case.)
    const engine::PhysicalAttributes rough{.mass = 1, .friction = 0.8, .restitution = 1};
    const engine::PhysicalAttributes smooth{.mass = 1, .friction = 0, .restitution = 1};
    engine::RigidShape& small_ball = closed.page.core.add(Circle({250, 150}, 10, rough));
    engine::RigidShape& large_ball = closed.page.core.add(Circle({550, 300}, 20, rough));
    engine::RigidShape& box = closed.page.core.add(Rectangle({400, 225}, 40, 20, smooth));
    small_ball.setVelocity(heading(0.5) * speed);
    large_ball.setVelocity(heading(2.5) * speed);
    box.setVelocity(heading(4.0) * speed);
    box.setAngularVelocity(3);
    const std::vector<engine::RigidShape*> moving{&small_ball, &large_ball, &box};

    // No gravity, e = 1, so no impulse can add energy: E never rises above E0 (rounding:
    // 1e-9 of it). Then no shape of mass m can be faster than sqrt(2 E0 / m), and no
    // step longer than that times dt: 28,900 px at 1e6 px/s, less than half the wall.
    // So a shape that ends a step inside a wall has its centre nearer the inner face,
    // and the next step's pass pushes it back through that face; only then does it take
    // that step's move, |v| dt with the velocity it ends the step with. So at the end of
    // every step each shape is out of the inside by no more than its own last move,
    // |v| dt, plus what other shapes pushed it by after the wall's correction: no more
    // than their overlap, the bounding diameters of all of them (the slack).
    const double energy = test::kineticEnergy(closed.page.core);
    double slack = 0.0;
    for (const engine::RigidShape* shape : moving) slack += 2 * shape->boundRadius();
    double most_energy = energy;
    double farthest_out = 0.0;
    double most_beyond_step = -std::numeric_limits<double>::infinity();
    runChecked(closed.page, 600, [&](int) {
        most_energy = std::max(most_energy, test::kineticEnergy(closed.page.core));
        for (const engine::RigidShape* shape : moving) {
            const double out = closed.outside(shape->center());
            farthest_out = std::max(farthest_out, out);
            if (out > 0) most_beyond_step = std::max(most_beyond_step, out - shape->velocity().length() * kDt);
        }
    });
    WARN("closed box at " << speed << " px/s: energy at most " << most_energy / energy << " of the start, at the end "
                          << test::kineticEnergy(closed.page.core) / energy << "; a centre went " << farthest_out
                          << " px out of the inside, at most " << most_beyond_step
                          << " px beyond its own last move (bound " << slack << ")");
    CHECK(most_energy <= energy * (1 + 1e-9));
    CHECK(most_beyond_step <= slack);
    // And so no further than the fastest possible step and the slack.
    CHECK(farthest_out <= std::sqrt(2 * energy / 1.0) * kDt + slack);
}

TEST_CASE("extremes: a rough box bouncing in a closed box gains energy with the book's friction (failure, pinned)") {
    // The book works out the friction impulse from the sliding before the normal
    // impulse (docs/errata.md, "Friction from the velocity before the bounce"). When the
    // box hits with a corner, the normal impulse also spins it, which changes the
    // sliding at the corner, even turns it round; friction then pushes the way the
    // corner now slides, and adds energy. Measured: E jumps to 1.7 E0 at one hit within
    // 10 s; left to run, hit after hit, the box flies fast enough to pass through a wall.
    const double peak = test::roughBoxEnergyPeak(keptWorld(kNoGravity));
    WARN("rough box, e = 1, book friction: energy rose to " << peak << " of the start (physics: at most 1)");
    CHECK(peak > 1.2);
}

// ---------------------------------------------------------------------------------------
// Steps from 1e-5 s to 0.1 s.

TEST_CASE("extremes: for dt from 1e-5 s to 0.1 s a dropped ball and box land and rest on the floor") {
    const double dt = GENERATE(1e-5, 1e-4, 1e-3, 1.0 / 60, 0.05, 0.1);
    INFO("dt " << dt << " s");
    test::WorldFixture page(keptWorld(engine::kGravity, dt));
    // Floor top at y = 400; both shapes 5 px above it, mass 1, e = 0.2.
    Rectangle& floor = page.core.add(Rectangle({400, 420}, 600, 40, {.mass = 0}));
    Circle& ball = page.core.add(Circle({300, 400 - 5 - 10}, 10));
    Rectangle& box = page.core.add(Rectangle({500, 400 - 5 - 10}, 30, 20));
    // Mechanical energy, potential measured from the floor's top.
    const auto energy = [&] {
        return test::kineticEnergy(page.core) + kG * (400 - ball.center().y) + kG * (400 - box.center().y);
    };
    const double start_energy = energy();
    double most_energy = -std::numeric_limits<double>::infinity();
    double ball_in_floor = most_energy;
    double box_in_floor = most_energy;
    // Two simulated seconds: 200,000 steps at 1e-5 s.
    runChecked(page, static_cast<int>(std::lround(2.0 / dt)), [&](int) {
        most_energy = std::max(most_energy, energy());
        ball_in_floor = std::max(ball_in_floor, oracle::depth(ball, floor));
        box_in_floor = std::max(box_in_floor, oracle::depth(box, floor));
    });
    // Landing from 5 px, at sqrt(2 g 5 px) = 14.1 px/s, sinks no deeper than one step.
    const double bound = landingDepth(fallSpeed(5), dt);
    // Resting, a ball ends every step at the same depth: the pass stops it (to e times
    // its speed, upward), gravity gives it g dt back, and it moves down with what is
    // left. Steady when v = -e v + g dt, so v = g dt / (1 + e), and the step ends
    // v dt = g dt^2 / (1 + e) deep: 0.167 px at dt = 0.1 s, 1.7e-9 px at 1e-5 s.
    const double resting = kG * dt * dt / (1 + ball.restitution());
    WARN("dt " << dt << ": ball " << ball_in_floor << " px and box " << box_in_floor
               << " px into the floor at worst (bound " << bound << "); the ball rests " << oracle::depth(ball, floor)
               << " px deep (g dt^2 / (1 + e) = " << resting << "); energy at most " << most_energy - start_energy
               << " above the start");
    CHECK(ball_in_floor <= bound);
    CHECK(box_in_floor <= bound);
    CHECK(oracle::depth(ball, floor) == Approx(resting).epsilon(0.01));
    // Symplectic Euler loses m g^2 dt^2 / 2 each step of a fall from rest, and a bounce
    // with e < 1 loses more: the energy never rises above the start (rounding aside).
    CHECK(most_energy <= start_energy + 1e-9 * std::abs(start_energy));
}

// ---------------------------------------------------------------------------------------
// A thousand shapes made at one point.

TEST_CASE("extremes: 1,000 shapes made at one point push apart, finite and bounded, gaining no energy") {
    // Rectangles and circles of 5 to 15 px and masses 1 to 5, all centred on (400, 225),
    // at rest, no gravity. Every relaxation pass tests 499,500 pairs, so 10 steps (150
    // passes): under a second in Release, some 15 s under the sanitizers. (The grid
    // broad phase finds the same pairs but is no faster here: the shapes start in one
    // cell and spread over only a few; measured 1.9 s against 1.6 s for 20 steps.)
    constexpr int kShapes = 1000;
    constexpr int kSteps = 10;
    const Vec2 point{400, 225};
    test::WorldFixture page(keptWorld(kNoGravity));
    double chain = 0.0;  // all the shapes laid end to end
    for (int i = 0; i < kShapes; ++i) {
        const double size = 5 + (i * 37 % 100) / 10.0;
        const engine::PhysicalAttributes attributes{.mass = 1.0 + i % 5};
        if (i % 2 == 0) {
            page.core.add(Rectangle(point, size, size * (1 + (i % 3) * 0.5), attributes));
        } else {
            page.core.add(Circle(point, size / 2, attributes));
        }
        chain += 2 * page.core.object(i).boundRadius();
    }
    runChecked(page, kSteps, [&](int) {
        // At rest, nothing ever closes in on anything, so no impulse acts: only
        // positional correction moves them, and it changes no velocity.
        REQUIRE(test::kineticEnergy(page.core) == 0.0);
    });
    // Positional correction moves each pair apart in inverse proportion to their masses,
    // so their centre of mass stays put, and so does that of all of them (rounding of
    // 1,000 coordinates near 400: far below 1e-9 px).
    const Vec2 centre = test::centreOfMass(page.core);
    double farthest = 0.0;
    for (std::size_t i = 0; i < page.core.objectCount(); ++i) {
        farthest = std::max(farthest, page.core.object(i).center().distance(point));
    }
    // How far apart they are: pairs that the oracle finds more than 0.01 px deep.
    std::vector<oracle::Shape> outlines;
    for (std::size_t i = 0; i < page.core.objectCount(); ++i) outlines.push_back(oracle::outline(page.core.object(i)));
    int overlapping = 0;
    double deepest = 0.0;
    for (std::size_t i = 0; i < outlines.size(); ++i) {
        for (std::size_t j = i + 1; j < outlines.size(); ++j) {
            const double d = oracle::depth(outlines[i], outlines[j]);
            if (d > 0.01) ++overlapping;
            deepest = std::max(deepest, d);
        }
    }
    const int pairs = kShapes * (kShapes - 1) / 2;
    WARN("1,000 shapes at one point, after "
         << kSteps << " steps: " << overlapping << " of " << pairs << " pairs still overlap (deepest " << deepest
         << " px), the farthest centre " << farthest << " px out (bound " << chain << "), centre of mass moved "
         << centre.distance(point) << " px");
    CHECK(centre.distance(point) <= 1e-9);
    // Pushed apart, no shape can get further than all of them laid end to end, in a
    // line from the point: the bound of a chain, 14,000 px. That is all the physics
    // says; how far the rows actually spread has no closed form. Measured: 317 px. A
    // second bound, 400 px, guards against a change for the worse.
    CHECK(farthest <= chain);
    CHECK(farthest <= 400);
    // They have mostly parted: fewer than 1% of the pairs still overlap. (Not all:
    // unturned, at rest, every push is along a face normal or straight up, so they
    // spread along the two axes through the point, in jammed rows that part slowly.)
    CHECK(overlapping < pairs / 100);
}

// ---------------------------------------------------------------------------------------
// 100,000 steps of the book's demo.

TEST_CASE("extremes: 100,000 steps of the book's demo stay finite, on the canvas and bounded in energy") {
    test::WorldFixture page(engine::kBookWorld);
    test::buildBookScene(page.core, page.random);
    const std::size_t platforms = 4;
    std::vector<Vec2> platform_centres;
    std::vector<double> platform_angles;
    for (std::size_t i = 0; i < platforms; ++i) {
        REQUIRE(page.core.object(i).isStatic());
        platform_centres.push_back(page.core.object(i).center());
        platform_angles.push_back(page.core.object(i).angle());
    }
    const double width = page.core.width();
    const double height = page.core.height();
    // Potential energy measured from 100 px below the canvas: a shape is removed once
    // its centre leaves the canvas, one step after at most, which puts every shape in
    // the list above that line. So removing one only takes energy away, and the sum
    // over the list, kinetic plus potential, can never exceed what it started with.
    const double ground = height + 100;
    const auto energy = [&] {
        double total = test::kineticEnergy(page.core);
        for (std::size_t i = 0; i < page.core.objectCount(); ++i) {
            const engine::RigidShape& shape = page.core.object(i);
            if (!shape.isStatic()) total += shape.mass() * kG * (ground - shape.center().y);
        }
        return total;
    };
    const double start_energy = energy();
    double most_energy = start_energy;
    double out_per_step = 0.0;
    runChecked(page, 100000, [&](int) {
        most_energy = std::max(most_energy, energy());
        for (std::size_t i = 0; i < page.core.objectCount(); ++i) {
            const engine::RigidShape& shape = page.core.object(i);
            const double out = test::outside(shape.center(), 0, width, 0, height);
            if (out == 0) continue;
            // The removal runs before the shapes move: one outside now was inside then
            // and has moved one step, |v| dt, since.
            const double step = shape.velocity().length() * kDt;
            out_per_step = std::max(out_per_step, out / step);
            if (out > step * (1 + 1e-12))
                FAIL("shape " << i << " is " << out << " px off the canvas, its step " << step);
        }
    });
    WARN("book demo, 100,000 steps: " << page.core.objectCount() << " shapes left; energy at most "
                                      << (most_energy - start_energy) / start_energy
                                      << " of the start above it; a centre off the canvas by at most " << out_per_step
                                      << " of its step");
    // The energy bound, with 1e-9 for rounding; the demo's shapes are rough, and rough
    // boxes may gain energy (see the closed box case), so this holds for its scene only.
    CHECK(most_energy <= start_energy * (1 + 1e-9));
    // The platforms are static: not moved or turned at all.
    for (std::size_t i = 0; i < platforms; ++i) {
        CHECK(page.core.object(i).center() == platform_centres[i]);
        CHECK(page.core.object(i).angle() == platform_angles[i]);
    }
}

// ---------------------------------------------------------------------------------------
// Exact coincidences.

namespace {

// Two shapes built on top of each other, and their overlap worked out by hand.
struct Coincidence {
    std::string name;
    std::function<void(engine::Core&)> build;
    double overlap;
};

std::vector<Coincidence> coincidences() {
    return {
        // Concentric circles part by their radii added up (the book pushes straight up).
        {"circle and circle, same centre",
         [](engine::Core& core) {
             core.add(Circle({400, 225}, 10));
             core.add(Circle({400, 225}, 5, {.mass = 3}));
         },
         15},
        // Identical 40 x 20 rectangles part across their short side.
        {"identical rectangles, same centre",
         [](engine::Core& core) {
             core.add(Rectangle({400, 225}, 40, 20));
             core.add(Rectangle({400, 225}, 40, 20));
         },
         20},
        {"identical rectangles, same centre, both turned 0.3 rad",
         [](engine::Core& core) {
             core.add(Rectangle({400, 225}, 40, 20)).rotate(0.3);
             core.add(Rectangle({400, 225}, 40, 20)).rotate(0.3);
         },
         20},
        // A circle at the centre leaves through a long side: the radius plus half the height.
        {"rectangle and circle, same centre",
         [](engine::Core& core) {
             core.add(Rectangle({400, 225}, 40, 20));
             core.add(Circle({400, 225}, 10));
         },
         20},
        // A circle centred on a corner leaves by its radius, along either side's normal.
        {"circle centred on a rectangle's corner",
         [](engine::Core& core) {
             core.add(Rectangle({400, 225}, 40, 20));
             core.add(Circle({380, 215}, 10));
         },
         10},
    };
}

}  // namespace

TEST_CASE("extremes: shapes that coincide exactly part in one step, at rest, keeping their centre of mass") {
    for (const Coincidence& pair : coincidences()) {
        INFO(pair.name);
        test::WorldFixture page(keptWorld(kNoGravity));
        pair.build(page.core);
        const engine::RigidShape& a = page.core.object(0);
        const engine::RigidShape& b = page.core.object(1);
        REQUIRE(oracle::depth(a, b) == Approx(pair.overlap).epsilon(1e-12));
        const Vec2 centre = test::centreOfMass(page.core);
        runChecked(page, 1);
        // Each pass removes 80% of what is left, along a normal that stays the same: one
        // step leaves 0.2^15 of the overlap. Nothing moved towards anything, so no
        // impulse, and the correction keeps the centre of mass.
        WARN(pair.name << ": " << pair.overlap << " px deep, after one step " << oracle::depth(a, b)
                       << " px (0.2^15 of it: " << pair.overlap * kLeftAfterOneStep << ")");
        CHECK_THAT(oracle::depth(a, b), test::near(pair.overlap * kLeftAfterOneStep, 1e-12));
        CHECK(test::kineticEnergy(page.core) == 0.0);
        CHECK(test::centreOfMass(page.core).distance(centre) <= 1e-12);
    }
}

TEST_CASE("extremes: coinciding shapes thrown apart keep their momentum and gain no energy") {
    for (const Coincidence& pair : coincidences()) {
        INFO(pair.name);
        test::WorldFixture page(keptWorld(kNoGravity));
        pair.build(page.core);
        page.core.object(0).setVelocity({100, 0});
        page.core.object(1).setVelocity({-50, 30});
        const Vec2 momentum = test::linearMomentum(page.core);
        const double energy = test::kineticEnergy(page.core);
        double most_energy = energy;
        runChecked(page, 60, [&](int) { most_energy = std::max(most_energy, test::kineticEnergy(page.core)); });
        // Equal and opposite impulses; e <= 1.
        WARN(pair.name << ", thrown apart: energy at most " << most_energy / energy << " of the start, momentum off by "
                       << (test::linearMomentum(page.core) - momentum).length());
        CHECK((test::linearMomentum(page.core) - momentum).length() <= 1e-12 * momentum.length());
        CHECK(most_energy <= energy * (1 + 1e-12));
    }
}

TEST_CASE("extremes: shapes just touching, moving together, stay exactly as they are") {
    // Touching, with no speed towards each other: a depth of 0 moves nothing, a closing
    // speed of 0 makes no impulse. They glide on together at (30, 40) px/s, unturned.
    struct Touching {
        std::string name;
        std::function<void(engine::Core&)> build;
    };
    const double side = 10 / std::sqrt(2.0);  // a radius of 10 along the diagonal
    const std::vector<Touching> pairs{
        {"two circles",
         [](engine::Core& core) {
             core.add(Circle({400, 225}, 10));
             core.add(Circle({420, 225}, 10));
         }},
        {"two squares side by side",
         [](engine::Core& core) {
             core.add(Rectangle({400, 225}, 20, 20));
             core.add(Rectangle({420, 225}, 20, 20));
         }},
        {"a square and a circle on its side",
         [](engine::Core& core) {
             core.add(Rectangle({400, 225}, 20, 20));
             core.add(Circle({420, 225}, 10));
         }},
        {"a square and a circle on its corner",
         [side](engine::Core& core) {
             core.add(Rectangle({400, 225}, 20, 20));
             core.add(Circle({410 + side, 235 + side}, 10));
         }},
    };
    const Vec2 velocity{30, 40};
    for (const Touching& pair : pairs) {
        INFO(pair.name);
        test::WorldFixture page(keptWorld(kNoGravity));
        pair.build(page.core);
        engine::RigidShape& a = page.core.object(0);
        engine::RigidShape& b = page.core.object(1);
        a.setVelocity(velocity);
        b.setVelocity(velocity);
        const Vec2 apart = b.center() - a.center();
        runChecked(page, 60);
        CHECK(a.velocity() == velocity);
        CHECK(b.velocity() == velocity);
        CHECK(a.angularVelocity() == 0.0);
        CHECK(b.angularVelocity() == 0.0);
        CHECK((b.center() - a.center() - apart).length() <= 1e-9);  // moved alike, to rounding
    }
}

// ---------------------------------------------------------------------------------------
// Worlds where nothing can happen.

TEST_CASE("extremes: a world of static shapes, overlapping too, does not move at all") {
    // The book's platforms, plus static shapes inside each other: a static body has no
    // acceleration and no impulse changes it, and pairs of static shapes are not even
    // tested. Gravity on, 600 steps: every number stays exactly as it was.
    test::WorldFixture page(keptWorld(engine::kGravity));
    page.core.add(Rectangle({500, 200}, 400, 20, {.mass = 0})).rotate(2.8);
    page.core.add(Rectangle({200, 400}, 400, 20, {.mass = 0}));
    page.core.add(Rectangle({100, 200}, 200, 20, {.mass = 0}));
    page.core.add(Rectangle({10, 360}, 20, 100, {.mass = 0}));
    page.core.add(Circle({200, 400}, 30, {.mass = 0}));
    page.core.add(Rectangle({200, 400}, 400, 20, {.mass = 0}));
    struct Still {
        Vec2 center;
        double angle;
    };
    std::vector<Still> before;
    for (std::size_t i = 0; i < page.core.objectCount(); ++i) {
        before.push_back({page.core.object(i).center(), page.core.object(i).angle()});
    }
    runChecked(page, 600);
    CHECK(page.core.physics().collisions().empty());
    for (std::size_t i = 0; i < page.core.objectCount(); ++i) {
        INFO("shape " << i);
        const engine::RigidShape& shape = page.core.object(i);
        CHECK(shape.center() == before[i].center);
        CHECK(shape.angle() == before[i].angle);
        CHECK(shape.velocity() == Vec2{});
        CHECK(shape.angularVelocity() == 0.0);
    }
}

TEST_CASE("extremes: an empty world updates, and nothing happens") {
    test::WorldFixture page(engine::kBookWorld);
    runChecked(page, 600);
    CHECK(page.core.stepCount() == 600);
    CHECK(page.core.objectCount() == 0);
    CHECK(page.core.physics().collisions().empty());
    // The frame's echo and drawing cope with no selected object.
    page.core.runGameLoop();
    CHECK(page.window.document.ui_echo.find("Id: none") != std::string::npos);
}

// ---------------------------------------------------------------------------------------
// Tunnelling: the slowest ball that passes a thin wall (a failure, on purpose).

namespace {

// A static wall 4 px thick from x = 400 to 404, 400 px tall, and a ball of radius 2
// coming from the left at `speed`, its centre starting `back` px before it would touch
// the wall (back = 0: touching, which counts as apart). No gravity, no friction, e = 0.5.
enum class Outcome { passed, stopped, neither };

constexpr double kWallLeft = 400;
constexpr double kWallThickness = 4;
constexpr double kBallRadius = 2;

Outcome shoot(double speed, double back) {
    engine::WorldSettings world = keptWorld(kNoGravity);
#if __has_include("continuous.h")
    world.continuous = false;  // 5.6: the book's discrete step; its sweep stops every shot (its stage test)
#endif
    test::WorldFixture page(world);
    const engine::PhysicalAttributes slippery{.mass = 0, .friction = 0, .restitution = 0.5};
    page.core.add(Rectangle({kWallLeft + kWallThickness / 2, 225}, kWallThickness, 400, slippery));
    Circle& ball = page.core.add(Circle({kWallLeft - kBallRadius - back, 225}, kBallRadius, {1, 0, 0.5}));
    ball.setVelocity({speed, 0});
    // It reaches the wall within two steps (back is less than one step); five more let
    // it leave on one side or the other.
    runChecked(page, 7);
    if (ball.center().x > kWallLeft + kWallThickness + kBallRadius && ball.velocity().x > 0) return Outcome::passed;
    if (ball.center().x < kWallLeft - kBallRadius && ball.velocity().x < 0) return Outcome::stopped;
    return Outcome::neither;
}

}  // namespace

TEST_CASE("extremes: tunnelling: a ball passes a thin wall from half the speed the simple bound gives") {
    // The simple bound: the ball's centre overlaps the wall only within a stretch of
    // thickness + diameter = 8 px, so a ball whose step v dt exceeds that can jump the
    // stretch without ever overlapping: at 8 px / (1/60 s) = 480 px/s and above.
    const double simple_bound = (kWallThickness + 2 * kBallRadius) / kDt;
    // The engine does worse. A ball caught with its centre past the middle of the wall
    // is nearer the far face and is pushed out through it, so only the near half of the
    // stretch, thickness / 2 + radius = 4 px, stops it: from a start just touching the
    // wall, a step of 4 px (240 px/s) already carries the centre to the middle.
    const double half_bound = (kWallThickness / 2 + kBallRadius) / kDt;

    // The search: from a quarter of the simple bound upwards in 1 px/s, the slowest
    // speed that passes, starting just touching (the start that passes most easily).
    double slowest_pass = 0.0;
    for (double speed = simple_bound / 4; speed <= 2 * simple_bound; speed += 1) {
        if (shoot(speed, 0) == Outcome::passed) {
            slowest_pass = speed;
            break;
        }
    }
    WARN("tunnelling (wall 4 px, ball 4 px across, dt 1/60 s): passes from "
         << slowest_pass << " px/s; simple bound " << simple_bound << " px/s, half of it " << half_bound);
    REQUIRE(slowest_pass > 0);
    CHECK(slowest_pass >= half_bound - 1);
    CHECK(slowest_pass <= half_bound + 1);
    // Above the simple bound it passes (the failure), up to 960,000 px/s ...
    for (const double factor : {1.01, 2.0, 10.0, 2000.0}) {
        INFO("speed " << factor * simple_bound);
        CHECK(shoot(factor * simple_bound, 0) == Outcome::passed);
    }
    // ... and well below it, under half, it is stopped from every start: a step shorter
    // than the 4 px near half of the stretch cannot jump it, wherever it begins.
    for (const double factor : {0.1, 0.25, 0.45}) {
        const double speed = factor * simple_bound;
        for (int phase = 0; phase < 16; ++phase) {
            INFO("speed " << speed << ", starting " << phase << "/16 of a step back");
            CHECK(shoot(speed, speed * kDt * phase / 16) == Outcome::stopped);
        }
    }
}

}  // namespace extremes_test
