#include "scene_maker.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <optional>

#include "random.h"
#include "stages.h"

namespace bench::scenes {
namespace {

// Each scene has its own seed, so changing one scene never changes another.
constexpr std::uint64_t kRainSeed = 101;
constexpr std::uint64_t kGasSeed = 102;
constexpr std::uint64_t kScaleSeed = 103;

constexpr double kWall = 20.0;    // px: thickness of floors and walls
constexpr double kMargin = 20.0;  // px: free canvas around a box

// The book's world at this size, keeping every body; gravity as the book's unless given.
WorldDescription world_of(double width, double height, std::optional<double> gravity = std::nullopt) {
    WorldDescription world = book_world();
    world.width = width;
    world.height = height;
    if (gravity) world.gravity = {0.0, *gravity};
    world.remove_out_of_bounds = false;
    return world;
}

// A body's fields as a reader reads them, which the layout would put one a line:
// clang-format off
BodyDescription fixed_box(Vec2 center, double width, double height, double friction, double restitution) {
    return {.shape = Shape::rectangle, .center = center, .width = width, .height = height, .mass = 0.0,
            .friction = friction, .restitution = restitution};
}
// clang-format on

double uniform(browser::Random& random, double low, double high) { return low + (high - low) * random.next(); }

struct SizeRange {
    double low;
    double high;
};

// A box (sides drawn from `box_sides`, turned at random) or a disc (diameter drawn
// from `disc_across`), one as likely as the other. The mass goes with the area,
// `unit_area` px^2 to a mass of 1, so big shapes do not ride on small ones as heavily
// as a 100:1 load, which the relaxation cannot carry (ch5_demo/scenes/heavy_on_light).
BodyDescription random_shape(browser::Random& random, Vec2 center, SizeRange box_sides, SizeRange disc_across,
                             double unit_area) {
    BodyDescription body;
    body.center = center;
    if (random.next() < 0.5) {
        body.shape = Shape::rectangle;
        body.width = uniform(random, box_sides.low, box_sides.high);
        body.height = uniform(random, box_sides.low, box_sides.high);
        body.angle = uniform(random, 0.0, std::numbers::pi);
        body.mass = body.width * body.height / unit_area;
    } else {
        body.shape = Shape::circle;
        body.radius = uniform(random, disc_across.low, disc_across.high) / 2;
        body.mass = std::numbers::pi * body.radius * body.radius / unit_area;
    }
    return body;
}

// Floor and two walls of an open box, or four walls of a closed one, kMargin inside
// the canvas's edges.
void add_walls(SceneDescription& scene, bool closed, double friction, double restitution) {
    const double w = scene.world.width;
    const double h = scene.world.height;
    const double side_height = h - 2 * kMargin;
    scene.bodies.push_back(fixed_box({w / 2, h - kMargin - kWall / 2}, w - 2 * kMargin, kWall, friction, restitution));
    scene.bodies.push_back(fixed_box({kMargin + kWall / 2, h / 2}, kWall, side_height, friction, restitution));
    scene.bodies.push_back(fixed_box({w - kMargin - kWall / 2, h / 2}, kWall, side_height, friction, restitution));
    if (closed) {
        scene.bodies.push_back(fixed_box({w / 2, kMargin + kWall / 2}, w - 2 * kMargin, kWall, friction, restitution));
    }
}

}  // namespace

SceneDescription pyramid(int rows) {
    constexpr double kSide = 30.0;
    constexpr double kPitch = kSide + 1.0;      // 1 px between neighbours
    constexpr double kRowPitch = kSide + 0.25;  // 0.25 px above the support
    const double base_width = rows * kPitch;
    SceneDescription scene;
    scene.world = world_of(std::max(800.0, base_width + 300.0), std::max(450.0, rows * kRowPitch + 150.0));
    const double floor_top = scene.world.height - 40.0;
    const double middle = scene.world.width / 2;
    scene.bodies.push_back(fixed_box({middle, floor_top + kWall / 2}, base_width + 200.0, kWall, 0.8, 0.0));
    for (int row = 0; row < rows; ++row) {
        const int boxes = rows - row;
        const double y = floor_top - 0.25 - kSide / 2 - row * kRowPitch;
        for (int k = 0; k < boxes; ++k) {
            const double x = middle + (k - (boxes - 1) / 2.0) * kPitch;
            scene.bodies.push_back(
                {.shape = Shape::rectangle, .center = {x, y}, .width = kSide, .height = kSide, .restitution = 0.0});
        }
    }
    return scene;
}

SceneDescription rain(int shapes) {
    // The lattice is half again as wide as tall, and each cell holds the largest shape
    // turned any way (a 16 px box is 22.6 px across its corners) with room to jitter.
    constexpr double kPitch = 26.0;
    constexpr double kDrop = 30.0;  // px from the floor to the lowest row
    const int columns = static_cast<int>(std::ceil(1.5 * std::sqrt(static_cast<double>(shapes))));
    const int rows = (shapes + columns - 1) / columns;
    SceneDescription scene;
    scene.world =
        world_of(columns * kPitch + 2 * (kWall + kMargin), rows * kPitch + kDrop + kWall + 2 * kMargin + 40.0, 100.0);
    add_walls(scene, false, 0.8, 0.2);

    browser::Random random(kRainSeed);
    const double left = kMargin + kWall;
    const double floor_top = scene.world.height - kMargin - kWall;
    for (int i = 0; i < shapes; ++i) {
        const Vec2 cell{left + (i % columns + 0.5) * kPitch, floor_top - kDrop - (i / columns + 0.5) * kPitch};
        const Vec2 jitter{uniform(random, -1.0, 1.0), uniform(random, -1.0, 1.0)};
        BodyDescription body = random_shape(random, cell + jitter, {10.0, 16.0}, {10.0, 18.0}, 225.0);
        body.velocity = {uniform(random, -10.0, 10.0), uniform(random, 0.0, 30.0)};
        scene.bodies.push_back(body);
    }
    return scene;
}

// A body's fields as a reader reads them, which the layout would put one a line:
// clang-format off
SceneDescription gas() {
    constexpr int kColumns = 10;
    constexpr int kRows = 6;
    constexpr double kSpeed = 150.0;
    SceneDescription scene;
    scene.world = world_of(800.0, 450.0, 0.0);
    add_walls(scene, true, 0.0, 1.0);

    browser::Random random(kGasSeed);
    const double inside = kMargin + kWall;
    const double pitch_x = (scene.world.width - 2 * inside) / kColumns;
    const double pitch_y = (scene.world.height - 2 * inside) / kRows;
    for (int row = 0; row < kRows; ++row) {
        for (int column = 0; column < kColumns; ++column) {
            const Vec2 center{inside + (column + 0.5) * pitch_x + uniform(random, -10.0, 10.0),
                              inside + (row + 0.5) * pitch_y + uniform(random, -10.0, 10.0)};
            const double heading = uniform(random, 0.0, 2 * std::numbers::pi);
            scene.bodies.push_back({.shape = Shape::circle, .center = center, .radius = 10.0, .friction = 0.0,
                                    .restitution = 1.0,
                                    .velocity = Vec2{std::cos(heading), std::sin(heading)} * kSpeed});
        }
    }
    return scene;
}

SceneDescription projectile() {
    SceneDescription scene;
    scene.world = world_of(800.0, 450.0, kProjectileGravity);
    scene.bodies.push_back({.shape = Shape::circle, .center = {100.0, 400.0}, .radius = 5.0,
                            .velocity = {150.0, -150.0}});
    return scene;
}

SceneDescription slide() {
    SceneDescription scene;
    scene.world = world_of(1500.0, 450.0, kSlideGravity);
    constexpr double kFloorTop = 390.0;
    scene.bodies.push_back(fixed_box({750.0, kFloorTop + kWall / 2}, 1400.0, kWall, kSlideFriction, 0.0));
    scene.bodies.push_back({.shape = Shape::rectangle, .center = {150.0, kFloorTop - 10.0}, .width = 40.0,
                            .height = 20.0, .friction = kSlideFriction, .restitution = 0.0,
                            .velocity = {kSlideSpeed, 0.0}});
    return scene;
}

SceneDescription heavy_on_light(double heavy) {
    SceneDescription scene;
    scene.world = world_of(800.0, 450.0);
    scene.bodies.push_back(fixed_box({400.0, 430.0}, 600.0, 20.0, 0.8, 0.2));
    scene.bodies.push_back({.shape = Shape::rectangle, .center = {400.0, 409.75}, .width = 100.0, .height = 20.0,
                            .mass = 1.0, .friction = 0.8, .restitution = 0.2});
    scene.bodies.push_back({.shape = Shape::rectangle, .center = {400.0, 369.5}, .width = 60.0, .height = 60.0,
                            .mass = heavy, .friction = 0.8, .restitution = 0.2});
    return scene;
}
// clang-format on

SceneDescription slope() {
    constexpr double kRadius = 20.0;
    SceneDescription scene;
    scene.world = world_of(800.0, 450.0, kSlopeGravity);
    BodyDescription ramp = fixed_box({400.0, 250.0}, 600.0, kWall, 0.8, 0.0);
    ramp.angle = kSlopeAngle;
    scene.bodies.push_back(ramp);
    // Turned by the angle, the ramp's length runs along (cos, sin), down to the right on
    // the screen, and its top face looks out along (sin, -cos).
    const Vec2 down_slope{std::cos(kSlopeAngle), std::sin(kSlopeAngle)};
    const Vec2 out_of_face{std::sin(kSlopeAngle), -std::cos(kSlopeAngle)};
    const Vec2 center = ramp.center - down_slope * 200.0 + out_of_face * (kWall / 2 + kRadius);
    scene.bodies.push_back(
        {.shape = Shape::circle, .center = center, .radius = kRadius, .friction = 0.8, .restitution = 0.0});
    return scene;
}

// A body's fields as a reader reads them, which the layout would put one a line:
// clang-format off
SceneDescription thin_wall() {
    SceneDescription scene;
    scene.world = world_of(800.0, 450.0, 0.0);
    scene.bodies.push_back(fixed_box({400.0, 225.0}, kWallThickness, 200.0, 0.0, 0.5));
    const double x = 400.0 - kWallThickness / 2 - kWallGap - kWallBallRadius;
    scene.bodies.push_back({.shape = Shape::circle, .center = {x, 225.0}, .radius = kWallBallRadius,
                            .friction = 0.0, .restitution = 0.5, .velocity = {1500.0, 0.0}});
    return scene;
}
// clang-format on

SceneDescription scale(int shapes) {
    constexpr double kPitch = 20.0;
    const int columns = static_cast<int>(std::ceil(std::sqrt(static_cast<double>(shapes))));
    const double side = columns * kPitch + 2 * kMargin;
    SceneDescription scene;
    scene.world = world_of(side, side, 0.0);
    browser::Random random(kScaleSeed);
    for (int i = 0; i < shapes; ++i) {
        const Vec2 cell{kMargin + (i % columns + 0.5) * kPitch, kMargin + (i / columns + 0.5) * kPitch};
        const Vec2 jitter{uniform(random, -3.0, 3.0), uniform(random, -3.0, 3.0)};
        BodyDescription body = random_shape(random, cell + jitter, {8.0, 14.0}, {8.0, 14.0}, 100.0);
        body.velocity = {uniform(random, -20.0, 20.0), uniform(random, -20.0, 20.0)};
        scene.bodies.push_back(body);
    }
    return scene;
}

SceneDescription spread(int shapes) {
    constexpr double kPitch = 20.0;
    constexpr double kRadius = 4.0;
    const int columns = static_cast<int>(std::ceil(std::sqrt(static_cast<double>(shapes))));
    const double side = columns * kPitch + 2 * kMargin;
    SceneDescription scene;
    scene.world = world_of(side, side, 0.0);
    for (int i = 0; i < shapes; ++i) {
        const Vec2 cell{kMargin + (i % columns + 0.5) * kPitch, kMargin + (i / columns + 0.5) * kPitch};
        scene.bodies.push_back({.shape = Shape::circle, .center = cell, .radius = kRadius});
    }
    return scene;
}

// A body's fields as a reader reads them, which the layout would put one a line:
// clang-format off
SceneDescription pair(PairKind kind) {
    SceneDescription scene;
    scene.world = world_of(800.0, 450.0);
    constexpr double kTop = 290.0;  // the top of the static shape
    if (kind == PairKind::circle_circle) {
        scene.bodies.push_back({.shape = Shape::circle, .center = {400.0, kTop + 40.0}, .radius = 40.0,
                                .mass = 0.0, .restitution = 0.0});
    } else {
        scene.bodies.push_back(fixed_box({400.0, kTop + kWall / 2}, 200.0, kWall, 0.8, 0.0));
    }
    if (kind == PairKind::rect_rect) {
        scene.bodies.push_back({.shape = Shape::rectangle, .center = {400.0, kTop - 20.0}, .width = 40.0,
                                .height = 40.0, .restitution = 0.0});
    } else {
        scene.bodies.push_back(
            {.shape = Shape::circle, .center = {400.0, kTop - 20.0}, .radius = 20.0, .restitution = 0.0});
    }
    return scene;
}
// clang-format on

// A table of the scenes in aligned columns, which the layout would put one a line:
// clang-format off
std::vector<NamedScene> shipped() {
    return {{"pyramid_10", pyramid(10)}, {"pyramid_20", pyramid(20)}, {"rain_100", rain(100)},
            {"rain_400", rain(400)},     {"rain_1000", rain(1000)},   {"rain_1600", rain(1600)},
            {"gas", gas()},              {"projectile", projectile()}, {"slide", slide()},
            {"heavy_on_light", heavy_on_light()},
            {"slope", slope()},          {"thin_wall", thin_wall()}};
}
// clang-format on

}  // namespace bench::scenes
