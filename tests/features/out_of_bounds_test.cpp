// Shapes that leave the canvas (every stage from 5.1 on, world key remove_out_of_bounds):
// a shape whose centre is off the canvas, past any of its four edges, is removed at the
// end of the step; one exactly on an edge is not off it. The canvas here is 640 x 400,
// set by a scene file, so that an edge measured on the wrong side or the wrong axis
// shows (no edge equals another, nor the book's 800 x 450).
#include <catch2/catch.hpp>

#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

#include "circle.h"
#include "core.h"
#include "expect.h"
#include "near.h"
#include "world_fixture.h"
#include "world_from_scene.h"

namespace out_of_bounds_test {

using engine::Circle;
using engine::Vec2;

namespace {

constexpr double kWidth = 640, kHeight = 400;

// The page main.cpp makes for a scene: its canvas as large as the scene's world.
struct ScenePage {
    explicit ScenePage(const std::string& more_world_keys)
        : world(test::worldFromScene(R"({"width": 640, "height": 400)" + more_world_keys + "}")),
          window(world.dt * 1000.0, browser::Document{browser::Canvas(static_cast<int>(std::ceil(world.width)),
                                                                      static_cast<int>(std::ceil(world.height)))}),
          core(window, world) {}
    engine::WorldSettings world;
    browser::Window window;
    engine::Core core;
};

std::vector<Vec2> centres(const engine::Core& core) {
    std::vector<Vec2> found;
    for (std::size_t i = 0; i < core.objectCount(); ++i) found.push_back(core.object(i).center());
    return found;
}

}  // namespace

TEST_CASE("out of bounds: past each of the four edges a shape is removed; on the edge it stays") {
    // Movement off: nothing moves, so each step removes exactly the shapes placed off the
    // canvas. A quarter of a pixel past an edge is off it; exactly on it is not.
    struct Edge {
        const char* name;
        Vec2 on, past;
    };
    const Edge edges[] = {
        {"left", {0, 100}, {-0.25, 200}},
        {"right", {kWidth, 100}, {kWidth + 0.25, 200}},
        {"top", {100, 0}, {200, -0.25}},
        {"bottom", {100, kHeight}, {200, kHeight + 0.25}},
    };
    for (const Edge& edge : edges) {
        INFO(edge.name << " edge");
        ScenePage page(R"(, "movement": false)");
        // the demo's default
        test::requireEqual("the world's remove_out_of_bounds: on, the demo's default", true,
                           page.world.remove_out_of_bounds);
        test::requireEqual("the canvas width, px", kWidth, page.core.width());
        test::requireEqual("the canvas height, px", kHeight, page.core.height());
        const Vec2 inside{500, 300};
        page.core.add(Circle(edge.on, 5));
        page.core.add(Circle(edge.past, 5));
        page.core.add(Circle(inside, 5));
        page.core.update();
        test::expectEqual(
            "the centres left after a step: the ball on the edge and the one inside stay, the one 0.25 px past goes",
            std::vector<Vec2>{edge.on, inside}, centres(page.core));
        page.core.update();
        test::expectEqual("objects after another step: the two on the canvas stay", 2, page.core.objectCount());
    }
}

TEST_CASE("out of bounds: remove_out_of_bounds false keeps shapes off the canvas, moving as before") {
    ScenePage page(R"(, "remove_out_of_bounds": false, "gravity": [0, 20])");
    test::requireEqual("the world's remove_out_of_bounds, as the scene sets it", false,
                       page.world.remove_out_of_bounds);
    Circle& far_out = page.core.add(Circle({-300, kHeight + 50}, 5));
    page.core.add(Circle({kWidth + 0.25, 100}, 5));
    for (int step = 0; step < 60; ++step) page.core.update();
    test::expectEqual("objects after 60 steps with remove_out_of_bounds false: both kept, off the canvas", 2,
                      page.core.objectCount());
    // Still simulated: 60 steps of a fall from rest, symplectic Euler, g dt^2 60 61 / 2.
    // (1e-9 px: rounding of 60 steps on coordinates of a few hundred px.)
    const double dt = page.world.dt;
    CHECK_THAT(far_out.center(), test::near(Vec2{-300, kHeight + 50 + 20 * dt * dt * 60 * 61 / 2}, 1e-9));
}

TEST_CASE("out of bounds: a shape is removed at the end of the step that takes it off, after every shape moved") {
    // Three balls falling from rest; the middle one also moves right at 60 px/s, 1 px a
    // step, from half a pixel inside the right edge. The book removes a shape in the
    // middle of its loop over the shapes, so the one after it slides into its place and
    // misses its step; here every shape takes its step, then the removal comes.
    ScenePage page(R"(, "movement": true, "gravity": [0, 20])");
    Circle& first = page.core.add(Circle({100, 100}, 5));
    page.core.add(Circle({kWidth - 0.5, 100}, 5)).setVelocity({60, 0});
    page.core.add(Circle({300, 100}, 5));
    page.core.update();
    test::requireEqual("objects after the step: the middle ball, past the right edge, removed", 2,
                       page.core.objectCount());
    const double fallen = 20 * page.world.dt * page.world.dt;
    test::expectEqual("the first ball's centre after the step, px: it took its step", Vec2{100, 100 + fallen},
                      first.center());
    test::expectEqual("the third ball's centre after the step, px: it took its step too, though the one before it went",
                      Vec2{300, 100 + fallen}, page.core.object(1).center());
}

TEST_CASE("out of bounds: the selection stays on its index, and goes back to object 0 once past the end") {
    // The book's selection is an index (gObjectNum); a removal moves the shapes after it
    // down the list. An index left past the end would select nothing: it becomes 0.
    struct Case {
        std::size_t selected;
        std::size_t removed;
        std::size_t then_selected;
    };
    const Case cases[] = {{0, 2, 0}, {1, 2, 1}, {2, 2, 0}, {2, 0, 0}, {1, 0, 1}};
    for (const Case& c : cases) {
        INFO("object " << c.selected << " selected, object " << c.removed << " removed");
        ScenePage page(R"(, "movement": false)");
        for (std::size_t i = 0; i < 3; ++i) {
            page.core.add(Circle({i == c.removed ? -10.0 : 100.0 + 100.0 * static_cast<double>(i), 100}, 5));
        }
        page.core.select(c.selected);
        page.core.update();
        test::requireEqual("objects after the step: the one off the canvas removed", 2, page.core.objectCount());
        test::expectEqual("the selected index after the removal (the book's gObjectNum)", c.then_selected,
                          page.core.selectedIndex());
    }
}

}  // namespace out_of_bounds_test
