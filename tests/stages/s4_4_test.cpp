// Stage 4.4: the book's scene turns its platform and gains a second one; collisions
// turn shapes.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>
#include <vector>

#include "book_scene.h"
#include "circle.h"
#include "expect.h"
#include "near.h"
#include "my_game.h"
#include "platform_check.h"
#include "rectangle.h"
#include "walkthrough.h"
#include "world_fixture.h"

namespace s4_4_test {

using engine::Vec2;

TEST_CASE("s4_4: the scene has two turned static platforms, kept by a reset") {
    // The book's MyGame.js order: the cursor, the two platforms, then the four borders.
    test::WorldFixture page(test::world(true));
    test::buildBookScene(page.core, page.random);
    test::requireEqual("objects of the book's scene: the cursor, two platforms, the four borders", 7u,
                       page.core.objectCount());
    test::requireEqual("objects R keeps (UserControl::kKeptOnReset): the seven of the scene", 7u,
                       engine::UserControl::kKeptOnReset);
    test::expectEqual("the cursor's centre (object 0), px", Vec2{400, 225}, page.core.object(0).center());
    test::checkPlatform(page.core.object(1), {.center = {500, 200}, .angle = 3.0});
    test::checkPlatform(page.core.object(2), {.center = {200, 400}, .angle = 0.785, .friction = 1, .restitution = 0});
    test::checkBorders(page.core, 3);
}

TEST_CASE("s4_4: a circle dropped on the steep platform rolls down it at 2/3 g sin(slope)") {
    // The steep platform (object 2) is turned 0.785 rad, friction 1, e = 0; the default
    // ball (radius 15, mass 1, friction 0.8) lands on it 21 px below, within 2 s. A
    // solid disc rolling without slipping speeds up at g sin(a) / (1 + I / (m r^2)) =
    // 2/3 g sin(a); the book's friction takes 0.8 of the slip away at every contact,
    // which keeps the ball rolling, short of a small steady slip (measured: 0.15 px/s;
    // bound 0.5). Between 2.5 s and 7.5 s it is rolling down the slope: its speed along
    // the slope grows at 2/3 g sin(a), to 1% (measured: 0.01%), and across the slope it
    // moves no faster than a resting shape sinks, g dt a step.
    test::WorldFixture page(test::world(true));
    test::buildBookScene(page.core, page.random);
    engine::Circle& ball = page.core.add(engine::Circle({150, 300}, 15));
    const double slope = page.core.object(2).angle();
    test::requireEqual("the steep platform's angle (object 2), rad", 0.785, slope);
    const Vec2 downhill{std::cos(slope), std::sin(slope)};
    const Vec2 out_of_slope{std::sin(slope), -std::cos(slope)};
    const double g = engine::kGravity.y;
    const double dt = engine::kFrameTime;
    page.steps(150);
    const double speed_at_2_5s = ball.velocity().dot(downhill);
    for (int step = 150; step < 450; ++step) {
        page.steps(1);
        const double along = ball.velocity().dot(downhill);
        INFO("step " << step + 1 << ": " << along << " px/s along the slope, w r = " << ball.angularVelocity() * 15);
        const bool on_the_slope =
            test::expectAtMost("the ball's speed across the slope, px/s: no more than a resting shape sinks, g dt",
                               g * dt, std::abs(ball.velocity().dot(out_of_slope)));
        // Turning clockwise on screen (w > 0), as rolling down to the right does.
        const bool rolling = test::expectAtMost("the slip |w r - v along the slope|, px/s: rolling, not sliding", 0.5,
                                                std::abs(ball.angularVelocity() * ball.radius() - along));
        if (!on_the_slope || !rolling) break;  // the first step that fails says enough
    }
    const double acceleration = (ball.velocity().dot(downhill) - speed_at_2_5s) / (300 * dt);
    CHECK_THAT(acceleration, test::near(2.0 / 3 * g * std::sin(slope), 0.01 * 2.0 / 3 * g * std::sin(slope)));
}

// The README's walkthrough ("Play it live"): with movement on, a circle is made low
// over the steep platform and a box up to its left, each given 100 px/s downwards (K),
// since gravity alone (10 px/s^2) would take seconds to bring them down; then the
// cursor moves out of the box's way.
TEST_CASE("s4_4: README walkthrough: the circle lands and rolls, the box turns as it lands") {
    test::ScratchFolder folder("s4_4_walkthrough");
    const std::vector<test::DumpRow> rows =
        test::runWalkthrough(folder, "comma a*20 s*8 g 7 k*100 0 a*4 w*4 f 8 k*100 0 w*10", 240);
    const auto state = [&rows](long step, std::size_t index) { return test::stateAt(rows, step, index); };
    const long last = rows.back().step;
    test::requireEqual("object 7 of the walkthrough (G)", std::string("circle"), state(1, 7).shape);
    test::requireEqual("object 8 of the walkthrough (F)", std::string("rectangle"), state(1, 8).shape);
    // Gravity pulls through the centre and turns nothing: while a shape flies free its
    // angular velocity stays exactly 0 and its angle exactly where it was made.
    test::expectEqual("the circle's angular velocity at step 1, flying free, rad/s", 0.0, state(1, 7).angular_velocity);
    test::expectEqual("the box's angle at step 1, flying free, rad", 0.0, state(1, 8).angle);
    // The circle falls some 80 px to the slope at about 120 px/s, which takes more than
    // half a second: at step 10 (a sixth of a second) it is still free.
    test::expectEqual("the circle's angular velocity at step 10, still in the air, rad/s", 0.0,
                      state(10, 7).angular_velocity);
    // It has landed and rolls: at the end it spins at over half a radian a second.
    test::expectAtLeast("the circle's spin |w| at the end, rad/s: landed on the slope and rolling", 0.5 + 1e-12,
                        std::abs(state(last, 7).angular_velocity));
    // The box has turned by more than half a radian in its landing.
    test::expectAtLeast("the box's |angle| at the end, rad: turned by its landing on a corner", 0.5 + 1e-12,
                        std::abs(state(last, 8).angle));
}

}  // namespace s4_4_test
