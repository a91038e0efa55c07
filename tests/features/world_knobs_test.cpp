// The world knobs of stage 5.1 (scene_file.h, WorldSettings): each one held to what it
// promises. The three broad phases must move the world bit for bit alike, everywhere;
// sub-steps must be the same as a shorter step; the integrators, the friction models,
// rotation and friction off, and the static bodies left out of the integration are
// judged against mechanics worked out by hand.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "book_scene.h"
#include "circle.h"
#include "random_scene.h"
#include "rectangle.h"
#include "scene_file.h"
#include "scene_io.h"
#include "world_fixture.h"

namespace fs = std::filesystem;
using browser::BodyDescription;
using browser::BroadPhase;
using browser::Key;
using browser::ShapeKind;
using browser::WorldSettings;
using engine::Vec2;

namespace {

// ---------------------------------------------------------------------------------
// Bit-identical runs

// What a state dump holds for one body.
struct BodyState {
    Vec2 center;
    double angle;
    Vec2 velocity;
    double angular_velocity;
    friend bool operator==(const BodyState&, const BodyState&) = default;
};

std::vector<BodyState> stateOf(const engine::Core& core) {
    std::vector<BodyState> state;
    for (std::size_t i = 0; i < core.objectCount(); ++i) {
        const engine::RigidShape& shape = core.object(i);
        state.push_back({shape.center(), shape.angle(), shape.velocity(), shape.angularVelocity()});
    }
    return state;
}

// Fails at the first body whose state differs in any bit (== on doubles; the runs start
// from the same numbers, so nothing but a different sequence of operations can part them).
void requireSameState(const engine::Core& reference, const engine::Core& other, const std::string& what,
                      long step) {
    const std::vector<BodyState> expected = stateOf(reference);
    const std::vector<BodyState> got = stateOf(other);
    INFO(what << ", step " << step);
    REQUIRE(got.size() == expected.size());
    for (std::size_t i = 0; i < expected.size(); ++i) {
        if (got[i] == expected[i]) continue;
        FAIL("body " << i << " differs: centre (" << got[i].center.x << ", " << got[i].center.y << ") against ("
                     << expected[i].center.x << ", " << expected[i].center.y << ")");
    }
}

WorldSettings withBroadPhase(WorldSettings world, BroadPhase broad_phase) {
    world.broad_phase = broad_phase;
    return world;
}

// The same world three times over, one per broad phase, stepped side by side.
struct ThreeWorlds {
    explicit ThreeWorlds(const WorldSettings& world, std::uint64_t seed = 1)
        : by_bound(withBroadPhase(world, BroadPhase::bounding_circle), seed),
          by_all(withBroadPhase(world, BroadPhase::all_pairs), seed),
          by_grid(withBroadPhase(world, BroadPhase::grid), seed) {}

    void build(const std::vector<BodyDescription>& bodies) {
        for (test::WorldFixture* page : pages()) engine::buildScene(page->core, bodies);
    }
    void press(Key key, int times = 1) {
        for (test::WorldFixture* page : pages()) page->press(key, times);
    }
    // `count` steps, the states compared after every one of them.
    void stepsCompared(int count, const std::string& what) {
        for (int step = 0; step < count; ++step) {
            for (test::WorldFixture* page : pages()) page->steps(1);
            requireSameState(by_bound.core, by_all.core, what + ", all_pairs", by_bound.core.stepCount());
            requireSameState(by_bound.core, by_grid.core, what + ", grid", by_bound.core.stepCount());
        }
    }
    std::vector<test::WorldFixture*> pages() { return {&by_bound, &by_all, &by_grid}; }

    test::WorldFixture by_bound;
    test::WorldFixture by_all;
    test::WorldFixture by_grid;
};

const fs::path kLibrary{SCENE_LIBRARY_DIR};

browser::SceneDescription loadScene(const std::string& name) {
    return browser::load_scene(kLibrary / (name + ".json"), engine::kBookWorld, browser::WorldKeys::with_knobs);
}

// A random world of `count` moving shapes, boxes and discs from 2 to 200 px spread over
// the sizes (so one can be a hundred times another), over and in each other somewhere
// on the canvas, thrown at up to 100 px/s and spinning; among them a few static pegs,
// and under them an 800 px static floor, far too wide for the grid's cells.
std::vector<BodyDescription> randomBodies(std::uint64_t seed, int count) {
    test::RandomShapes random(seed);
    std::vector<BodyDescription> bodies;
    bodies.push_back({.shape = ShapeKind::rectangle, .center = {400, 440}, .width = 800, .height = 20, .mass = 0});
    constexpr double kSmallest = 2.0;
    constexpr double kLargest = 200.0;
    for (int i = 0; i < count; ++i) {
        BodyDescription body;
        body.center = {random.uniform(0, 800), random.uniform(0, 430)};
        if (random.uniform(0, 1) < 0.5) {
            body.shape = ShapeKind::rectangle;
            body.width = random.logUniform(kSmallest, kLargest);
            body.height = random.logUniform(kSmallest, kLargest);
            body.angle = random.anyAngle();
        } else {
            body.shape = ShapeKind::circle;
            body.radius = random.logUniform(kSmallest, kLargest) / 2;
        }
        const bool peg = random.uniform(0, 1) < 0.1;
        body.mass = peg ? 0.0 : random.uniform(0.5, 30);
        body.friction = random.uniform(0, 1);
        body.restitution = random.uniform(0, 1);
        if (!peg) {
            body.velocity = random.anyDirection() * random.uniform(0, 100);
            body.angular_velocity = random.uniform(-3, 3);
        }
        bodies.push_back(body);
    }
    return bodies;
}

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
// Broad phases

TEST_CASE("world knobs: the three broad phases move every library scene bit for bit alike") {
    // 120 steps (2 s): every scene has had collisions by then (checked: the billiards'
    // first comes after about 36 steps, the rain's after 10).
    constexpr int kSteps = 120;
    for (const fs::directory_entry& entry : fs::directory_iterator(kLibrary)) {
        if (entry.path().extension() != ".json") continue;
        const std::string name = entry.path().stem().string();
        const browser::SceneDescription scene = loadScene(name);
        ThreeWorlds worlds(scene.world);
        worlds.build(scene.bodies);
        std::size_t collisions = 0;
        for (int step = 0; step < kSteps; ++step) {
            worlds.stepsCompared(1, name);
            collisions += worlds.by_grid.core.physics().collisions().size();
        }
        INFO(name);
        CHECK(collisions > 0);
    }
}

TEST_CASE("world knobs: the three broad phases move the bench's scenes bit for bit alike") {
    // The bench (bench/scenes) times each broad phase on these scenes; here they must
    // agree in every bit for 2 s, by then the rain has landed and the gas has bounced.
    // The rains of 400 shapes and more are left out: all_pairs sends their 80,000 to
    // 1,300,000 pairs through the exact test 15 times a step, seconds a step in the
    // sanitizer build. The grid and the bounding circles agree there too: the bench's
    // tables show the same number of exact tests for both.
    constexpr std::size_t kMostBodies = 250;
    constexpr int kSteps = 120;
    int scenes = 0;
    for (const fs::directory_entry& entry : fs::directory_iterator(fs::path(BENCH_SCENES_DIR))) {
        if (entry.path().extension() != ".json") continue;
        const browser::SceneDescription scene =
            browser::load_scene(entry.path(), engine::kBookWorld, browser::WorldKeys::with_knobs);
        if (scene.bodies.size() > kMostBodies) continue;
        ThreeWorlds worlds(scene.world);
        worlds.build(scene.bodies);
        worlds.stepsCompared(kSteps, entry.path().stem().string());
        ++scenes;
    }
    CHECK(scenes >= 8);  // gas, projectile, both pyramids, rain_100, slide, slope, thin_wall
}

TEST_CASE("world knobs: the three broad phases move the book's demo alike, shapes thrown in with F and G") {
    ThreeWorlds worlds(engine::kBookWorld, 2017);
    for (test::WorldFixture* page : worlds.pages()) test::buildBookScene(page->core, page->random);
    worlds.stepsCompared(60, "book scene");
    // New shapes at the long slide and at a shape in the air, then everything kicked:
    // the grid must take in shapes that were not there when the last step began.
    worlds.press(Key::Digit0);
    worlds.press(Key::F);
    worlds.press(Key::G);
    worlds.press(Key::Digit5);
    worlds.press(Key::G, 3);
    worlds.stepsCompared(120, "book scene after F, G");
    worlds.press(Key::H);
    worlds.press(Key::F, 2);
    worlds.stepsCompared(180, "book scene after H");
}

TEST_CASE("world knobs: the three broad phases move random worlds alike, with 1 and with 15 passes") {
    const int passes = GENERATE(1, 15);
    const std::uint64_t seed = GENERATE(range(1, 5));
    WorldSettings world = engine::kBookWorld;
    world.relaxation_iterations = passes;
    ThreeWorlds worlds(world);
    worlds.build(randomBodies(seed, 100));
    worlds.stepsCompared(180, "random world " + std::to_string(seed) + ", " + std::to_string(passes) + " passes");
}

TEST_CASE("world knobs: the broad phases agree on shapes far out, where the grid clamps its cells") {
    // Discs of radius 10 (the grid's cells are then 30 px), some on the canvas and pairs
    // of overlapping ones far out, where nothing removes them. The grid widens each box
    // by 1e-9 of the coordinates against rounding: 2 px at 1e9, which is filed as usual;
    // 80 px at 4e10, still under 8 cells, but 4e10 / 30 is beyond the 2^30 cells the
    // grid counts to, so both discs of that pair are clamped into the same last cell; and
    // at 1e15 the margin makes a disc too big for the cells. Every pair must still be
    // found, and the discs pushed apart.
    WorldSettings world = demoWorld();
    world.gravity = {0, 0};
    std::vector<BodyDescription> bodies;
    for (int i = 0; i < 10; ++i) {
        bodies.push_back({.shape = ShapeKind::circle, .center = {100.0 + 15 * i, 200.0 + 3 * i}, .radius = 10});
    }
    const std::vector<double> far_out{1e9, -1e9, 4e10, -4e10, 1e15};
    for (double far : far_out) {
        bodies.push_back({.shape = ShapeKind::circle, .center = {far, far}, .radius = 10});
        bodies.push_back({.shape = ShapeKind::circle, .center = {far + 16, far}, .radius = 10});
    }
    ThreeWorlds worlds(world);
    worlds.build(bodies);
    worlds.stepsCompared(30, "far shapes");
    for (std::size_t k = 0; k < far_out.size(); ++k) {
        const engine::RigidShape& left = worlds.by_grid.core.object(10 + 2 * k);
        const engine::RigidShape& right = worlds.by_grid.core.object(11 + 2 * k);
        INFO("pair at " << far_out[k]);
        // 4 px into each other at the start; the passes take 0.8 of what is left each
        // time, so they end touching, to within the spacing of the numbers out there.
        CHECK(right.center().x - left.center().x > 19.5);
    }
}

TEST_CASE("world knobs: the grid gathers a row again when the pass pushes its shape into other cells") {
    // No gravity, one pass, and 40 copies, 300 px apart, of three discs: a small one
    // (r 5, mass 1) 30 px deep in a big one (r 50, mass 1000) whose centre is 25 px to
    // its left, and a second small one 32 px to its right, out of reach. Pair (small,
    // big) comes first: the correction moves the small disc right by
    // 0.8 * 30 / (1 + 1/1000) = 23.976 px, to 8.024 px from the other small one, which
    // it now overlaps; so that pair is found in the same pass. The grid's cells are 15 px
    // (three times the median radius 5): when the small disc's row began, covering
    // 95..105 px across, the other one, at 127..137, shared no cell with it. (Cells also
    // share buckets of the hash table by chance, which would hide a missing gather in
    // one copy, but not in 40.)
    constexpr int kCopies = 40;
    WorldSettings world = demoWorld();
    world.gravity = {0, 0};
    world.relaxation_iterations = 1;
    std::vector<BodyDescription> bodies;
    for (int k = 0; k < kCopies; ++k) {
        const Vec2 at{100.0 + 300 * (k % 8), 100.0 + 300 * (k / 8)};
        bodies.push_back({.shape = ShapeKind::circle, .center = at, .radius = 5});
        bodies.push_back({.shape = ShapeKind::circle, .center = at + Vec2{-25, 0}, .radius = 50, .mass = 1000});
        bodies.push_back({.shape = ShapeKind::circle, .center = at + Vec2{32, 0}, .radius = 5});
    }
    ThreeWorlds worlds(world);
    worlds.build(bodies);
    worlds.stepsCompared(1, "pushed into other cells");
    const auto& found = worlds.by_grid.core.physics().collisions();
    REQUIRE(found.size() == 2 * kCopies);
    for (std::size_t k = 0; k < kCopies; ++k) {
        INFO("copy " << k);
        CHECK((found[2 * k].first == 3 * k && found[2 * k].second == 3 * k + 1));
        CHECK((found[2 * k + 1].first == 3 * k && found[2 * k + 1].second == 3 * k + 2));
    }
    worlds.stepsCompared(30, "pushed into other cells, later steps");
}

TEST_CASE("world knobs: the grid hands on far fewer pairs than testing them all, and loses none") {
    // 256 shapes, 8 to 14 px, one to every 20 px square of a lattice, drifting, no
    // gravity: each has a few neighbours. Every broad phase but the grid looks at every
    // pair that is not two static shapes, in every pass: n (n - 1) / 2 of them.
    constexpr int kSide = 16;
    constexpr int kCount = kSide * kSide;
    test::RandomShapes random(3);
    std::vector<BodyDescription> bodies;
    for (int i = 0; i < kCount; ++i) {
        BodyDescription body;
        body.center = {20 + 20.0 * (i % kSide) + random.uniform(-3, 3), 20 + 20.0 * (i / kSide) + random.uniform(-3, 3)};
        if (i % 2 == 0) {
            body.shape = ShapeKind::circle;
            body.radius = random.uniform(4, 7);
        } else {
            body.width = random.uniform(8, 14);
            body.height = random.uniform(8, 14);
            body.angle = random.anyAngle();
        }
        body.velocity = random.anyDirection() * random.uniform(0, 30);
        bodies.push_back(body);
    }
    WorldSettings world = demoWorld();
    world.gravity = {0, 0};
    ThreeWorlds worlds(world);
    worlds.build(bodies);
    const long every_pair = static_cast<long>(kCount) * (kCount - 1) / 2 * world.relaxation_iterations;
    for (int step = 0; step < 10; ++step) {
        worlds.stepsCompared(1, "lattice");
        const engine::Physics& bound = worlds.by_bound.core.physics();
        const engine::Physics& all = worlds.by_all.core.physics();
        const engine::Physics& grid = worlds.by_grid.core.physics();
        INFO("step " << step + 1);
        CHECK(bound.candidatePairs() == every_pair);
        CHECK(all.candidatePairs() == every_pair);
        CHECK(all.narrowPhaseTests() == every_pair);
        // The same pairs pass the bounding circles, and the grid lets by only a few per shape.
        CHECK(grid.narrowPhaseTests() == bound.narrowPhaseTests());
        CHECK(grid.candidatePairs() >= grid.narrowPhaseTests());
        CHECK(grid.candidatePairs() * 20 < every_pair);
    }
}

// =================================================================================
// Sub-steps

TEST_CASE("world knobs: 4 sub-steps of a 1/64 s step are 4 steps of 1/256 s, bit for bit") {
    // 1/64 / 4 = 1/256 exactly in binary, so each sub-step does the very operations a
    // step of 1/256 s does. Shapes fall off the canvas and are removed here too.
    const browser::SceneDescription scene = loadScene("book_demo");
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
        requireSameState(stepped.core, sub_stepped.core, "sub-steps", step);
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
    CHECK(page.core.stepCount() == 64);
    CHECK(ball.velocity().y == kG);
    CHECK(ball.center().y == 100 + kG * 257 / 512);
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
    for (const auto integrator : {browser::Integrator::symplectic, browser::Integrator::explicit_euler}) {
        INFO(browser::knob_name(integrator));
        WorldSettings world = demoWorld();
        world.integrator = integrator;
        test::WorldFixture page(world);
        engine::Circle& ball = page.core.add(engine::Circle(start, 5));
        ball.setVelocity(throw_velocity);
        const double sign = integrator == browser::Integrator::symplectic ? 1.0 : -1.0;
        for (int n = 1; n <= 120; ++n) {
            page.steps(1);
            const double t = n * dt;
            const double exact_y = start.y + throw_velocity.y * t + kG * t * t / 2;
            INFO("step " << n);
            CHECK(ball.center().y - exact_y == Approx(sign * kG * dt * dt * n / 2).margin(1e-9));
            CHECK(ball.center().x == Approx(start.x + throw_velocity.x * t).margin(1e-9));
            CHECK(ball.velocity().y == Approx(throw_velocity.y + kG * t).margin(1e-9));
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
        for (const auto model : {browser::FrictionModel::coulomb, browser::FrictionModel::book}) {
            INFO("mu = " << mu << ", " << browser::knob_name(model));
            WorldSettings world = demoWorld();
            world.rotation = false;
            world.friction_model = model;
            test::WorldFixture page(world);
            addFloor(page.core);
            const engine::Rectangle& box = addSlidingBox(page.core, kSpeed, mu);
            const double slid = slideUntilStopped(page, box, 1200);
            const double deceleration = model == browser::FrictionModel::coulomb ? mu * kG : kG;
            CHECK(box.velocity().x == Approx(0).margin(1e-9));
            CHECK(slid == Approx(kSpeed * kSpeed / (2 * deceleration)).margin(tolerance));
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
        {.shape = ShapeKind::rectangle, .center = {400, 300}, .width = 500, .height = 20, .mass = 0, .angle = 0.3},
        {.shape = ShapeKind::circle, .center = {250, 200}, .radius = 15, .mass = 0},
    };
    test::RandomShapes random(11);
    for (int i = 0; i < 12; ++i) {
        const Vec2 center{random.uniform(200, 600), random.uniform(20, 180)};
        if (i % 2 == 0) {
            bodies.push_back({.shape = ShapeKind::rectangle, .center = center, .width = random.uniform(10, 40),
                              .height = random.uniform(10, 40), .mass = random.uniform(1, 10)});
        } else {
            bodies.push_back({.shape = ShapeKind::circle, .center = center, .radius = random.uniform(5, 20)});
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
    CHECK(box.angle() == 0.0);
    CHECK(box.angularVelocity() == 2.0);
    CHECK(box.velocity().y == Approx(kG).margin(1e-9));  // still falling for 1 s
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
        CHECK(box.velocity().x == Approx(60.0).margin(1e-9));
        CHECK(box.center().x == Approx(100 + 60.0 * 120 * engine::kFrameTime).margin(1e-9));
        // On the floor all along, neither sunk into it nor tipped over.
        CHECK(box.center().y == Approx(kFloorTop - 10).margin(0.5));
        CHECK(box.angle() == Approx(0).margin(0.01));
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
    CHECK(moving.center().x == Approx(100 + velocity.x * t).margin(1e-9));
    CHECK(moving.center().y == Approx(100 + velocity.y * t).margin(1e-9));
    CHECK(moving.angle() == Approx(spin * t).margin(1e-12));
    CHECK(moving.velocity() == velocity);
    CHECK(moving.angularVelocity() == spin);
}
