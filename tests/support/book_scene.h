#pragma once
// The book's own scene (MyGame) for any stage. Up to chapter 4 MyGame only places fixed
// shapes; the cool demo's (5.1) also throws random ones, so it takes the page's
// Math.random. The template only makes the choice of call wait until a stage's
// buildScene is known; no test needs to know which stage it runs against.

#include <catch2/catch.hpp>

#include <cstddef>
#include <utility>
#include <vector>

#include "expect.h"
#include "my_game.h"
#include "near.h"
#include "random.h"
#include "vec2.h"

namespace test {

template <class Core>
void buildBookScene(Core& core, browser::Random& random) {
    if constexpr (requires { engine::buildScene(core, random); }) {
        engine::buildScene(core, random);
    } else {
        engine::buildScene(core);
    }
}

// One of the cool demo's random shapes (5.1 on), as the book's MyGame.js draws it.
struct DemoShape {
    bool is_box;
    lib::Vec2 center;
    double width = 0, height = 0, radius = 0;
    double mass, friction, restitution;
    lib::Vec2 velocity;
};

// The demo's ten boxes and ten balls, drawn from `random` as the book's constructor
// calls take Math.random, worked out here from the book rather than from the stage: for
// each pair a box (centre x in [0, 800), y in the top half [0, 225), width and height
// 10 + [0, 50), mass [0, 30), friction, restitution, then the velocity set after it is
// made, each component in [-30, 30)), then a ball the same way with a radius of
// 10 + [0, 20) in place of the sides.
inline std::vector<DemoShape> demoShapesAsTheBookDraws(browser::Random& random) {
    std::vector<DemoShape> shapes;
    for (int pair = 0; pair < 10; ++pair) {
        for (const bool is_box : {true, false}) {
            DemoShape shape{.is_box = is_box};
            shape.center.x = random.next() * 800;
            shape.center.y = random.next() * 450 / 2;
            if (is_box) {
                shape.width = random.next() * 50 + 10;
                shape.height = random.next() * 50 + 10;
            } else {
                shape.radius = random.next() * 20 + 10;
            }
            shape.mass = random.next() * 30;
            shape.friction = random.next();
            shape.restitution = random.next();
            shape.velocity.x = random.next() * 60 - 30;
            shape.velocity.y = random.next() * 60 - 30;
            shapes.push_back(shape);
        }
    }
    return shapes;
}

// The borders of chapters 2 to 4 (objects 1 to 4: top, bottom, left, right) run 800 x 3
// along y = 0 and 450 and 3 x 450 along x = 0 and 800, so each corner of the canvas is a
// 1.5 x 1.5 overlap of two of them, parted by 1.5 px either way. Checks that a pass
// found exactly those four pairs, in the pass's order.
template <class Collisions>
void checkBorderCornersFound(const Collisions& found) {
    test::requireEqual("pairs found among the borders (objects 1 to 4): each corner of the canvas, where two overlap",
                       std::size_t{4}, found.size());
    const std::pair<std::size_t, std::size_t> corners[] = {{1, 3}, {1, 4}, {2, 3}, {2, 4}};
    for (std::size_t k = 0; k < 4; ++k) {
        INFO("corner " << k << ": borders " << corners[k].first << " and " << corners[k].second
                       << " (1 top, 2 bottom, 3 left, 4 right), in the pass's order");
        test::expectEqual("the pair's first object", corners[k].first, found[k].first);
        test::expectEqual("the pair's second object", corners[k].second, found[k].second);
        CHECK_THAT(found[k].info.depth(), test::near(1.5, 1e-12));  // rounding of coordinates up to 800 px
    }
}

}  // namespace test
