// The broad phase as a choice (stage 5.2 on, broad_phase.h): the three broad phases
// must move the world bit for bit alike, everywhere, and the grid must hand on far
// fewer pairs than testing them all.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "book_scene.h"
#include "circle.h"
#include "near.h"
#include "rectangle.h"
#include "random_scene.h"
#include "same_state.h"
#include "scene_file.h"
#include "scene_io.h"
#include "world_fixture.h"
#include "world_from_scene.h"

namespace broad_phase_choice_test {

namespace fs = std::filesystem;
using browser::Key;
using engine::BodyDescription;
using engine::BroadPhaseKind;
using engine::ShapeType;
using engine::Vec2;
using engine::WorldSettings;

namespace {

WorldSettings withBroadPhase(WorldSettings world, BroadPhaseKind broad_phase) {
#if __has_include("islands.h")
    // 5.5: all_pairs may find a pair touching to the last digit that the others do not,
    // and a contact decides when a shape may sleep; with sleep off all three agree.
    world.sleep = false;
#endif
    world.broad_phase = broad_phase;
    return world;
}

// The same world three times over, one per broad phase, stepped side by side.
struct ThreeWorlds {
    explicit ThreeWorlds(const WorldSettings& world, std::uint64_t seed = 1)
        : by_bound(withBroadPhase(world, BroadPhaseKind::bounding_circle), seed),
          by_all(withBroadPhase(world, BroadPhaseKind::all_pairs), seed),
          by_grid(withBroadPhase(world, BroadPhaseKind::grid), seed) {}

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
            test::requireSameState(by_bound.core, by_all.core, what + ", all_pairs", by_bound.core.stepCount());
            test::requireSameState(by_bound.core, by_grid.core, what + ", grid", by_bound.core.stepCount());
        }
    }
    std::vector<test::WorldFixture*> pages() { return {&by_bound, &by_all, &by_grid}; }

    test::WorldFixture by_bound;
    test::WorldFixture by_all;
    test::WorldFixture by_grid;
};

const fs::path kLibrary{SCENE_LIBRARY_DIR};

engine::Scene loadScene(const std::string& name) { return engine::loadScene(kLibrary / (name + ".json")); }

// A random world of `count` moving shapes, boxes and discs from 2 to 200 px spread over
// the sizes (so one can be a hundred times another), over and in each other somewhere
// on the canvas, thrown at up to 100 px/s and spinning; among them a few static pegs,
// and under them an 800 px static floor, far too wide for the grid's cells.
std::vector<BodyDescription> randomBodies(std::uint64_t seed, int count) {
    test::RandomShapes random(seed);
    std::vector<BodyDescription> bodies;
    bodies.push_back({.shape = ShapeType::Rectangle, .center = {400, 440}, .width = 800, .height = 20, .mass = 0});
    constexpr double kSmallest = 2.0;
    constexpr double kLargest = 200.0;
    for (int i = 0; i < count; ++i) {
        BodyDescription body;
        body.center = {random.uniform(0, 800), random.uniform(0, 430)};
        if (random.uniform(0, 1) < 0.5) {
            body.shape = ShapeType::Rectangle;
            body.width = random.logUniform(kSmallest, kLargest);
            body.height = random.logUniform(kSmallest, kLargest);
            body.angle = random.anyAngle();
        } else {
            body.shape = ShapeType::Circle;
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

// The demo's world without its removal of shapes that leave the canvas, and with the
// knobs a test sets.
WorldSettings demoWorld() {
    WorldSettings world = engine::kBookWorld;
    world.remove_out_of_bounds = false;
    return world;
}

}  // namespace

TEST_CASE("broad phase choice: the scene file's broad_phase decides which pairs the passes look at") {
    // Forty circles of radius 10 in two rows, 30 px apart: no two bounding circles touch.
    // Movement off, 15 passes, of which only the first runs: it changes nothing, so the
    // step ends there (physics.cpp). The book's bounding circles look at all 780 pairs
    // and pass none on; all_pairs looks at all 780 and passes all of them to the exact
    // test; the grid (cells three radii wide, each circle in a cell of its own) looks at
    // a few per circle (measured: under 1 in 20 of the pairs; bound 1 in 5). Left out,
    // the key keeps this stage's grid.
    struct Case {
        const char* key;
        BroadPhaseKind kind;
    };
    const Case cases[] = {{R"("broad_phase": "bounding_circle")", BroadPhaseKind::bounding_circle},
                          {R"("broad_phase": "all_pairs")", BroadPhaseKind::all_pairs},
                          {R"("broad_phase": "grid")", BroadPhaseKind::grid},
                          {R"("relaxation_iterations": 15)", BroadPhaseKind::grid}};
    constexpr long kEveryPair = 40 * 39 / 2;
    for (const Case& c : cases) {
        INFO(c.key);
        const WorldSettings world = test::worldFromScene(std::string(R"({"movement": false, )") + c.key + "}");
        REQUIRE(world.broad_phase == c.kind);
        test::WorldFixture page(world);
        for (int i = 0; i < 40; ++i) page.core.add(engine::Circle({100.0 + 30 * (i % 20), 100.0 + 100 * (i / 20)}, 10));
        page.steps(1);
        const engine::PairStatistics& pairs = page.core.physics().pairStatistics();
        WARN(c.key << ": " << pairs.candidates << " candidates, " << pairs.narrow_tests << " narrow tests");
        CHECK(page.core.physics().collisions().empty());
        CHECK(pairs.passes == 1);
        switch (c.kind) {
            case BroadPhaseKind::bounding_circle:
                CHECK(pairs.candidates == kEveryPair);
                CHECK(pairs.narrow_tests == 0);
                break;
            case BroadPhaseKind::all_pairs:
                CHECK(pairs.candidates == kEveryPair);
                CHECK(pairs.narrow_tests == kEveryPair);
                break;
            case BroadPhaseKind::grid:
                CHECK(pairs.candidates * 5 < kEveryPair);
                CHECK(pairs.narrow_tests == 0);
                break;
        }
    }
}

TEST_CASE("broad phase choice: a pair found apart whose shapes no resolution has touched is not tested again") {
    // Movement off, 15 passes, four shapes, six pairs a pass:
    //  0, 1  circles of radius 10, 15 px apart: 5 px deep in each other. Each pass
    //        corrects 80 % of what is left, never all of it, so the pair collides and
    //        is resolved in every pass, and is tested in every pass.
    //  2, 3  a 20 px square and a circle of radius 5, 16 px to the right of its centre:
    //        their bounding circles overlap (16 < 14.14 + 5), the shapes do not (the
    //        circle's edge is 1 px short of the square's face). Found apart in pass 0;
    //        no resolution ever touches either, so passes 1 to 14 skip it.
    //  the four other pairs are far apart, bounding circles included.
    // The book's loop makes 2 exact tests a pass, 30 in all; the rule leaves 2 + 14.
    for (const BroadPhaseKind kind : {BroadPhaseKind::bounding_circle, BroadPhaseKind::grid}) {
        WorldSettings world = test::worldFromScene(R"({"movement": false})");
        world.broad_phase = kind;
        test::WorldFixture page(world);
        page.core.add(engine::Circle({100.0, 100.0}, 10));
        page.core.add(engine::Circle({115.0, 100.0}, 10));
        page.core.add(engine::Rectangle({300.0, 100.0}, 20, 20));
        page.core.add(engine::Circle({316.0, 100.0}, 5));
        page.steps(1);
        const engine::PairStatistics& pairs = page.core.physics().pairStatistics();
        INFO((kind == BroadPhaseKind::grid ? "grid" : "bounding_circle") << ": " << pairs.candidates << " candidates");
        CHECK(pairs.passes == 15);
        CHECK(pairs.narrow_tests == 2 + 14);
        CHECK(pairs.skipped_tests == 14);
        REQUIRE(page.core.physics().collisions().size() == 1);
        CHECK(page.core.physics().collisions()[0].first == 0);
        // What the 15 corrections of 80 % left: 5 px times 0.2^15, and the pair's centre
        // where it was.
        const Vec2 left = page.core.object(0).center();
        const Vec2 right = page.core.object(1).center();
        CHECK_THAT(20.0 - (right.x - left.x), test::near(5.0 * std::pow(0.2, 15), 1e-12));
        CHECK_THAT(left.x + right.x, test::near(215.0, 1e-12));
        if (kind == BroadPhaseKind::bounding_circle) CHECK(pairs.candidates == 15 * 6);
    }
}

TEST_CASE("broad phase choice: a step's passes end after one that changed nothing") {
    // Two static rectangles lying in each other (their resolution moves nothing) and a
    // circle falling far from them: every pass would find the same collision and change
    // nothing, so only the first runs, and the record keeps no pair of two static shapes.
    for (const BroadPhaseKind kind : {BroadPhaseKind::bounding_circle, BroadPhaseKind::grid}) {
        WorldSettings world = engine::kBookWorld;
        world.broad_phase = kind;
        test::WorldFixture page(world);
        page.core.add(engine::Rectangle({200.0, 300.0}, 100, 20, {.mass = 0}));
        page.core.add(engine::Rectangle({250.0, 300.0}, 100, 20, {.mass = 0}));
        page.core.add(engine::Circle({600.0, 100.0}, 10));
        page.steps(3);
        const engine::PairStatistics& pairs = page.core.physics().pairStatistics();
        CHECK(pairs.passes == 1);
        CHECK(pairs.narrow_tests == 1);
        CHECK(page.core.physics().collisions().empty());
        // The circle fell as if alone: three steps of the book's integration from rest
        // (v += g dt, then x += v dt) put it 6 g dt^2 lower.
        const double dt = world.dt;
        CHECK_THAT(page.core.object(2).center().y, test::near(100.0 + 6 * world.gravity.y * dt * dt, 1e-9));
    }
}

TEST_CASE("broad phase choice: the three broad phases move every library scene bit for bit alike") {
    // 120 steps (2 s): every scene has had collisions by then (checked: the billiards'
    // first comes after about 36 steps, the rain's after 10).
    constexpr int kSteps = 120;
    for (const fs::directory_entry& entry : fs::directory_iterator(kLibrary)) {
        if (entry.path().extension() != ".json") continue;
        const std::string name = entry.path().stem().string();
        const engine::Scene scene = loadScene(name);
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

TEST_CASE("broad phase choice: the three broad phases move the bench's scenes bit for bit alike") {
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
        const engine::Scene scene = engine::loadScene(entry.path());
        if (scene.bodies.size() > kMostBodies) continue;
        ThreeWorlds worlds(scene.world);
        worlds.build(scene.bodies);
        worlds.stepsCompared(kSteps, entry.path().stem().string());
        ++scenes;
    }
    CHECK(scenes >= 8);  // gas, projectile, both pyramids, rain_100, slide, slope, thin_wall
}

TEST_CASE("broad phase choice: the three broad phases move the book's demo alike, shapes thrown in with F and G") {
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

TEST_CASE("broad phase choice: the three broad phases move random worlds alike, with 1 and with 15 passes") {
    const int passes = GENERATE(1, 15);
    const std::uint64_t seed = GENERATE(range(1, 5));
    WorldSettings world = engine::kBookWorld;
    world.relaxation_iterations = passes;
    ThreeWorlds worlds(world);
    worlds.build(randomBodies(seed, 100));
    worlds.stepsCompared(180, "random world " + std::to_string(seed) + ", " + std::to_string(passes) + " passes");
}

TEST_CASE("broad phase choice: the broad phases agree on shapes far out, where the grid clamps its cells") {
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
        bodies.push_back({.shape = ShapeType::Circle, .center = {100.0 + 15 * i, 200.0 + 3 * i}, .radius = 10});
    }
    const std::vector<double> far_out{1e9, -1e9, 4e10, -4e10, 1e15};
    for (double far : far_out) {
        bodies.push_back({.shape = ShapeType::Circle, .center = {far, far}, .radius = 10});
        bodies.push_back({.shape = ShapeType::Circle, .center = {far + 16, far}, .radius = 10});
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

TEST_CASE("broad phase choice: the grid gathers a row again when the pass pushes its shape into other cells") {
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
        bodies.push_back({.shape = ShapeType::Circle, .center = at, .radius = 5});
        bodies.push_back({.shape = ShapeType::Circle, .center = at + Vec2{-25, 0}, .radius = 50, .mass = 1000});
        bodies.push_back({.shape = ShapeType::Circle, .center = at + Vec2{32, 0}, .radius = 5});
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

TEST_CASE("broad phase choice: the grid hands on far fewer pairs than testing them all, and loses none") {
    // 256 shapes, 8 to 14 px, one to every 20 px square of a lattice, drifting, no
    // gravity: each has a few neighbours. Every broad phase but the grid looks at every
    // pair in every pass it runs, as the book's loop does: n (n - 1) / 2 of them. (A step
    // with no collision ends after its first pass, the same in all three.)
    constexpr int kSide = 16;
    constexpr int kCount = kSide * kSide;
    test::RandomShapes random(3);
    std::vector<BodyDescription> bodies;
    for (int i = 0; i < kCount; ++i) {
        BodyDescription body;
        body.center = {20 + 20.0 * (i % kSide) + random.uniform(-3, 3),
                       20 + 20.0 * (i / kSide) + random.uniform(-3, 3)};
        if (i % 2 == 0) {
            body.shape = ShapeType::Circle;
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
    const long pairs_per_pass = static_cast<long>(kCount) * (kCount - 1) / 2;
    for (int step = 0; step < 10; ++step) {
        worlds.stepsCompared(1, "lattice");
        const engine::Physics& bound = worlds.by_bound.core.physics();
        const engine::Physics& all = worlds.by_all.core.physics();
        const engine::Physics& grid = worlds.by_grid.core.physics();
        INFO("step " << step + 1);
        const long passes = bound.pairStatistics().passes;
        CHECK(all.pairStatistics().passes == passes);
        CHECK(grid.pairStatistics().passes == passes);
        const long every_pair = pairs_per_pass * passes;
        CHECK(bound.pairStatistics().candidates == every_pair);
        CHECK(all.pairStatistics().candidates == every_pair);
        CHECK(all.pairStatistics().narrow_tests == every_pair);
        // The same pairs pass the bounding circles, the same are skipped, and the grid
        // lets by only a few per shape.
        CHECK(grid.pairStatistics().narrow_tests == bound.pairStatistics().narrow_tests);
        CHECK(grid.pairStatistics().skipped_tests == bound.pairStatistics().skipped_tests);
        CHECK(grid.pairStatistics().candidates >= grid.pairStatistics().narrow_tests);
        CHECK(grid.pairStatistics().candidates * 20 < every_pair);
    }
}

}  // namespace broad_phase_choice_test
