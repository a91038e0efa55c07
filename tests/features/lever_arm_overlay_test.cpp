// The overlay of angular impulses (4.4 on): the lever arms from both centres to the
// contact the impulses act at, and the record behind them, Physics::responses().
#include <catch2/catch.hpp>

#include "circle.h"
#include "expect.h"
#include "legend_color.h"
#include "near.h"
#include "world_fixture.h"

namespace lever_arm_overlay_test {

TEST_CASE("lever arm overlay: the overlay draws the lever arms from both centres to the contact the impulses act at") {
    // Movement off (5.1's demo starts it on): only the response acts.
    engine::WorldSettings settings = test::world(false);
    settings.positional_correction = false;
    settings.relaxation_iterations = 1;
    test::WorldFixture page(settings);
    // A static circle at (200.5, 100.5) and one of mass 1 at (238.5, 100.5), radius 20,
    // coming at it at 60 px/s: they overlap from x = 218.5 (the moving one's rim, the
    // start) to 220.5. All the inverse mass is the moving circle's, so the contact is
    // the start: the arms are (18, 0) and (-20, 0). Along the line of centres the
    // impulse turns neither circle.
    page.core.add(engine::Circle({200.5, 100.5}, 20, engine::PhysicalAttributes{.mass = 0.0}));
    page.core.add(engine::Circle({238.5, 100.5}, 20)).setVelocity({-60, 0});
    page.window.overlay = true;
    page.window.overlay_all = true;  // every layer: this one may be an earlier stage's
    page.window.clock.advanceFrame();
    page.core.runGameLoop();
    const engine::PairResponse& response = page.core.physics().responses().at({0, 1});
    CHECK_THAT(response.contact, test::near(lib::Vec2{218.5, 100.5}, 1e-9));
    CHECK_THAT(response.arm_first, test::near(lib::Vec2{18, 0}, 1e-9));
    CHECK_THAT(response.arm_second, test::near(lib::Vec2{-20, 0}, 1e-9));
    test::expectEqual("the first shape's spin from the hit, rad/s: a head-on hit turns nothing", 0.0,
                      response.spin_first);
    test::expectEqual("the second shape's spin from the hit, rad/s", 0.0, response.spin_second);
    const browser::Color lever = test::legendColor(page.window.document, "lever arms");
    // The first arm runs along the row y = 100.5 from x = 200.5 to 218.5.
    test::expectEqual("pixel (205, 100), on the lever arm from the centre to the contact: the legend's colour", lever,
                      page.window.document.canvas.pixels().at(205, 100));
}

}  // namespace lever_arm_overlay_test
