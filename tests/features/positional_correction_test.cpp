// Positional correction and relaxation (every stage from 4.2 on), with movement off so
// that nothing but the correction moves the shapes.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "circle.h"
#include "expect.h"
#include "my_game.h"
#include "near.h"
#include "physics.h"
#include "rectangle.h"
#include "world_fixture.h"
#include "world_from_scene.h"

namespace positional_correction_test {

using browser::Key;
using engine::Vec2;

namespace {

// Every pass removes 80% of what is left of an overlap, so after the 15 passes of one
// step 0.2^15 of it remains.
const double kLeftAfterOneStep = std::pow(1 - engine::kPosCorrectionRate, engine::kRelaxationCount);

// The deepest overlap between two shapes that are not both static.
double deepestOverlap(const engine::Core& core) {
    double deepest = 0;
    for (std::size_t i = 0; i < core.objectCount(); ++i) {
        for (std::size_t j = i + 1; j < core.objectCount(); ++j) {
            if (core.object(i).isStatic() && core.object(j).isStatic()) continue;
            if (const auto info = engine::findCollision(core.object(i), core.object(j))) {
                deepest = std::max(deepest, info->depth());
            }
        }
    }
    return deepest;
}

}  // namespace

TEST_CASE("positional correction: two circles part by inverse mass, 80% of the overlap a pass") {
    test::requireEqual("the relaxation loop's passes a step (the book's mRelaxationCount: kRelaxationCount)", 15,
                       engine::kRelaxationCount);
    test::requireEqual("the share of an overlap each pass removes (the book's mPosCorrectionRate: kPosCorrectionRate)",
                       0.8, engine::kPosCorrectionRate);
    test::WorldFixture page(test::world(false));
    // Radii 10, centres 15 apart: 5 px deep along +x. Masses 1 and 3: inverse masses 1
    // and 1/3, so the light one takes 3/4 of every move and the heavy one 1/4.
    engine::Circle& light = page.core.add(engine::Circle({100, 100}, 10, {.mass = 1}));
    engine::Circle& heavy = page.core.add(engine::Circle({115, 100}, 10, {.mass = 3}));
    page.steps(1);
    INFO(
        "two circles of radius 10, 5 px deep along x, masses 1 (light) and 3 (heavy), after one step of 15 passes, "
        "each removing 80% of what is left: the light one takes 3/4 of every move");
    const double parted = 5 * (1 - kLeftAfterOneStep);
    // 1e-12 px: the rounding of 15 passes on coordinates near 100 px (a few 1e-14 px
    // each), well below what the last pass moves (5 * 0.2^14 * 0.8 = 6.6e-10 px).
    CHECK_THAT(light.center().x, test::near(100 - parted * 3 / 4, 1e-12));
    CHECK_THAT(heavy.center().x, test::near(115 + parted / 4, 1e-12));
    test::expectEqual("the light circle's y, px: the overlap is along x only", 100.0, light.center().y);
    // The pair's centre of mass has not moved: 1 * 100 + 3 * 115 = 445.
    INFO("the pair's centre of mass, 1 x light + 3 x heavy, px: the passes move the pair apart, not along");
    CHECK_THAT(light.center().x + 3 * heavy.center().x, test::near(445, 4.5e-13));
    // The last pass still found the pair, 5 * 0.2^14 deep, and drew it.
    test::requireEqual("pairs the last of the 15 passes still found (Physics::collisions(): what it keeps)", 1u,
                       page.core.physics().collisions().size());
    CHECK_THAT(page.core.physics().collisions()[0].info.depth(), test::near(5 * kLeftAfterOneStep / 0.2, 1e-12));
}

TEST_CASE("positional correction: each pass removes correction_rate of what is left: d (1 - rate)^passes remains") {
    // The same two circles, 5 px deep, masses 1 and 3, movement off; the world read from
    // a scene file. Pass k finds the pair d (1 - rate)^(k - 1) deep and removes `rate` of
    // that, the light circle taking 3/4 of the move and the heavy one 1/4; so one step of
    // P passes leaves d (1 - rate)^P, and the last pass found d (1 - rate)^(P - 1). No
    // pass (P = 0) or a rate of 0 moves nothing; a rate of 1 parts them in the first pass.
    struct Case {
        double rate;
        int passes;
    };
    const Case cases[] = {{0.8, 15}, {0.8, 1}, {0.8, 3}, {0.5, 15}, {0.5, 2}, {0.3, 7}, {1.0, 4}, {0.0, 15}, {0.8, 0}};
    for (const Case& c : cases) {
        INFO("a scene file sets the world's correction_rate " << c.rate << " and relaxation_iterations " << c.passes
                                                              << ": the passes and the share each removes come from "
                                                                 "WorldSettings, not the book's constants");
        const engine::WorldSettings world =
            test::worldFromScene(R"({"movement": false, "correction_rate": )" + std::to_string(c.rate) +
                                 R"(, "relaxation_iterations": )" + std::to_string(c.passes) + "}");
        test::requireEqual("the scene's correction_rate, as read", c.rate, world.correction_rate);
        test::requireEqual("the scene's relaxation_iterations, as read", c.passes, world.relaxation_iterations);
        test::WorldFixture page(world);
        engine::Circle& light = page.core.add(engine::Circle({100, 100}, 10, {.mass = 1}));
        engine::Circle& heavy = page.core.add(engine::Circle({115, 100}, 10, {.mass = 3}));
        page.steps(1);
        const double left = 5 * std::pow(1 - c.rate, c.passes);
        // 1e-12 px: rounding of at most 15 passes on coordinates near 100 px; a pass more
        // or less changes the gap by at least 5 * 0.2^14 * 0.8 = 6.6e-10 px here.
        CHECK_THAT(heavy.center().x - light.center().x, test::near(20 - left, 1e-12));
        CHECK_THAT(light.center().x, test::near(100 - (5 - left) * 3 / 4, 1e-12));
        CHECK_THAT(heavy.center().x, test::near(115 + (5 - left) / 4, 1e-12));
        test::expectEqual("the light circle's velocity, px/s: positional correction moves, it does not push", Vec2{},
                          light.velocity());
        if (c.passes > 0 && c.rate < 1) {
            test::requireEqual("pairs the last pass still found", 1u, page.core.physics().collisions().size());
            CHECK_THAT(page.core.physics().collisions()[0].info.depth(),
                       test::near(5 * std::pow(1 - c.rate, c.passes - 1), 1e-12));
        }
    }
}

TEST_CASE("positional correction: a scene file's correction_rate is a share, its relaxation_iterations a whole count") {
    // correction_rate in [0, 1]: more than the whole overlap would push shapes past each
    // other. relaxation_iterations a whole number in [0, 1000], so that a step ends.
    for (const char* accepted : {R"("correction_rate": 0)", R"("correction_rate": 1)", R"("relaxation_iterations": 0)",
                                 R"("relaxation_iterations": 1000)"}) {
        INFO(accepted);
        CHECK_NOTHROW(test::worldFromScene(std::string("{") + accepted + "}"));
    }
    for (const char* refused :
         {R"("correction_rate": -0.1)", R"("correction_rate": 1.5)", R"("relaxation_iterations": -1)",
          R"("relaxation_iterations": 2.5)", R"("relaxation_iterations": 1001)"}) {
        INFO(refused);
        CHECK_THROWS_AS(test::worldFromScene(std::string("{") + refused + "}"), browser::SceneError);
    }
}

TEST_CASE("positional correction: the scene file's positional_correction: false leaves overlaps alone") {
    // Left out, the key keeps the book's setting, on; false turns the passes' correction
    // off (the M key's flag), so the pair stays 5 px deep.
    for (const bool on : {true, false}) {
        INFO("positional_correction " << on);
        const engine::WorldSettings world = test::worldFromScene(
            on ? R"({"movement": false})" : R"({"movement": false, "positional_correction": false})");
        test::requireEqual("the scene's positional_correction, as read", on, world.positional_correction);
        test::WorldFixture page(world);
        engine::Circle& a = page.core.add(engine::Circle({100, 100}, 10));
        engine::Circle& b = page.core.add(engine::Circle({115, 100}, 10));
        page.steps(1);
        if (on) {
            CHECK_THAT(b.center().x - a.center().x, test::near(20 - 5 * kLeftAfterOneStep, 1e-12));
        } else {
            test::expectEqual("the first circle's centre with positional correction off, px", Vec2{100, 100},
                              a.center());
            test::expectEqual("the second circle's centre with positional correction off, px", Vec2{115, 100},
                              b.center());
        }
    }
}

TEST_CASE("positional correction: a static shape does not move, nor do two static shapes in each other") {
    test::WorldFixture page(test::world(false));
    engine::Rectangle& floor = page.core.add(engine::Rectangle({100, 110}, 200, 20, {.mass = 0}));
    engine::Rectangle& wall = page.core.add(engine::Rectangle({190, 100}, 20, 100, {.mass = 0}));
    engine::Circle& ball = page.core.add(engine::Circle({50, 95}, 10));  // 5 px into the floor's top at y = 100
    page.steps(1);
    test::expectEqual("the static floor's centre after a step, px", Vec2{100, 110}, floor.center());
    // floor and wall overlap, and stay so
    test::expectEqual("the static wall's centre after a step, px", Vec2{190, 100}, wall.center());
    test::expectEqual("the ball's x, px: the floor pushes it straight up", 50.0, ball.center().x);
    CHECK_THAT(ball.center().y, test::near(95 - 5 * (1 - kLeftAfterOneStep), 1e-12));
    // The pass tests the floor and the wall like any pair, as the book's does; only the
    // resolution leaves two static shapes alone. (4.2 records and draws their collision,
    // later stages keep only the pairs the resolution works on.)
    for (const engine::Collision& pair : page.core.physics().collisions()) {
        const bool floor_and_wall = pair.first == 0 && pair.second == 1;
        INFO("a pair the last pass found: objects " << pair.first << " and " << pair.second
                                                    << "; expected the floor and the wall (0, 1), or a pair with the "
                                                       "ball (object 2)");
        CHECK((floor_and_wall || pair.second == 2));
    }
}

TEST_CASE("positional correction: M turns it off and on again") {
    test::WorldFixture page(test::world(false));
    engine::Circle& a = page.core.add(engine::Circle({100, 100}, 10));
    engine::Circle& b = page.core.add(engine::Circle({110, 100}, 10));
    test::expectEqual("positional correction as the page starts (WorldSettings::positional_correction)", true,
                      page.core.settings().positional_correction);
    page.press(Key::M);
    test::expectEqual("positional correction after M", false, page.core.settings().positional_correction);
    page.steps(5);
    test::expectEqual("the first circle's centre after 5 steps with positional correction off, px", Vec2{100, 100},
                      a.center());
    test::expectEqual("the second circle's centre after 5 steps with positional correction off, px", Vec2{110, 100},
                      b.center());
    test::expectEqual("pairs the pass found with positional correction off: still found, only not resolved", 1u,
                      page.core.physics().collisions().size());
    page.press(Key::M);
    page.steps(1);
    // 1e-12 px: one step's rounding on coordinates near 100 px is a few 1e-14 px; the
    // last pass's share alone, 10 * 0.2^14 * 0.8 = 1.3e-9 px, must show.
    CHECK_THAT(b.center().x - a.center().x, test::near(20 - 10 * kLeftAfterOneStep, 1e-12));
}

TEST_CASE("positional correction: 20 shapes created at one point part within 200 steps") {
    // The book's own experiment (4.2, Observation): movement off, 20 shapes made at the
    // cursor with F and G, then positional correction on. Each step's 15 passes move
    // every overlapping pair apart, but freeing one pair pushes shapes into others, so a
    // pile takes several steps. Measured over 200 seeds: half the piles part within 4
    // steps and nine in ten within 20; the slowest took 175, a row of rectangles
    // jammed against the static cursor in the middle of the pile, which slides round it
    // by about 2% of the overlap a step. Hence the bound of 200 steps (3.3 s) for each
    // pile, and of 20 steps for the median of the ten tried here.
    constexpr int kBound = 200;
    constexpr int kMedianBound = 20;
    constexpr double kTolerance = 0.5;  // px: what still counts as touching on screen
    std::vector<int> steps_taken;
    for (std::uint64_t seed = 1; seed <= 10; ++seed) {
        test::WorldFixture page(test::world(false), seed);
        // Chapter 4's cursor, a static 3 px square at the canvas centre, is object 0 and
        // selected: F and G make their shapes there. (Built here rather than taken from
        // the stage's scene, so the experiment runs the same on the demo's stages.)
        page.core.add(engine::Rectangle({400, 225}, 3, 3, {.mass = 0}));
        page.core.select(0);
        page.press(Key::M);  // off while the shapes are made, as the book suggests
        for (int i = 0; i < 10; ++i) {
            page.press(Key::F);
            page.press(Key::G);
        }
        page.press(Key::M);
        int steps = 0;
        while (deepestOverlap(page.core) > kTolerance && steps <= kBound) {
            page.steps(1);
            ++steps;
        }
        INFO("seed " << seed);
        test::expectAtMost("steps until no two of the 20 shapes overlap by more than 0.5 px", kBound, steps);
        steps_taken.push_back(steps);
    }
    std::sort(steps_taken.begin(), steps_taken.end());
    test::expectAtMost("the median, over ten seeds, of the steps until 20 shapes made at one point part", kMedianBound,
                       steps_taken[steps_taken.size() / 2]);
    WARN("20 shapes at one point parted to within " << kTolerance << " px in " << steps_taken.front() << " to "
                                                    << steps_taken.back() << " steps, median "
                                                    << steps_taken[steps_taken.size() / 2]);
}

}  // namespace positional_correction_test
