// The overlay of positional correction (4.2 on): an arrow from each corrected shape's
// centre, ten times as long as the last step's passes moved it.
#include <catch2/catch.hpp>

#include <bit>
#include <cstddef>
#include <cstdint>
#include <string>

#include "book_scene.h"
#include "circle.h"
#include "expect.h"
#include "legend_color.h"
#include "near.h"
#include "stage_fixture.h"
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
    page.window.overlay_all = true;  // every layer: this one may be an earlier stage's
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
    shown.window.overlay_all = true;  // every layer: this one may be an earlier stage's
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

TEST_CASE("correction overlay: the book's scene run with the overlay off keeps no record and moves to the same bits") {
    // The book's scene on two pages, the overlay on in one of them, shaken with H (the
    // same random numbers on both) so that many pairs collide and are corrected. Frame
    // after frame the page without the overlay keeps no record at all, and every shape
    // on it has the very same bits as on the page with it: the record costs the step
    // nothing it computes.
    test::StageFixture plain;
    test::StageFixture shown;
    shown.window.overlay = true;
    shown.window.overlay_all = true;  // every layer: this one may be an earlier stage's
    for (test::StageFixture* page : {&plain, &shown}) {
        test::buildBookScene(page->core, page->random);
        page->press(browser::Key::H);
    }
    const auto bits = [](double value) { return std::bit_cast<std::uint64_t>(value); };
    std::size_t frames_recorded = 0, differing = 0;
    constexpr int kFrames = 120;  // 2 s at the page's 60 frames a second
    for (int frame = 0; frame < kFrames; ++frame) {
        plain.frame();
        shown.frame();
        if (!plain.core.physics().responses().empty()) {
            FAIL_CHECK("frame " << frame << ": the page without the overlay kept "
                                << plain.core.physics().responses().size() << " pairs' record");
        }
        frames_recorded += !shown.core.physics().responses().empty();
        // A shape that leaves the canvas is removed (remove_out_of_bounds): the pages
        // keep the same shapes only if every step moved them alike.
        if (!test::expectEqual("shapes on the page with the overlay, as on the page without", plain.core.objectCount(),
                               shown.core.objectCount())) {
            FAIL_CHECK("frame " << frame << ": the pages hold different shapes");
            break;
        }
        for (std::size_t i = 0; i < plain.core.objectCount(); ++i) {
            const auto& a = plain.core.object(i);
            const auto& b = shown.core.object(i);
            const bool same = bits(a.center().x) == bits(b.center().x) && bits(a.center().y) == bits(b.center().y) &&
                              bits(a.angle()) == bits(b.angle()) && bits(a.velocity().x) == bits(b.velocity().x) &&
                              bits(a.velocity().y) == bits(b.velocity().y) &&
                              bits(a.angularVelocity()) == bits(b.angularVelocity());
            if (!same && differing++ == 0) FAIL_CHECK("frame " << frame << ": shape " << i << " moved otherwise");
        }
    }
    test::expectEqual("shape states that differ between the pages, over all frames", std::size_t{0}, differing);
    // The page with the overlay did record: the comparison is between a step that keeps
    // the record and one that does not.
    test::expectAbove("frames whose step recorded a corrected pair, with the overlay on", 0.0,
                      static_cast<double>(frames_recorded));
}

}  // namespace correction_overlay_test
