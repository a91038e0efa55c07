// Stage 4.1: shapes move under gravity, but collisions are only found, not answered;
// the book's scene is static.
#include <catch2/catch.hpp>

#include <string>
#include <vector>

#include "book_scene.h"
#include "circle.h"
#include "my_game.h"
#include "expect.h"
#include "near.h"
#include "stage_fixture.h"
#include "walkthrough.h"
#include "world_fixture.h"

namespace s4_1_test {

using engine::Vec2;

TEST_CASE("s4_1: the cursor and the borders are static and stay put with movement on") {
    test::WorldFixture page(test::world(true));
    test::buildBookScene(page.core, page.random);
    test::requireEqual("objects of the book's scene: the cursor and the four borders (UserControl::kKeptOnReset)",
                       engine::UserControl::kKeptOnReset, page.core.objectCount());
    std::vector<Vec2> before;
    for (std::size_t i = 0; i < page.core.objectCount(); ++i) before.push_back(page.core.object(i).center());
    page.steps(60);
    for (std::size_t i = 0; i < page.core.objectCount(); ++i) {
        INFO("object " << i << " (0 the cursor, 1 to 4 the borders: top, bottom, left, right)");
        test::expectEqual("static (mass 0, so invMass() 0)", true, page.core.object(i).isStatic());
        test::expectEqual("its centre after 60 steps with movement on, px", before[i], page.core.object(i).center());
    }
}

TEST_CASE("s4_1: colliding shapes are reported and pass through each other untouched") {
    test::WorldFixture page(test::world(true, {0, 0}));
    const test::ApproachingCircles pair(page);
    engine::Circle& left = pair.left;
    engine::Circle& right = pair.right;
    bool reported = false;
    for (int step = 0; step < 30; ++step) {  // 0.5 s: they meet after 1/12 s and cross
        page.steps(1);
        reported = reported || !page.core.physics().collisions().empty();
    }
    test::expectEqual("a collision of the two circles reported by the pass as they cross", true, reported);
    test::expectEqual("the left circle's velocity after crossing, px/s: nothing answers collisions yet", Vec2{60, 0},
                      left.velocity());
    test::expectEqual("the right circle's velocity after crossing, px/s", Vec2{-60, 0}, right.velocity());
    // 1e-12 px: 30 steps of 1 px, rounded near 100 px.
    CHECK_THAT(left.center().x, test::near(130, 1e-12));
    CHECK_THAT(right.center().x, test::near(100, 1e-12));
}

TEST_CASE("s4_1: a frame shows the world from before its update, with that update's collision on top") {
    // The book's order from 3.1 on: the frame echoes and draws first, then runs the due
    // update, whose collision pass draws onto the picture already made.
    test::StageFixture page;
    page.core.toggleMovement();
    // Pixel-centred circles, radii 20, 30 apart: 10 px deep. The right one, selected
    // (red), moves 10 px right a step.
    page.core.add(engine::Circle({100.5, 100.5}, 20, {.mass = 0}));
    engine::Circle& ball = page.core.add(engine::Circle({130.5, 100.5}, 20));
    ball.setVelocity({600, 0});
    page.core.select(1);
    page.frame();
    test::requireEqual("updates the first frame of 1000/60 ms ran", 1, page.core.stepCount());
    CHECK_THAT(ball.center().x, test::near(140.5, 1e-12));  // one step: rounding of 140 px
    // The echo and the outline are from before the update: the ball's rightmost point
    // is still at x = 150.5, and gravity has not yet added to its velocity.
    INFO("the echo:\n" << page.window.document.ui_echo);
    test::expectEqual("the echo's line \"Velocity: 600,0.00\", the velocity from before the update", true,
                      page.window.document.ui_echo.find("Velocity: 600,0.00\n") != std::string::npos);
    const browser::Image& pixels = page.window.document.canvas.pixels();
    test::expectEqual("pixel (150, 100), the selected ball's rim where it was before the update", browser::colors::kRed,
                      pixels.at(150, 100));
    test::expectEqual("pixel (160, 100), where its rim is after the update: not drawn yet", browser::colors::kWhite,
                      pixels.at(160, 100));
    // The pass ran before the ball moved: its line runs from 110.5 to 120.5.
    test::expectEqual("pixel (115, 100), on the collision line the update's pass found before the ball moved",
                      browser::colors::kOrange, pixels.at(115, 100));
}

// The README's walkthrough ("Play it live"): movement on, a rectangle (5) and a circle
// (6) at the cursor, the circle thrown right at 60 px/s and up at 80 px/s.
TEST_CASE("s4_1: README walkthrough: both fall under gravity, the circle flies a parabola through the box") {
    test::ScratchFolder folder("s4_1_walkthrough");
    const std::vector<test::DumpRow> rows = test::runWalkthrough(folder, "comma f g 6 l*60 i*80", 120);
    constexpr double kGDt = 10.0 / 60.0;  // what one step of gravity adds to vy, px/s
    for (const long step : {1L, 60L, 119L}) {
        const test::DumpRow box = test::stateAt(rows, step, 5);
        const test::DumpRow ball = test::stateAt(rows, step, 6);
        // Symplectic Euler: after n steps gravity has added n g dt, to the box at rest
        // and to the thrown circle alike.
        CHECK_THAT(box.vy, test::near(step * kGDt, 1e-9));
        CHECK_THAT(ball.vy, test::near(-80.0 + step * kGDt, 1e-9));
        // Nothing answers collisions yet: the circle starts inside the box and keeps
        // its sideways speed, exactly, through it.
        INFO("step " << step);
        test::expectEqual("the circle's sideways speed vx, px/s: kept exactly through the box", 60.0, ball.vx);
        test::expectEqual("the box's sideways speed vx, px/s", 0.0, box.vx);
    }
    // Up first, then turning down: the top of the parabola is 80 / (g dt) = 480 steps
    // away, so within the run the circle is still rising.
    test::expectAtMost("the circle's height at step 119 (y, px; +y is down): above where it was at step 60",
                       test::stateAt(rows, 60, 6).cy - 1e-9, test::stateAt(rows, 119, 6).cy);
}

}  // namespace s4_1_test
