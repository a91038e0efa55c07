// The study of 5.6's continuous collision (ch5_demo/5.6_continuous_collision/README.md),
// one run, beside Box2D 2.4 with its bullets:
//   - 1,000 shots at 20,000 px/s at a 2 px static wall: circles and rectangles of random
//     size, turned and spinning at random, within 45 degrees of straight at it; 5.6 on
//     both solvers with continuous collision on and off, and Box2D with every shot a
//     bullet. A shot is through when, ten steps later, its centre is past the wall.
//   - 1,000 bullets at a 2 px plank of mass 1 that slides along its length (rotation
//     off in both engines): through when the ball is ever past the plank between its ends.
//   - the rain of 1000 (bench/scenes/rain_1000.json) with continuous on and off, on
//     both solvers: the cost of a step in processor time (bench/thread_clock.h), the two
//     runs taking turns window by window.
//   - the trade: for 1, 4 and 16 sub-steps with continuous off, and for continuous on,
//     the slowest speed at which a ball (radius 4 px) passes a 2 px wall head-on from
//     any of 16 starting phases, and the cost of a step of the rain of 1000 (sequential
//     impulse solver). Written to bench/extra_results/ccd_trade.csv and ccd_trade.png.
//
//   build/ccd_study
//
// Box2D 2.4 moves no body more than b2_maxTranslation (2 m, 60 px at the bench's 30 px
// to the metre) in a step: its shots fly at 3,600 px/s, not 20,000. Linked with stage
// 5.6's engine alone (namespace engine), as sleep_study is with 5.5's.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <memory>
#include <numbers>
#include <string>
#include <vector>

#if BENCH_HAS_BOX2D
#include <box2d/box2d.h>
#endif

#include "browser.h"
#include "charts.h"
#include "circle.h"
#include "core.h"
#include "random.h"
#include "rectangle.h"
#include "scene_io.h"
#include "thread_clock.h"

namespace {

using engine::Vec2;

constexpr int kShots = 1000;
constexpr double kShotSpeed = 20000.0;  // px/s
constexpr double kWallX = 400.0;
constexpr double kThin = 2.0;  // px: the wall's and the plank's thickness
constexpr double kPixelsPerMetre = 30.0;

// One shot, drawn from the seeded random numbers: the same for every engine.
struct Shot {
    bool circle;
    double width, height;  // a circle's radius is width / 2
    double angle, heading, spin;
};

double uniform(browser::Random& random, double low, double high) { return low + (high - low) * random.next(); }

std::vector<Shot> wallShots() {
    browser::Random random(56);
    std::vector<Shot> shots;
    for (int i = 0; i < kShots; ++i) {
        const double a = uniform(random, 8, 40), b = uniform(random, 8, 40);
        shots.push_back({i % 2 == 0, a, i % 2 == 0 ? a : b, uniform(random, -std::numbers::pi, std::numbers::pi),
                         uniform(random, -std::numbers::pi / 4, std::numbers::pi / 4), uniform(random, -30, 30)});
    }
    return shots;
}

engine::WorldSettings shootingWorld(engine::SolverKind solver, bool continuous, int substeps = 1) {
    engine::WorldSettings world = engine::kBookWorld;
    world.gravity = {0, 0};
    world.remove_out_of_bounds = false;
    world.sleep = false;
    world.solver = solver;
    world.continuous = continuous;
    world.substeps = substeps;
    return world;
}

struct Page {
    explicit Page(const engine::WorldSettings& world) : window(world.dt * 1000.0), core(window, world) {}
    browser::Window window;
    engine::Core core;
};

int wallThroughStage(const std::vector<Shot>& shots, engine::SolverKind solver, bool continuous) {
    int through = 0;
    for (const Shot& shot : shots) {
        Page page(shootingWorld(solver, continuous));
        page.core.add(engine::Rectangle({kWallX, 225}, kThin, 8000, {.mass = 0}));
        engine::RigidShape& shape =
            shot.circle ? static_cast<engine::RigidShape&>(page.core.add(engine::Circle({100, 225}, shot.width / 2)))
                        : page.core.add(engine::Rectangle({100, 225}, shot.width, shot.height));
        shape.rotate(shot.angle);
        shape.setVelocity(Vec2{std::cos(shot.heading), std::sin(shot.heading)} * kShotSpeed);
        shape.setAngularVelocity(shot.spin);
        for (int step = 0; step < 10; ++step) page.core.update();
        through += shape.center().x > kWallX ? 1 : 0;
    }
    return through;
}

// The plank's shots: heading within 1 rad of straight, aimed at the plank's middle.
struct PlankShot {
    double plank_speed, angle, radius;
};

std::vector<PlankShot> plankShots() {
    browser::Random random(7);
    std::vector<PlankShot> shots;
    for (int i = 0; i < kShots; ++i) {
        const double plank_speed = uniform(random, -600, 600);
        const double angle = uniform(random, -1, 1);
        shots.push_back({plank_speed, angle, uniform(random, 3, 10)});
    }
    return shots;
}

int plankThroughStage(const std::vector<PlankShot>& shots, bool bullet) {
    int through = 0;
    for (const PlankShot& shot : shots) {
        engine::WorldSettings world = shootingWorld(engine::SolverKind::book, true);
        world.rotation = false;
        Page page(world);
        const Vec2 middle{kWallX, 225};
        engine::Rectangle& plank = page.core.add(engine::Rectangle(middle, kThin, 400));
        plank.setVelocity({0, shot.plank_speed});
        const Vec2 toward{std::cos(shot.angle), std::sin(shot.angle)};
        engine::Circle& ball = page.core.add(engine::Circle(middle - toward * 300, shot.radius));
        ball.setBullet(bullet);
        ball.setVelocity(toward * kShotSpeed);
        bool passed = false;
        for (int step = 0; step < 10 && !passed; ++step) {
            page.core.update();
            const Vec2 from_middle = ball.center() - plank.center();
            passed = from_middle.x > 0 && std::abs(from_middle.y) < 200;
        }
        through += passed ? 1 : 0;
    }
    return through;
}

#if BENCH_HAS_BOX2D
b2Vec2 metres(Vec2 px) {
    return {static_cast<float>(px.x / kPixelsPerMetre), static_cast<float>(px.y / kPixelsPerMetre)};
}

b2Body* box2dBody(b2World& world, b2BodyType type, Vec2 center, double angle, const b2Shape& shape, bool bullet,
                  bool fixed_rotation) {
    b2BodyDef definition;
    definition.type = type;
    definition.position = metres(center);
    definition.angle = static_cast<float>(angle);
    definition.bullet = bullet;
    definition.fixedRotation = fixed_rotation;
    b2Body* body = world.CreateBody(&definition);
    b2FixtureDef fixture;
    fixture.shape = &shape;
    fixture.density = 1.0f;
    fixture.friction = 0.8f;
    fixture.restitution = 0.2f;
    body->CreateFixture(&fixture);
    return body;
}

b2PolygonShape box2dBox(double width, double height) {
    b2PolygonShape box;
    box.SetAsBox(static_cast<float>(width / 2 / kPixelsPerMetre), static_cast<float>(height / 2 / kPixelsPerMetre));
    return box;
}

constexpr float kStep = 1.0f / 60.0f;

int wallThroughBox2d(const std::vector<Shot>& shots) {
    int through = 0;
    for (const Shot& shot : shots) {
        b2World world(b2Vec2(0, 0));
        box2dBody(world, b2_staticBody, {kWallX, 225}, 0, box2dBox(kThin, 8000), false, false);
        b2CircleShape disc;
        disc.m_radius = static_cast<float>(shot.width / 2 / kPixelsPerMetre);
        const b2PolygonShape box = box2dBox(shot.width, shot.height);
        b2Body* body = box2dBody(world, b2_dynamicBody, {100, 225}, shot.angle,
                                 shot.circle ? static_cast<const b2Shape&>(disc) : box, true, false);
        body->SetLinearVelocity(metres(Vec2{std::cos(shot.heading), std::sin(shot.heading)} * kShotSpeed));
        body->SetAngularVelocity(static_cast<float>(shot.spin));
        for (int step = 0; step < 10; ++step) world.Step(kStep, 8, 3);
        through += body->GetPosition().x * kPixelsPerMetre > kWallX ? 1 : 0;
    }
    return through;
}

int plankThroughBox2d(const std::vector<PlankShot>& shots) {
    int through = 0;
    for (const PlankShot& shot : shots) {
        b2World world(b2Vec2(0, 0));
        const Vec2 middle{kWallX, 225};
        b2Body* plank = box2dBody(world, b2_dynamicBody, middle, 0, box2dBox(kThin, 400), false, true);
        plank->SetLinearVelocity(metres({0, shot.plank_speed}));
        b2CircleShape disc;
        disc.m_radius = static_cast<float>(shot.radius / kPixelsPerMetre);
        const Vec2 toward{std::cos(shot.angle), std::sin(shot.angle)};
        b2Body* ball = box2dBody(world, b2_dynamicBody, middle - toward * 300, 0, disc, true, true);
        ball->SetLinearVelocity(metres(toward * kShotSpeed));
        bool passed = false;
        for (int step = 0; step < 10 && !passed; ++step) {
            world.Step(kStep, 8, 3);
            const b2Vec2 from_middle = ball->GetPosition() - plank->GetPosition();
            passed = from_middle.x > 0 && std::abs(from_middle.y * kPixelsPerMetre) < 200;
        }
        through += passed ? 1 : 0;
    }
    return through;
}
#endif

// The cost of a step of the rain of 1000, in us: `steps` steps of each world, the worlds
// taking turns 30 steps at a time, so a busy moment of the machine hits both alike.
std::vector<double> rainCosts(const std::vector<engine::WorldSettings>& worlds, int steps) {
    const engine::Scene scene = engine::loadScene(std::filesystem::path(BENCH_SCENES_DIR) / "rain_1000.json");
    std::vector<std::unique_ptr<Page>> pages;
    for (engine::WorldSettings world : worlds) {
        const engine::WorldSettings file = scene.world;
        world.gravity = file.gravity;
        world.width = file.width;
        world.height = file.height;
        world.dt = file.dt;
        pages.push_back(std::make_unique<Page>(world));
        engine::buildScene(pages.back()->core, scene.bodies);
    }
    std::vector<double> seconds(worlds.size(), 0.0);
    for (int done = 0; done < steps; done += 30) {
        for (std::size_t k = 0; k < pages.size(); ++k) {
            const double start = bench::thread_cpu_seconds();
            for (int step = 0; step < 30; ++step) pages[k]->core.update();
            seconds[k] += bench::thread_cpu_seconds() - start;
        }
    }
    for (double& s : seconds) s = s * 1e6 / steps;
    return seconds;
}

// The slowest speed (from 60 px/s up by 2 % at a time, to 1e6 px/s) at which a ball of
// radius 4 px shot head-on at a 2 px static wall ends past it, from any of 16 starts a
// sixteenth of a step apart; 0 when none passes.
double firstThrough(int substeps, bool continuous) {
    for (double speed = 60; speed <= 1e6; speed *= 1.02) {
        for (int phase = 0; phase < 16; ++phase) {
            Page page(shootingWorld(engine::SolverKind::sequential_impulse, continuous, substeps));
            page.core.add(engine::Rectangle({kWallX + kThin / 2, 225}, kThin, 400, {.mass = 0}));
            const double back = speed / 60 * phase / 16;
            engine::Circle& ball = page.core.add(engine::Circle({kWallX - 4 - back - 1, 225}, 4));
            ball.setVelocity({speed, 0});
            for (int step = 0; step < 6; ++step) page.core.update();
            if (ball.center().x > kWallX + kThin) return speed;
        }
    }
    return 0.0;
}

}  // namespace

int main() {
    const std::vector<Shot> shots = wallShots();
    std::printf(
        "1,000 shots at 20,000 px/s through a 2 px static wall (circles and rectangles, random angles and spins):\n");
    for (engine::SolverKind solver : {engine::SolverKind::book, engine::SolverKind::sequential_impulse}) {
        const char* name = solver == engine::SolverKind::book ? "book's passes" : "sequential impulse";
        std::printf("  5.6 %s: continuous on %d through, off %d through\n", name, wallThroughStage(shots, solver, true),
                    wallThroughStage(shots, solver, false));
    }
    const std::vector<PlankShot> planks = plankShots();
    std::printf("1,000 shots at 20,000 px/s at a 2 px plank of mass 1, sliding at up to 600 px/s (rotation off):\n");
    std::printf("  5.6 bullets: %d through; not bullets: %d through\n", plankThroughStage(planks, true),
                plankThroughStage(planks, false));
#if BENCH_HAS_BOX2D
    std::printf(
        "  Box2D 2.4 (bullets, shots capped at 3,600 px/s by b2_maxTranslation): wall %d through, plank %d through\n",
        wallThroughBox2d(shots), plankThroughBox2d(planks));
#endif

    std::printf("rain of 1000, cost of a step (10 s, the two runs taking turns):\n");
    for (engine::SolverKind solver : {engine::SolverKind::sequential_impulse, engine::SolverKind::book}) {
        const std::vector<double> cost = rainCosts({shootingWorld(solver, true), shootingWorld(solver, false)},
                                                   solver == engine::SolverKind::book ? 300 : 600);
        std::printf("  %s: continuous on %.0f us, off %.0f us: %+.1f %%\n",
                    solver == engine::SolverKind::book ? "book's passes (5 s)" : "sequential impulse", cost[0], cost[1],
                    100.0 * (cost[0] / cost[1] - 1.0));
    }

    struct Trade {
        std::string name;
        int substeps;
        bool continuous;
    };
    const Trade trades[] = {
        {"1 sub-step", 1, false}, {"4 sub-steps", 4, false}, {"16 sub-steps", 16, false}, {"continuous on", 1, true}};
    std::vector<engine::WorldSettings> worlds;
    for (const Trade& trade : trades) {
        worlds.push_back(shootingWorld(engine::SolverKind::sequential_impulse, trade.continuous, trade.substeps));
    }
    const std::vector<double> costs = rainCosts(worlds, 120);
    const std::filesystem::path results(BENCH_EXTRA_RESULTS_DIR);
    std::ofstream csv(results / "ccd_trade.csv");
    csv << "setting,first_through_px_per_s,rain_1000_us_per_step\n";
    bench::Chart chart{.title = "a 4 px ball at a 2 px wall: sub-steps against continuous collision",
                       .x_label = "cost of a step of the rain of 1000 (us)",
                       .y_label = "slowest speed through (px/s)",
                       .log_x = true,
                       .log_y = true};
    std::printf(
        "the trade (sequential impulse solver):\n  setting | slowest speed through | rain of 1000, us a step\n");
    for (std::size_t k = 0; k < std::size(trades); ++k) {
        const double through = firstThrough(trades[k].substeps, trades[k].continuous);
        csv << trades[k].name << ',' << through << ',' << costs[k] << '\n';
        std::printf("  %s | %s | %.0f\n", trades[k].name.c_str(),
                    through > 0 ? (std::to_string(std::lround(through)) + " px/s").c_str() : "none up to 1e6 px/s",
                    costs[k]);
        // None through up to 1e6 px/s is drawn at 1e6, labelled so.
        chart.series.push_back(
            {.name = trades[k].name,
             .points = {{costs[k], through > 0 ? through : 1e6, through > 0 ? "" : "none through"}}});
    }
    bench::write_chart(chart, results / "ccd_trade.png");
    return 0;
}
