// The overlay of the collision info (3.2 on; from 4.3 on the book no longer draws it):
// markers at the start and the end of the overlap and the normal drawn from the start,
// each in the colour the legend gives it, where the geometry of two circles puts them.
#include <catch2/catch.hpp>

#include <algorithm>
#include <string>

#include "circle.h"
#include "expect.h"
#include "legend_color.h"
#include "stage_fixture.h"

namespace collision_overlay_test {

#if __has_include("world_settings.h")
// Chapter 4: the book's world without positional correction, and with movement off
// (5.1's demo starts it on), so that the two circles stay where they are: they touch at
// rest, and no impulse moves them.
template <class Settings>
Settings atRest(Settings settings) {
    settings.movement = false;
    if constexpr (requires { settings.positional_correction; }) settings.positional_correction = false;
    return settings;
}
struct Page {
    browser::Window window{test::kFrameMs};
    engine::Core core{window, atRest(engine::kBookWorld)};
};
#else
struct Page {
    browser::Window window{test::kFrameMs};
    engine::Core core{window};
};
#endif

TEST_CASE("collision overlay: start, end and normal of two circles' overlap, in the legend's colours") {
    Page page;
    // Radius 20, centres 30 apart on the row of pixel centres y = 100.5: they overlap by
    // 40 - 30 = 10 px along the normal (1, 0), from the second circle's leftmost point
    // (210.5, 100.5) to the first one's rightmost (220.5, 100.5).
    page.core.add(engine::Circle({200.5, 100.5}, 20));
    page.core.add(engine::Circle({230.5, 100.5}, 20));
    page.window.overlay = true;
    page.window.overlay_all = true;  // every layer: this one may be an earlier stage's
    page.window.clock.advanceFrame();
    page.core.runGameLoop();
    const browser::Document& document = page.window.document;
    const browser::Image& pixels = document.canvas.pixels();
    // The markers' crosses meet on those pixel centres, and they are drawn last.
    test::expectEqual("pixel (210, 100), the start of the overlap: the legend's start marker",
                      test::legendColor(document, "start"), pixels.at(210, 100));
    test::expectEqual("pixel (220, 100), the end of the overlap: the legend's end marker",
                      test::legendColor(document, "end"), pixels.at(220, 100));
    // The normal runs 20 px right from the start along the row: (213.5, 100.5) is on it,
    // 2 px or more from each marker's strokes and inside both circles.
    test::expectEqual("pixel (213, 100), on the normal drawn 20 px from the start",
                      test::legendColor(document, "normal"), pixels.at(213, 100));
    // It ends at x = 230.5: two pixels on, the row is white.
    test::expectEqual("pixel (232, 100), past the normal's 20 px", browser::colors::kWhite, pixels.at(232, 100));
    const auto counted = std::find_if(document.legend.begin(), document.legend.end(),
                                      [](const auto& entry) { return entry.text == "colliding pairs: 1"; });
    test::expectEqual("the legend's line \"colliding pairs: 1\" (one pair collides)", true,
                      counted != document.legend.end());
}

}  // namespace collision_overlay_test
