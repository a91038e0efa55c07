// Stage 4.3: the book's scene gains a static platform; impulses change linear
// velocities only, so nothing turns.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstddef>
#include <vector>

#include "book_scene.h"
#include "circle.h"
#include "my_game.h"
#include "expect.h"
#include "near.h"
#include "platform_check.h"
#include "rectangle.h"
#include "walkthrough.h"
#include "world_fixture.h"

namespace s4_3_test {

using engine::Vec2;

TEST_CASE("s4_3: the scene has a static, gripping, dead platform at (200, 400), kept by a reset") {
    // The book's MyGame.js order: the cursor, the platform, then the four borders.
    test::WorldFixture page(test::world(true));
    test::buildBookScene(page.core, page.random);
    test::requireEqual("objects of the book's scene: the cursor, the platform, the four borders", 6u,
                       page.core.objectCount());
    test::requireEqual("objects R keeps (UserControl::kKeptOnReset): the six of the scene", 6u,
                       engine::UserControl::kKeptOnReset);
    test::expectEqual("the cursor's centre (object 0), px", Vec2{400, 225}, page.core.object(0).center());
    test::checkPlatform(page.core.object(1), {.center = {200, 400}, .friction = 1, .restitution = 0});
    test::checkBorders(page.core, 2);
}

TEST_CASE("s4_3: a circle dropped on the platform comes to rest on it") {
    test::WorldFixture page(test::world(true));
    test::buildBookScene(page.core, page.random);
    engine::Circle& ball = page.core.add(engine::Circle({100, 300}, 20, {.restitution = 0.5}));
    page.steps(600);  // 10 s
    // e = min(0.5, 0) = 0: it stops dead on the platform's top (y = 390). Resting, it
    // ends every step as deep as one step of gravity carries it, g dt^2 = 0.0028 px
    // (extremes_test: g dt^2 / (1 + e)).
    const double resting = engine::kGravity.y * engine::kFrameTime * engine::kFrameTime;
    CHECK_THAT(ball.center().y, test::near(370 + resting, 1e-9));
    test::expectEqual("the ball's x, px: it falls straight", 100.0, ball.center().x);
    // what gravity adds back in one step
    test::expectAtMost("the resting ball's vertical speed |vy|, px/s: about one step of gravity, g dt = 0.17", 0.2,
                       std::abs(ball.velocity().y));
}

TEST_CASE("s4_3: an off-centre hit changes velocities only; nothing turns") {
    test::WorldFixture page(test::world(true, {0, 0}));
    engine::Rectangle& box = page.core.add(engine::Rectangle({200, 200}, 40, 20, {2, 0.5, 0.5}));
    engine::Circle& ball = page.core.add(engine::Circle({229, 195}, 10, {1, 0.5, 0.5}));
    ball.setVelocity({-50, 0});
    page.steps(10);
    test::expectAtMost("the box's vx after the ball hits it from the right, px/s: pushed left", -1e-9,
                       box.velocity().x);
    test::expectEqual("the box's angular velocity, rad/s: impulses act through the centres in 4.3", 0.0,
                      box.angularVelocity());
    test::expectEqual("the box's angle, rad", 0.0, box.angle());
    test::expectEqual("the ball's angular velocity, rad/s", 0.0, ball.angularVelocity());
}

TEST_CASE("s4_3: a ball hitting a floor at a slant: e and mu of the less bouncy, less gripping surface") {
    // No gravity. The floor (static, e = 1, mu = 1) is added first, so the normal
    // points from it up to the ball: n = (0, -1). The ball (mass 1, e = 0.5, mu = 0.2)
    // is 1 px into it, moving at v = (10, 100). The pair takes e = min(0.5, 1) = 0.5 and
    // mu = min(0.2, 1) = 0.2. Normal speed v . n = -100, so jN = -(1 + e)(-100) / 1 =
    // 150: vy = 100 - 150 = -50, e times the speed it came in with. The slide is
    // v - (v . n) n = (10, 0), so the tangent is (-1, 0), and jT = (1 + e) mu 10 = 3,
    // under the cap jN: vx = 10 - 3 = 7. The later relaxation passes find the ball
    // moving apart, and change no velocity.
    test::WorldFixture page(test::world(true, {0, 0}));
    page.core.add(engine::Rectangle({400, 400}, 800, 20, {.mass = 0, .friction = 1, .restitution = 1}));
    engine::Circle& ball =
        page.core.add(engine::Circle({400, 381}, 10, {.mass = 1, .friction = 0.2, .restitution = 0.5}));
    ball.setVelocity({10, 100});
    page.steps(1);
    CHECK_THAT(ball.velocity(), test::near(Vec2{7, -50}, 1e-12));
}

// The README's walkthrough ("Play it live"): a circle and a box sent down onto the
// platform, then H at two seconds.
TEST_CASE("s4_3: README walkthrough: the shapes land on the platform, slow down, and never turn") {
    test::ScratchFolder folder("s4_3_walkthrough");
    const std::vector<test::DumpRow> rows =
        test::runWalkthrough(folder, "comma a*20 s*8 g 6 k*100 0 d*8 f 7 k*100 0 w*10 h@120", 240);
    const auto state = [&rows](long step, std::size_t index) { return test::stateAt(rows, step, index); };
    test::requireEqual("object 6 of the walkthrough (G)", std::string("circle"), state(1, 6).shape);
    test::requireEqual("object 7 of the walkthrough (F)", std::string("rectangle"), state(1, 7).shape);
    // Impulses act through the centres in this project: nothing ever turns.
    for (const test::DumpRow& row : rows) {
        INFO("object " << row.index << " (" << row.shape << ") at step " << row.step);
        test::expectEqual("its angle, rad: impulses act through the centres in 4.3", 0.0, row.angle);
        test::expectEqual("its angular velocity, rad/s", 0.0, row.angular_velocity);
    }
    // The platform's top is at y = 400 - 10. At step 60 both rest on it: above it, and
    // their vertical speed is the one step of gravity, g dt = 10/60 px/s, that the
    // contact takes away again each step.
    for (const std::size_t shape : {std::size_t{6}, std::size_t{7}}) {
        INFO("object " << shape << " (6 the circle, 7 the box)");
        test::expectAtMost("its centre's y at step 60, px: above the platform's top, y = 390", 390.0 - 1e-9,
                           state(60, shape).cy);
        CHECK_THAT(state(60, shape).vy, test::near(10.0 / 60.0, 1e-9));
        CHECK_THAT(state(119, shape).vy, test::near(10.0 / 60.0, 1e-9));
        // Friction slows the sliding between landing and H.
        INFO("|vx| at step 30: " << std::abs(state(30, shape).vx) << " px/s");
        test::expectAtMost("its sideways speed |vx| at step 119, px/s: friction slowed it since step 30",
                           std::abs(state(30, shape).vx) - 1e-12, std::abs(state(119, shape).vx));
    }
}

}  // namespace s4_3_test
