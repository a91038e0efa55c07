// The scene library (ch5_demo/scenes/*.json): every scene loads, builds and runs 600
// fixed steps (10 s) with finite numbers and without leaving a moving shape buried in a
// static one; then each scene is held to the one thing its README line promises, judged
// with physics worked out here (conservation laws, a rolling disc's acceleration) and
// the independent overlap oracle of collision_oracle.h, never with the engine's own
// collision tests.
//
// The scenes set every world key themselves, so they behave the same on every stage
// that reads scene files; SCENE_LIBRARY_DIR names their folder.
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <filesystem>
#include <limits>
#include <numbers>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "circle.h"
#include "collision_oracle.h"
#include "rectangle.h"
#include "scene_file.h"
#include "scene_io.h"
#include "world_fixture.h"
#include "world_measures.h"

namespace scene_library_test {

namespace fs = std::filesystem;
using engine::Vec2;
using oracle::depth;
using oracle::outline;
using test::finite;
using test::kineticEnergy;

namespace {

const fs::path kLibrary{SCENE_LIBRARY_DIR};

// Every scene of the folder, each with its own test case below. A new scene must be
// added here, or the first test fails.
const std::vector<std::string> kScenes{"billiards", "book_demo", "heavy_on_light", "newtons_cradle",
                                       "pyramid",   "rain",      "slope",          "tunnelling"};

// 600 steps of 1/60 s: the 10 s the README's commands show. The rain (200 shapes, so
// 19,900 pairs, 15 relaxation passes per step) is the costly one: about 1.3 s in Release.
constexpr int kSteps = 600;

// A moving shape may end this deep in a static one: a resting shape sinks a little
// every step under gravity before the next pass pushes it out again.
constexpr double kBuriedPx = 1.0;

engine::Scene load(const std::string& name) { return engine::loadScene(kLibrary / (name + ".json")); }

// A scene as the stage's main.cpp builds it: the world from the file, then its bodies in
// file order (object i is bodies[i]).
struct SceneRun {
    explicit SceneRun(const std::string& name) : SceneRun(load(name)) {}
    explicit SceneRun(engine::Scene loaded) : scene(std::move(loaded)), page(scene.world) {
        engine::buildScene(page.core, scene.bodies);
    }
    const engine::RigidShape& body(std::size_t index) const { return page.core.object(index); }
    void steps(int count) { page.steps(count); }

    engine::Scene scene;
    test::WorldFixture page;
};

// The deepest any moving shape lies in any static one (negative: none touches one).
struct Deepest {
    double depth = -std::numeric_limits<double>::infinity();
    std::size_t moving = 0;
    std::size_t fixed = 0;
};

Deepest deepestInStatic(const engine::Core& core) {
    Deepest deepest;
    for (std::size_t i = 0; i < core.objectCount(); ++i) {
        if (core.object(i).isStatic()) continue;
        for (std::size_t j = 0; j < core.objectCount(); ++j) {
            if (!core.object(j).isStatic()) continue;
            const double d = depth(core.object(i), core.object(j));
            if (d > deepest.depth) deepest = {d, i, j};
        }
    }
    return deepest;
}

std::vector<std::size_t> movingIndices(const engine::Core& core) {
    std::vector<std::size_t> found;
    for (std::size_t i = 0; i < core.objectCount(); ++i) {
        if (!core.object(i).isStatic()) found.push_back(i);
    }
    return found;
}

// Where a static rectangle reaches furthest left, right and up, from its corners.
std::array<Vec2, 4> corners(const engine::RigidShape& wall) {
    return oracle::corners(std::get<oracle::Box>(outline(wall)));
}
double leftFace(const engine::RigidShape& wall) {
    const auto c = corners(wall);
    return std::min({c[0].x, c[1].x, c[2].x, c[3].x});
}
double rightFace(const engine::RigidShape& wall) {
    const auto c = corners(wall);
    return std::max({c[0].x, c[1].x, c[2].x, c[3].x});
}
double topFace(const engine::RigidShape& wall) {
    const auto c = corners(wall);
    return std::min({c[0].y, c[1].y, c[2].y, c[3].y});
}

}  // namespace

TEST_CASE("scene library: the list here names every scene of the folder") {
    std::set<std::string> in_folder;
    for (const fs::directory_entry& entry : fs::directory_iterator(kLibrary)) {
        if (entry.path().extension() == ".json") in_folder.insert(entry.path().stem().string());
    }
    CHECK(in_folder == std::set<std::string>(kScenes.begin(), kScenes.end()));
}

TEST_CASE("scene library: every scene sets its whole world and keeps to the 800 x 450 canvas") {
    // Defaults that differ from the book's in every key: a key a scene leaves out would
    // show up as a difference between the two loads.
    // (Keys of the later stages' own, such as broad_phase, no scene sets: the library
    // runs on the book's engine, 5.1, and on every stage after it.)
    for (const std::string& name : kScenes) {
        INFO(name);
        engine::WorldSettings odd = engine::kBookWorld;
        odd.width = 640;
        odd.height = 480;
        odd.gravity = {1, 2};
        odd.dt = 0.01;
        odd.relaxation_iterations = 3;
        odd.correction_rate = 0.5;
        odd.movement = !engine::kBookWorld.movement;
        odd.positional_correction = !engine::kBookWorld.positional_correction;
        odd.remove_out_of_bounds = !engine::kBookWorld.remove_out_of_bounds;
        const engine::Scene scene = load(name);
        std::vector<engine::BodyDescription> bodies;
        const browser::SceneList body_list = engine::bodyList(bodies);
        browser::load_scene(kLibrary / (name + ".json"), engine::worldKeys(odd), {&body_list, 1});
        CHECK(odd == scene.world);
        CHECK(scene.world.movement);
        CHECK(scene.world.width == 800);
        CHECK(scene.world.height == 450);
        CHECK(scene.world.dt == 1.0 / 60.0);
        CHECK(scene.world.relaxation_iterations == 15);
        CHECK(scene.world.correction_rate == 0.8);
        CHECK(scene.world.positional_correction);
        // Static bodies first, and every centre on the canvas.
        bool moving_seen = false;
        for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
            const engine::BodyDescription& body = scene.bodies[i];
            INFO("body " << i);
            if (body.mass == 0) CHECK_FALSE(moving_seen);
            moving_seen = moving_seen || body.mass > 0;
            CHECK(body.center.x >= 0);
            CHECK(body.center.x <= 800);
            CHECK(body.center.y >= 0);
            CHECK(body.center.y <= 450);
        }
    }
}

TEST_CASE("scene library: every scene runs 600 steps with finite numbers and nothing buried in a static shape") {
    const std::string name = GENERATE(from_range(kScenes));
    INFO(name);
    SceneRun run(name);
    REQUIRE(run.page.core.objectCount() == run.scene.bodies.size());
    for (int step = 1; step <= kSteps; ++step) {
        run.steps(1);
        for (std::size_t i = 0; i < run.page.core.objectCount(); ++i) {
            if (!finite(run.body(i))) FAIL("step " << step << ", body " << i << ": a number is NaN or infinite");
        }
    }
    // The 100:1 stack is the exception: it shows a failure (see its own test below).
    if (name == "heavy_on_light") return;
    const Deepest deepest = deepestInStatic(run.page.core);
    INFO("body " << deepest.moving << " lies " << deepest.depth << " px deep in static body " << deepest.fixed);
    CHECK(deepest.depth <= kBuriedPx);
}

TEST_CASE("scene library: pyramid: 36 boxes stand for 10 s, only creeping") {
    SceneRun run("pyramid");
    const std::vector<std::size_t> boxes = movingIndices(run.page.core);
    REQUIRE(boxes.size() == 36);
    std::vector<Vec2> start;
    for (std::size_t i : boxes) start.push_back(run.body(i).center());
    run.steps(kSteps);
    // Boxes on boxes with friction are in equilibrium: nothing should move at all. The
    // rows start 0.25 px apart (8 rows: 2 px at the top) and the one-contact-per-pair
    // rocking makes the bottom corners creep outward, about 1.5 px in 10 s; 3 px tells
    // creep from collapse.
    constexpr double kCreepPx = 3.0;
    constexpr double kTiltRad = 0.01;
    for (std::size_t k = 0; k < boxes.size(); ++k) {
        const engine::RigidShape& box = run.body(boxes[k]);
        INFO("box " << boxes[k] << " at (" << box.center().x << ", " << box.center().y << ")");
        CHECK(box.center().distance(start[k]) <= kCreepPx);
        CHECK(std::abs(std::remainder(box.angle(), std::numbers::pi / 2)) <= kTiltRad);
    }
}

TEST_CASE("scene library: rain: 200 shapes end piled up inside the open box") {
    SceneRun run("rain");
    // Static: the floor, then the left and right walls.
    REQUIRE(run.body(0).isStatic());
    REQUIRE(run.body(1).isStatic());
    REQUIRE(run.body(2).isStatic());
    const double floor_top = topFace(run.body(0));
    const double inner_left = rightFace(run.body(1));
    const double inner_right = leftFace(run.body(2));
    const std::vector<std::size_t> drops = movingIndices(run.page.core);
    REQUIRE(drops.size() == 200);
    // Spread over the floor between the walls, the shapes' own area would make a layer
    // this thick; a loose pile fills at least half its volume (random discs pack about
    // 0.8), so it stands no more than twice as high.
    double area = 0.0;
    for (std::size_t i : drops) {
        const engine::BodyDescription& body = run.scene.bodies[i];
        area += body.shape == engine::ShapeType::Circle ? std::numbers::pi * body.radius * body.radius
                                                        : body.width * body.height;
    }
    const double loosest_pile = 2 * area / (inner_right - inner_left);
    run.steps(kSteps);
    double highest = floor_top;
    double speed_sum = 0.0;
    for (std::size_t i : drops) {
        const engine::RigidShape& drop = run.body(i);
        INFO("shape " << i << " at (" << drop.center().x << ", " << drop.center().y << ")");
        CHECK(drop.center().x > inner_left);
        CHECK(drop.center().x < inner_right);
        CHECK(drop.center().y < floor_top);
        highest = std::min(highest, drop.center().y);
        speed_sum += drop.velocity().length();
    }
    // Piled, not floating or stacked on end: no centre is higher than the loosest pile
    // reaches. And nearly at rest: the drops fell at up to 100 px/s; the pile still
    // jitters by about 1 px/s.
    INFO("highest centre " << floor_top - highest << " px above the floor, loosest pile " << loosest_pile << " px");
    CHECK(highest > floor_top - loosest_pile);
    CHECK(speed_sum / drops.size() < 3.0);
}

TEST_CASE("scene library: slope: the ball rolls down at 2/3 g sin(angle), spinning as fast as it rolls") {
    SceneRun run("slope");
    const engine::RigidShape& slope = run.body(0);
    REQUIRE(slope.isStatic());
    const engine::RigidShape& ball = run.body(3);
    REQUIRE(ball.type() == engine::ShapeType::Circle);
    const double radius = static_cast<const engine::Circle&>(ball).radius();
    const Vec2 downhill{std::cos(slope.angle()), std::sin(slope.angle())};
    const Vec2 start = ball.center();
    const double g = run.scene.world.gravity.y;
    // A solid disc (I = m r^2 / 2) rolling without slipping down a slope of angle a
    // accelerates at g sin(a) / (1 + I / (m r^2)) = 2/3 g sin(a); sliding without
    // friction it would take g sin(a). 8 s in, it is still on the slope.
    constexpr int kRolling = 480;
    run.steps(kRolling);
    const double t = kRolling * run.scene.world.dt;
    const double along = (ball.center() - start).dot(downhill);
    const double rolling = 2.0 / 3.0 * g * std::sin(slope.angle()) * t * t / 2;
    INFO("rolled " << along << " px, rolling predicts " << rolling << " px");
    // 3%: the ball starts 0.5 px above the slope and slips a little while it spins up.
    CHECK(along == Approx(rolling).epsilon(0.03));
    // Still on the slope: it neither hopped off nor sank in.
    INFO("depth in the slope " << depth(ball, slope) << " px");
    CHECK(std::abs(depth(ball, slope)) < 0.5);
    // Rolling: the rim moves as fast as the centre, w r = v; clockwise on screen (w > 0)
    // for a roll to the right.
    INFO("v " << ball.velocity().length() << " px/s, w r " << ball.angularVelocity() * radius << " px/s");
    CHECK(ball.angularVelocity() * radius == Approx(ball.velocity().length()).epsilon(0.03));
}

TEST_CASE("scene library: newtons_cradle: the hit passes along the row; no energy is lost") {
    SceneRun run("newtons_cradle");
    // Static walls, then the incoming ball, then the row from left to right.
    const std::vector<std::size_t> balls = movingIndices(run.page.core);
    REQUIRE(balls.size() == 6);
    const std::size_t incoming = balls.front();
    const std::size_t last = balls.back();
    const double speed = run.body(incoming).velocity().x;
    REQUIRE(speed > 0);
    const double energy = kineticEnergy(run.page.core);
    const Vec2 momentum = test::linearMomentum(run.page.core);

    int step = 0;
    while (run.body(incoming).velocity().x > speed / 2 && step < kSteps) {
        run.steps(1);
        ++step;
    }
    REQUIRE(step < kSteps);
    run.steps(10);  // a sixth of a second after the hit, long before the last ball reaches the wall
    REQUIRE(deepestInStatic(run.page.core).depth < 0);
    // Equal balls, e = 1, no friction: the ideal cradle hands the whole velocity down the
    // row, and only the last ball moves off. The engine resolves the pairs one at a time
    // in list order, which here is the order along the row, so within one pass the
    // velocity hops from ball to ball; positional correction then shifts the touching
    // balls a fraction of a pixel but leaves velocities alone. It comes out exact;
    // 1% allows for the one-contact approximation should a ball sit slightly off the line.
    constexpr double kCradle = 0.01;
    for (std::size_t i : balls) {
        INFO("ball " << i << " velocity (" << run.body(i).velocity().x << ", " << run.body(i).velocity().y << ")");
        if (i == last) {
            CHECK(run.body(i).velocity().x == Approx(speed).epsilon(kCradle));
        } else {
            CHECK(run.body(i).velocity().length() <= kCradle * speed);
        }
    }
    CHECK(test::linearMomentum(run.page.core).x == Approx(momentum.x).epsilon(1e-9));

    // Elastic, frictionless hits (the walls too: e = 1, and a circle's normal runs
    // through its centre, so nothing spins) keep the energy for the whole run.
    run.steps(kSteps - step - 10);
    CHECK(kineticEnergy(run.page.core) == Approx(energy).epsilon(1e-9));
}

TEST_CASE("scene library: billiards: the break scatters the rack, keeping momentum and energy") {
    SceneRun run("billiards");
    const std::vector<std::size_t> balls = movingIndices(run.page.core);
    REQUIRE(balls.size() == 16);
    std::vector<Vec2> start;
    for (std::size_t i : balls) start.push_back(run.body(i).center());
    const Vec2 momentum = test::linearMomentum(run.page.core);
    const double energy = kineticEnergy(run.page.core);
    REQUIRE(momentum.length() > 0);

    // No gravity and no friction: until a ball reaches a cushion only ball-ball impulses
    // act, equal and opposite, so the total momentum is kept to rounding. A step whose
    // collision pass finds a ball touching a cushion may change it.
    int step = 0;
    for (; step < kSteps && deepestInStatic(run.page.core).depth < 0; ++step) {
        run.steps(1);
        const Vec2 now = test::linearMomentum(run.page.core);
        INFO("step " << step + 1);
        CHECK((now - momentum).length() <= 1e-9 * momentum.length());
    }
    INFO("first cushion contact before step " << step + 1);
    CHECK(step > 30);  // the cue ball needs half a second to reach the rack
    run.steps(kSteps - step);

    // e = 1 everywhere and no spin: every impulse, ball-ball or ball-cushion, keeps the
    // kinetic energy, so it is kept for the whole 10 s.
    CHECK(kineticEnergy(run.page.core) == Approx(energy).epsilon(1e-9));
    // Scattered: every ball of the rack has left its place by more than its diameter.
    for (std::size_t k = 1; k < balls.size(); ++k) {
        INFO("ball " << balls[k]);
        CHECK(run.body(balls[k]).center().distance(start[k]) > 20);
    }
}

TEST_CASE("scene library: tunnelling: the fast ball passes through the thin wall, never seen touching it") {
    // The opposite of what the other scenes promise, on purpose (chapter 3's warning
    // about discrete time steps): at 1500 px/s the ball moves 25 px per step, more than
    // its 16 px diameter and the 4 px wall together, so no step finds it overlapping.
    engine::Scene scene = load("tunnelling");
#if __has_include("continuous.h")
    scene.world.continuous = false;  // 5.6: the book's discrete step; its sweep stops the ball (its stage test)
#endif
    SceneRun run(std::move(scene));
    const engine::RigidShape& wall = run.body(0);
    REQUIRE(wall.isStatic());
    REQUIRE(wall.type() == engine::ShapeType::Rectangle);
    const engine::RigidShape& fast = run.body(3);
    const engine::RigidShape& slow = run.body(4);
    REQUIRE(fast.velocity().x > 1000);
    REQUIRE(slow.velocity().x < 200);
    REQUIRE(fast.center().x < wall.center().x);
    REQUIRE(slow.center().x < wall.center().x);
    double closest = -std::numeric_limits<double>::infinity();
    for (int step = 0; step < kSteps; ++step) {
        run.steps(1);
        closest = std::max(closest, depth(fast, wall));
    }
    INFO("the fast ball came within " << -closest << " px of the wall");
    CHECK(closest < 0);
    CHECK(fast.center().x > rightFace(wall));
    // The same wall stops a slow ball: it bounces back and stays on the near side.
    CHECK(slow.center().x < leftFace(wall));
    CHECK(slow.velocity().x <= 0);
}

TEST_CASE("scene library: heavy_on_light: a 100:1 mass ratio presses the light box into the floor") {
    // What the scene shows is a failure of the book's solver, pinned here so the README
    // stays true. Ideally both boxes would just sit there. But every relaxation pass
    // corrects floor/light before light/heavy (pairs go in list order), and the
    // light/heavy correction moves the light box 100 times as far as the heavy one:
    // each pass ends with the light box pushed back into the floor, and the heavy box's
    // weight is never fully carried. Within 10 s the light box sinks several px into the
    // floor; run longer (README) and it is squeezed out sideways.
    SceneRun run("heavy_on_light");
    const engine::RigidShape& floor = run.body(0);
    const engine::RigidShape& light = run.body(1);
    const engine::RigidShape& heavy = run.body(2);
    REQUIRE(floor.isStatic());
    REQUIRE(light.mass() == 1);
    REQUIRE(heavy.mass() == 100);
    run.steps(kSteps);
    INFO("light box " << depth(light, floor) << " px in the floor, heavy box " << depth(heavy, light)
                      << " px in the light one; heavy box's velocity " << heavy.velocity().y << " px/s");
    // Still a stack: the heavy box is on top of the light one, which is on the floor.
    CHECK(heavy.center().y < light.center().y);
    CHECK(std::abs(heavy.center().x - light.center().x) < 20);
    CHECK(depth(heavy, floor) < 0);
    // The failure: the light box is pressed into the floor (a correct solver: 0 px).
    CHECK(depth(light, floor) > 3);
}

TEST_CASE("scene library: book_demo: the book's four platforms, and 20 shapes within its random ranges") {
    const engine::Scene scene = load("book_demo");
    CHECK(scene.world.gravity == Vec2{0, 20});
    CHECK(scene.world.remove_out_of_bounds);
    REQUIRE(scene.bodies.size() == 24);
    struct Platform {
        Vec2 center;
        double width, height, angle, friction, restitution;
    };
    const engine::BodyDescription defaults;
    const Platform platforms[] = {{{500, 200}, 400, 20, 2.8, 0.3, 0},
                                  {{200, 400}, 400, 20, 0, 1, 0.5},
                                  {{100, 200}, 200, 20, 0, defaults.friction, defaults.restitution},
                                  {{10, 360}, 20, 100, 0, 0, 1}};
    for (std::size_t i = 0; i < 4; ++i) {
        INFO("platform " << i);
        const engine::BodyDescription& body = scene.bodies[i];
        CHECK(body.shape == engine::ShapeType::Rectangle);
        CHECK(body.mass == 0);
        CHECK(body.center == platforms[i].center);
        CHECK(body.width == platforms[i].width);
        CHECK(body.height == platforms[i].height);
        CHECK(body.angle == platforms[i].angle);
        CHECK(body.friction == platforms[i].friction);
        CHECK(body.restitution == platforms[i].restitution);
    }
    // Then, ten times, a rectangle and a circle, as the book's loop makes them.
    for (std::size_t i = 4; i < scene.bodies.size(); ++i) {
        INFO("body " << i);
        const engine::BodyDescription& body = scene.bodies[i];
        CHECK(body.shape == (i % 2 == 0 ? engine::ShapeType::Rectangle : engine::ShapeType::Circle));
        CHECK((body.center.x >= 0 && body.center.x <= 800));
        CHECK((body.center.y >= 0 && body.center.y <= 225));
        if (body.shape == engine::ShapeType::Rectangle) {
            CHECK((body.width >= 10 && body.width <= 60));
            CHECK((body.height >= 10 && body.height <= 60));
        } else {
            CHECK((body.radius >= 10 && body.radius <= 30));
        }
        CHECK((body.mass > 0 && body.mass <= 30));
        CHECK((body.friction >= 0 && body.friction <= 1));
        CHECK((body.restitution >= 0 && body.restitution <= 1));
        CHECK((body.velocity.x >= -30 && body.velocity.x <= 30));
        CHECK((body.velocity.y >= -30 && body.velocity.y <= 30));
        CHECK(body.angle == 0);
        CHECK(body.angular_velocity == 0);
    }
}

}  // namespace scene_library_test
