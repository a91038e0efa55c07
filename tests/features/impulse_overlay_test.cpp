// The overlay of collision impulses (4.3 on): the normal and tangent impulses of the
// last step at the pair's contact, as the second shape received them, 2 px a unit and
// cut at 60 px; and the record behind it, Physics::responses().
#include <catch2/catch.hpp>

#include <string>

#include "circle.h"
#include "expect.h"
#include "legend_color.h"
#include "near.h"
#include "world_fixture.h"

namespace impulse_overlay_test {

TEST_CASE("impulse overlay: a head-on bounce off a static circle, by Newton's law of restitution") {
    // Movement off (5.1's demo starts it on): only the response acts.
    engine::WorldSettings settings = test::world(false);
    settings.positional_correction = false;
    settings.relaxation_iterations = 1;
    test::WorldFixture page(settings);
    // A static circle and one of mass 1 coming at it along the row y = 100.5 at 60 px/s,
    // radius 20, centres 38 apart. Restitution 0.2 (the default, the smaller of the
    // two): jN = (1 + e) x 60 / (1/m) = 72, along +x; no sliding, so jT = 0. The contact
    // lies on the line of centres, so turning (4.4) changes nothing.
    page.core.add(engine::Circle({200.5, 100.5}, 20, engine::PhysicalAttributes{.mass = 0.0}));
    engine::Circle& ball = page.core.add(engine::Circle({238.5, 100.5}, 20));
    ball.setVelocity({-60, 0});
    page.window.overlay = true;
    page.window.overlay_all = true;  // every layer: this one may be an earlier stage's
    page.window.clock.advanceFrame();
    page.core.runGameLoop();

    const engine::PairResponse& response = page.core.physics().responses().at({0, 1});
    CHECK_THAT(response.normal_impulse, test::near(lib::Vec2{72, 0}, 1e-9));
    CHECK_THAT(response.tangent_impulse, test::near(lib::Vec2{0, 0}, 1e-9));
    CHECK_THAT(ball.velocity(), test::near(lib::Vec2{12, 0}, 1e-9));

    // 72 x 2 px = 144 px, cut at 60: from the contact (between x = 218.5 and 220.5)
    // to x = 278.5 or 279.5. (270.5, 100.5) is on the shaft; (285.5, 100.5) past it.
    const browser::Color normal_impulse = test::legendColor(page.window.document, "normal impulse");
    const browser::Image& pixels = page.window.document.canvas.pixels();
    test::expectEqual("pixel (270, 100), on the normal impulse's arrow: the legend's colour", normal_impulse,
                      pixels.at(270, 100));
    test::expectEqual("pixel (285, 100), past the arrow's tip", browser::colors::kWhite, pixels.at(285, 100));
}

}  // namespace impulse_overlay_test
