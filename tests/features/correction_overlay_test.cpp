// The overlay of positional correction (4.2 on): an arrow from each corrected shape's
// centre, ten times as long as the last step's passes moved it.
#include <catch2/catch.hpp>

#include <string>

#include "circle.h"
#include "expect.h"
#include "legend_color.h"
#include "near.h"
#include "world_fixture.h"

namespace correction_overlay_test {

TEST_CASE("correction overlay: the move of one pass, ten times longer, from the moved centre") {
    // Movement off (5.1's demo starts it on): only the correction moves shapes.
    engine::WorldSettings settings = test::world(false);
    settings.positional_correction = true;
    settings.relaxation_iterations = 1;
    test::WorldFixture page(settings);
    // A static circle and one of mass 1, radius 20, centres 38 apart on the row of pixel
    // centres y = 100.5: 2 px deep. All of the correction, depth x rate, goes to the
    // movable one, along +x.
    page.core.add(engine::Circle({200.5, 100.5}, 20, engine::PhysicalAttributes{.mass = 0.0}));
    page.core.add(engine::Circle({238.5, 100.5}, 20));
    page.window.overlay = true;
    page.window.clock.advanceFrame();
    page.core.runGameLoop();
    const double moved = 2.0 * settings.correction_rate;
    REQUIRE_THAT(page.core.object(1).center().x, test::near(238.5 + moved, 1e-9));
    const browser::Image& pixels = page.window.document.canvas.pixels();
    // The arrow runs from x = 238.5 + moved to 238.5 + 11 moved (256.1 at the book's
    // rate 0.8), along the row: (250.5, 100.5) is on it, (257.5, 100.5) past its tip and
    // a pixel short of the circle's outline, drawn where it was before the step (258.5).
    if (!test::expectAbove("where the arrow ends, px: past the pixel checked (the correction at the scene's rate)",
                           252.0, 238.5 + 11 * moved))
        return;
    if (!test::expectBelow("where the arrow ends, px: short of the pixel checked past it", 257.0, 238.5 + 11 * moved))
        return;
    const browser::Color correction = test::legendColor(page.window.document, "correction");
    test::expectEqual(
        "pixel (250, 100), on the correction arrow (ten times the move, from the moved centre): the legend's "
        "correction colour",
        correction, pixels.at(250, 100));
    test::expectEqual("pixel (257, 100), past the arrow's tip", browser::colors::kWhite, pixels.at(257, 100));
}

TEST_CASE("correction overlay: the physics keeps its record only while the overlay is on, and moves alike") {
    engine::WorldSettings settings = test::world(false);
    settings.positional_correction = true;
    settings.relaxation_iterations = 1;
    // Two pages of the same world, the overlay on in one of them: the circles of the
    // case above, 2 px deep.
    test::WorldFixture plain(settings);
    test::WorldFixture shown(settings);
    for (test::WorldFixture* page : {&plain, &shown}) {
        page->core.add(engine::Circle({200.5, 100.5}, 20, engine::PhysicalAttributes{.mass = 0.0}));
        page->core.add(engine::Circle({238.5, 100.5}, 20));
    }
    shown.window.overlay = true;
    for (test::WorldFixture* page : {&plain, &shown}) {
        page->window.clock.advanceFrame();
        page->core.runGameLoop();
    }
    // With the overlay off the step keeps no record at all; with it on, the move of the
    // one pass: depth x rate, all of it the movable circle's.
    CHECK(plain.core.physics().responses().empty());
    REQUIRE(shown.core.physics().responses().size() == 1);
    CHECK_THAT(shown.core.physics().responses().at({0, 1}).moved_second,
               test::near(engine::Vec2{2.0 * settings.correction_rate, 0}, 1e-12));
    // The record changes nothing the step does.
    CHECK(plain.core.object(1).center() == shown.core.object(1).center());
    CHECK(plain.core.object(1).velocity() == shown.core.object(1).velocity());
    // The overlay off again: the record goes with it.
    shown.window.overlay = false;
    shown.window.clock.advanceFrame();
    shown.core.runGameLoop();
    CHECK(shown.core.physics().responses().empty());
}

}  // namespace correction_overlay_test
