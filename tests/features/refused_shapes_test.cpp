// Shapes that cannot be simulated are refused where they are made (stage 5.2 on,
// rigid_shape.h: engine::InvalidShape): a NaN or infinite number, a size <= 0, a
// negative mass or friction, a restitution outside [0, 1], each with one line naming the
// value; and the edges of what may be simulated are accepted, and move as the physics
// says. The scene files' own refusals are scene_files_test.cpp's.
#include <catch2/catch.hpp>

#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "circle.h"
#include "near.h"
#include "rectangle.h"
#include "world_fixture.h"
#include "world_measures.h"

namespace refused_shapes_test {

using engine::Vec2;
using engine::WorldSettings;

namespace {

// The demo's world without its removal of shapes that leave the canvas.
WorldSettings demoWorld() {
    WorldSettings world = engine::kBookWorld;
    world.remove_out_of_bounds = false;
    return world;
}

constexpr double kG = engine::kGravity.y;  // 20 px/s^2, down

const double kNaN = std::numeric_limits<double>::quiet_NaN();
const double kInf = std::numeric_limits<double>::infinity();

struct Refusal {
    std::string what;                        // the quantity the message must name
    std::string got;                         // and the value, as printed
    std::function<void(engine::Core&)> add;  // builds the shape and adds it
};

std::vector<Refusal> refusals() {
    const auto circle = [](Vec2 c, double r, engine::PhysicalAttributes a = {}) {
        return [=](engine::Core& core) { core.add(engine::Circle(c, r, a)); };
    };
    const auto rectangle = [](Vec2 c, double w, double h, engine::PhysicalAttributes a = {}) {
        return [=](engine::Core& core) { core.add(engine::Rectangle(c, w, h, a)); };
    };
    const Vec2 here{100, 100};
    return {
        {"circle center x", "nan", circle({kNaN, 100}, 10)},
        {"circle center y", "inf", circle({100, kInf}, 10)},
        {"rectangle center x", "-inf", rectangle({-kInf, 100}, 10, 10)},
        {"rectangle center y", "nan", rectangle({100, kNaN}, 10, 10)},
        {"circle radius", "0", circle(here, 0)},
        {"circle radius", "-2", circle(here, -2)},
        {"circle radius", "nan", circle(here, kNaN)},
        {"circle radius", "inf", circle(here, kInf)},
        {"rectangle width", "0", rectangle(here, 0, 10)},
        {"rectangle width", "-1", rectangle(here, -1, 10)},
        {"rectangle width", "nan", rectangle(here, kNaN, 10)},
        {"rectangle width", "inf", rectangle(here, kInf, 10)},
        {"rectangle height", "0", rectangle(here, 10, 0)},
        {"rectangle height", "-3", rectangle(here, 10, -3)},
        {"rectangle height", "nan", rectangle(here, 10, kNaN)},
        {"rectangle height", "inf", rectangle(here, 10, kInf)},
        {"circle mass", "-1", circle(here, 10, {.mass = -1})},
        {"rectangle mass", "nan", rectangle(here, 10, 10, {.mass = kNaN})},
        {"circle mass", "inf", circle(here, 10, {.mass = kInf})},
        {"circle friction", "-0.1", circle(here, 10, {.friction = -0.1})},
        {"rectangle friction", "nan", rectangle(here, 10, 10, {.friction = kNaN})},
        {"circle restitution", "-0.1", circle(here, 10, {.restitution = -0.1})},
        {"rectangle restitution", "1.1", rectangle(here, 10, 10, {.restitution = 1.1})},
        {"circle restitution", "nan", circle(here, 10, {.restitution = kNaN})},
    };
}

}  // namespace

TEST_CASE("refused shapes: a shape that cannot be simulated is refused with one line naming the value, and not added") {
    test::WorldFixture page(demoWorld());
    page.core.add(engine::Circle({50, 50}, 5));
    for (const Refusal& refusal : refusals()) {
        INFO(refusal.what << " = " << refusal.got);
        std::string message;
        try {
            refusal.add(page.core);
        } catch (const engine::InvalidShape& refused) {
            message = refused.what();
        }
        INFO("message: " << message);
        CHECK(message.find(refusal.what) == 0);
        CHECK(message.find("(got " + refusal.got + ")") != std::string::npos);
        CHECK(message.find('\n') == std::string::npos);
        // core.add takes a shape already made: when making it throws, nothing reaches the list.
        CHECK(page.core.objectCount() == 1);
    }
}

TEST_CASE("refused shapes: the edges of what may be simulated are accepted, and simulate as the physics says") {
    // Mass 0 is a static body, friction 0 a slippery one, e = 0 and e = 1 the two ends
    // of bounciness; a size need only be above 0, a friction has no upper limit.
    test::WorldFixture page(demoWorld());
    const engine::RigidShape& speck =
        page.core.add(engine::Circle({100, 100}, 1e-9, {.mass = 0, .friction = 0, .restitution = 0}));
    const engine::RigidShape& far_out =
        page.core.add(engine::Rectangle({-1e9, 1e9}, 1e-9, 1e5, {.mass = 1e-9, .friction = 100, .restitution = 1}));
    // A ball of mass 1e-9, friction 100 and e = 1 dropped 80 px onto a floor as grippy
    // and as bouncy: it falls straight, so friction has nothing to do, and the floor
    // sends it back up at e = 1 times the speed it met it with.
    page.core.add(engine::Rectangle({400, 400}, 800, 20, {.mass = 0, .friction = 100, .restitution = 1}));
    const engine::RigidShape& ball =
        page.core.add(engine::Circle({400, 300}, 10, {.mass = 1e-9, .friction = 100, .restitution = 1}));
    REQUIRE(page.core.objectCount() == 4);
    CHECK(speck.isStatic());
    CHECK_THAT(far_out.mass(), test::near(1e-9, 1e-24));  // 1 / (1 / m): rounding only
    double falling = 0;
    int n = 0;
    while (n < 600 && ball.velocity().y >= 0) {
        falling = ball.velocity().y;
        page.steps(1);
        ++n;
        REQUIRE_FALSE(test::firstNotFinite(page.core));
    }
    REQUIRE(ball.velocity().y < 0);
    // The impulse turns v into -e v; the step then adds g dt (collision_impulse_test).
    CHECK_THAT(-ball.velocity().y / falling, test::near(1 - kG * engine::kFrameTime / falling, 1e-12));
    CHECK(ball.velocity().x == 0);
    CHECK(speck.center() == Vec2{100, 100});
    // The far shape fell n steps from rest: g dt^2 n (n + 1) / 2 (symplectic Euler). A
    // coordinate of 1e9 px is kept to 1.2e-7 px, and each of n steps rounds once: 1e-5 px.
    const double dt = engine::kFrameTime;
    CHECK(far_out.center().x == -1e9);
    CHECK_THAT(far_out.center().y, test::near(1e9 + kG * dt * dt * n * (n + 1) / 2, 1e-5));
    CHECK(far_out.angle() == 0);
}

}  // namespace refused_shapes_test
