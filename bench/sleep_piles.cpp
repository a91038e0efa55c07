#include "sleep_piles.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <numbers>

#include "random.h"
#include "stages.h"

namespace bench::piles {
namespace {

using bench::BodyDescription;
using bench::Shape;

constexpr double kWall = 20.0;    // px: thickness of the floor and the walls
constexpr double kMargin = 20.0;  // px: free canvas around the box
// Each lattice cell holds the largest shape turned any way (a square is 1.42 times its
// side across its corners) with room to jitter by a pixel.
constexpr double kCellPerSize = 1.45;
constexpr double kJitter = 1.0;          // px, either way
constexpr double kDrop = 5.0;            // px from the floor to the lowest cell
constexpr double kSidewaysSpeed = 10.0;  // px/s, either way: the pile does not fall as a block
constexpr double kUnitArea = 225.0;      // px^2 to a mass of 1, as the bench's rain

double uniform(browser::Random& random, double low, double high) { return low + (high - low) * random.next(); }

double meanSize(const PileRecipe& recipe) { return (recipe.smallest + recipe.largest) / 2; }

BodyDescription shape(browser::Random& random, const PileRecipe& recipe, Vec2 center) {
    BodyDescription body;
    body.center = center;
    body.friction = recipe.friction;
    body.restitution = recipe.restitution;
    body.velocity = {uniform(random, -kSidewaysSpeed, kSidewaysSpeed), 0.0};
    const double size = uniform(random, recipe.smallest, recipe.largest);
    const bool square = recipe.kinds == Kinds::squares || (recipe.kinds == Kinds::mixed && random.next() < 0.5);
    if (square) {
        body.shape = Shape::rectangle;
        body.width = body.height = size;
        body.angle = uniform(random, 0.0, std::numbers::pi / 2);
        body.mass = size * size / kUnitArea;
    } else {
        body.shape = Shape::circle;
        body.radius = size / 2;
        body.mass = std::numbers::pi * body.radius * body.radius / kUnitArea;
    }
    return body;
}

}  // namespace

std::string_view spelling(Kinds kinds) {
    switch (kinds) {
        case Kinds::circles: return "circles";
        case Kinds::squares: return "squares";
        case Kinds::mixed: return "mixed";
    }
    return "mixed";
}

int shapeCount(const PileRecipe& recipe) { return recipe.across * recipe.layers; }

SceneDescription pile(const PileRecipe& recipe) {
    const double inside = recipe.across * meanSize(recipe);
    const double cell = recipe.kinds == Kinds::circles ? recipe.largest + 2 * kJitter : kCellPerSize * recipe.largest;
    const int columns = std::max(1, static_cast<int>(std::floor(inside / cell)));
    const int count = shapeCount(recipe);
    const int rows = (count + columns - 1) / columns;

    SceneDescription scene;
    scene.world = book_world();
    scene.world.width = inside + 2 * (kWall + kMargin);
    scene.world.height = rows * cell + kDrop + kWall + 2 * kMargin;
    scene.world.gravity = {0.0, recipe.gravity};
    scene.world.remove_out_of_bounds = false;
    const double w = scene.world.width;
    const double h = scene.world.height;
    const auto wall = [&](Vec2 center, double width, double height) {
        scene.bodies.push_back({.shape = Shape::rectangle,
                                .center = center,
                                .width = width,
                                .height = height,
                                .mass = 0.0,
                                .friction = recipe.friction,
                                .restitution = recipe.restitution});
    };
    wall({w / 2, h - kMargin - kWall / 2}, w - 2 * kMargin, kWall);
    wall({kMargin + kWall / 2, h / 2}, kWall, h - 2 * kMargin);
    wall({w - kMargin - kWall / 2, h / 2}, kWall, h - 2 * kMargin);

    browser::Random random(recipe.seed);
    const double left = kMargin + kWall + (inside - columns * cell) / 2;
    const double floor_top = h - kMargin - kWall;
    for (int i = 0; i < count; ++i) {
        const Vec2 center{left + (i % columns + 0.5) * cell, floor_top - kDrop - (i / columns + 0.5) * cell};
        const Vec2 jitter{uniform(random, -kJitter, kJitter), uniform(random, -kJitter, kJitter)};
        scene.bodies.push_back(shape(random, recipe, center + jitter));
    }
    return scene;
}

SceneDescription issuePile() {
    SceneDescription scene = pile(PileRecipe{});
    scene.world.solver = Solver::sequential_impulse;
    return scene;
}

std::string describe(const PileRecipe& recipe) {
    char line[160];
    std::snprintf(line, sizeof line, "g %g, mu %g, e %g, %g-%g px, %d deep, %s, seed %llu", recipe.gravity,
                  recipe.friction, recipe.restitution, recipe.smallest, recipe.largest, recipe.layers,
                  std::string(spelling(recipe.kinds)).c_str(), static_cast<unsigned long long>(recipe.seed));
    return line;
}

}  // namespace bench::piles
