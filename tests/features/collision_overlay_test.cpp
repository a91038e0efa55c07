// The overlay of the collision info (3.2 on; from 4.3 on the book no longer draws it):
// markers at the start and the end of the overlap and the normal drawn from the start,
// each in the colour the legend gives it, where the geometry of two circles puts them.
// And what every layer on adds from 3.2 on: 3.1's bounding circles under the rest, and
// a legend as long as the stage says (overlay.h's kLegendEntries), which the page's
// band is made for.
#include <catch2/catch.hpp>

#include <algorithm>
#include <string>
#include <vector>

#include "circle.h"
#include "expect.h"
#include "legend_color.h"
#include "legend_layout.h"
#include "overlay.h"
#include "page.h"
#include "rectangle.h"
#include "stage_fixture.h"
#include "text.h"

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
// Every layer's condition on, as far as the stage has it: the grid (5.2 on), sleeping
// (5.5 on) and the sequential impulse solver (5.4 on) each add their lines to the legend
// only while they run.
template <class Settings>
Settings everyLayerRuns(Settings settings) {
    settings = atRest(settings);
    if constexpr (requires { settings.broad_phase; }) settings.broad_phase = decltype(settings.broad_phase)::grid;
    if constexpr (requires { settings.sleep; }) settings.sleep = true;
    if constexpr (requires { settings.solver; }) settings.solver = decltype(settings.solver)::sequential_impulse;
    return settings;
}
struct EveryLayerPage {
    browser::Window window{test::kFrameMs};
    engine::Core core{window, everyLayerRuns(engine::kBookWorld)};
};
#else
struct Page {
    browser::Window window{test::kFrameMs};
    engine::Core core{window};
};
using EveryLayerPage = Page;
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

TEST_CASE("collision overlay: every layer on adds 3.1's bounding circles; the stage's own layer alone does not") {
    Page page;
    // A 60 x 80 px rectangle on the pixel centre (400.5, 300.5): its bounding circle, half
    // its diagonal, has the radius 50, and crosses the row y = 300.5 at x = 450.5, 25 px
    // right of the rectangle's side, where nothing else is drawn.
    page.core.add(engine::Rectangle({400.5, 300.5}, 60, 80));
    page.window.overlay = true;
    page.window.clock.advanceFrame();
    page.core.runGameLoop();
    const auto bounds = [](const browser::Document& document) {
        return std::count_if(document.legend.begin(), document.legend.end(),
                             [](const auto& entry) { return entry.text.starts_with("bounding circle"); });
    };
    test::expectEqual("lines of the legend naming bounding circles, the stage's own layer alone", 0,
                      bounds(page.window.document));
    page.window.overlay_all = true;
    page.window.clock.advanceFrame();
    page.core.runGameLoop();
    const browser::Document& document = page.window.document;
    test::expectEqual("lines of the legend naming bounding circles, every layer on", 1, bounds(document));
    test::expectEqual("pixel (450, 300), on the rectangle's bounding circle (radius 50 = half its diagonal)",
                      test::legendColor(document, "bounding circle"), document.canvas.pixels().at(450, 300));
    test::expectEqual("pixel (455, 300), 5 px outside the bounding circle", browser::colors::kWhite,
                      document.canvas.pixels().at(455, 300));
}

TEST_CASE(
    "collision overlay: the legend has the stage's kOwnLegendEntries lines with its own layer, kLegendEntries with "
    "every layer, as tall as its band") {
    EveryLayerPage page;
    page.core.add(engine::Circle({200.5, 100.5}, 20));
    page.core.add(engine::Circle({230.5, 100.5}, 20));
    page.core.add(engine::Rectangle({400.5, 300.5}, 60, 80));
    page.window.overlay = true;
    for (int frame = 0; frame < 3; ++frame) {
        page.window.clock.advanceFrame();
        page.core.runGameLoop();
    }
    test::expectEqual("lines of the legend with the stage's own layer, running (overlay.h's kOwnLegendEntries)",
                      engine::kOwnLegendEntries, page.window.document.legend.size());
    test::expectEqual("the entries the page's band is made for in a run that shows the own layer alone",
                      engine::kOwnLegendEntries, page.window.document.legend_entries);
    page.window.overlay_all = true;
    page.window.every_layer_possible = true;
    page.window.clock.advanceFrame();
    page.core.runGameLoop();
    const browser::Document& document = page.window.document;
    test::expectEqual("lines of the legend with every layer on and running (overlay.h's kLegendEntries)",
                      engine::kLegendEntries, document.legend.size());
    test::expectEqual("the entries the page's band is made for in a run where every layer can come on",
                      engine::kLegendEntries, document.legend_entries);
    // The band under the page is as tall as those entries' rows, and no taller.
    browser::Document without = document;
    without.legend.clear();
    without.legend_room = false;
    test::expectEqual(
        "the page's height with the legend, less the page's without it",
        browser::legend_band_height(engine::kLegendEntries, document.canvas.width() + browser::kPanelWidth,
                                    document.legend_text_width),
        browser::render_page(document).height - browser::render_page(without).height);
}

// Every entry of the legend, every layer on, is no wider than the stage says its entries
// can be (page.h's Document::legend_text_width, the width of the band's columns), and
// lies on the page, left of the next column: no entry runs into another or off the page.
TEST_CASE("collision overlay: every entry of the legend, every layer on, lies on the page in its own column") {
    EveryLayerPage page;
    page.core.add(engine::Circle({200.5, 100.5}, 20));
    page.core.add(engine::Circle({230.5, 100.5}, 20));
    page.core.add(engine::Rectangle({400.5, 300.5}, 60, 80));
    page.window.overlay = true;
    page.window.overlay_all = true;
    page.window.every_layer_possible = true;
    for (int frame = 0; frame < 3; ++frame) {
        page.window.clock.advanceFrame();
        page.core.runGameLoop();
    }
    const browser::Document& document = page.window.document;
    REQUIRE(document.legend.size() == engine::kLegendEntries);
    for (const browser::LegendEntry& entry : document.legend) {
        INFO(entry.text);
        CHECK(browser::text_width(entry.text) <= document.legend_text_width);
    }
    const int page_width = browser::render_page(document).width;
    REQUIRE(browser::legend_boxes(document).size() == document.legend.size());
    CHECK(test::entryOffThePage(document, page_width).value_or("none") == "none");
}

}  // namespace collision_overlay_test
