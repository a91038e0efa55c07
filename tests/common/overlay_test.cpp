// The overlay's plumbing: --overlay and the key t on a stage that has an overlay (and on
// no other), the key turning Window::overlay, the drawing words of overlay_draw.h, the
// canvas's fillText and fillRect, and the legend box at the bottom of the echo panel.
#include <catch2/catch.hpp>

#include <limits>
#include <string>
#include <vector>

#include "browser.h"
#include "captured_output.h"
#include "command_line.h"
#include "overlay_draw.h"
#include "page.h"
#include "scratch_folder.h"
#include "text.h"

using browser::Color;
using browser::Key;
using lib::Vec2;

namespace {

const browser::StageDefaults kWithOverlay{
    .id = "s9_8",
    .title = "9.8 A Stage With An Overlay",
    .keys = "f",
    .frames = 3,
    .key_help = {{"f", "a new rectangle"}},
    .overlay = "what the test draws",
};

browser::StageDefaults without_overlay() {
    browser::StageDefaults defaults = kWithOverlay;
    defaults.overlay.clear();
    return defaults;
}

browser::ParsedCommandLine parse(std::vector<std::string> arguments, const browser::StageDefaults& defaults,
                                 std::string* err = nullptr) {
    arguments.insert(arguments.begin(), "s9_8_test");
    std::vector<const char*> argv;
    for (const std::string& argument : arguments) argv.push_back(argument.c_str());
    argv.push_back(nullptr);
    const test::CapturedOutput captured;
    browser::ParsedCommandLine parsed =
        browser::parse_command_line(static_cast<int>(arguments.size()), argv.data(), defaults);
    if (err != nullptr) *err = captured.err();
    return parsed;
}

// Counts the keys the page itself gets.
struct CountingScripts : browser::PageScripts {
    void onKeyDown(Key) override { ++keys; }
    void onAnimationFrame() override {}
    int keys = 0;
};

constexpr Color kPurple{160, 0, 200, 255};

bool same(Color a, Color b) { return a == b; }

}  // namespace

TEST_CASE("overlay: --overlay and the key t exist only on a stage with an overlay") {
    const auto plain = parse({}, kWithOverlay);
    REQUIRE(plain.options);
    CHECK(plain.options->overlay_offered);
    CHECK_FALSE(plain.options->overlay);  // off by default: the book's pictures stay the book's

    const auto on = parse({"--overlay", "--keys", "t f t"}, kWithOverlay);
    REQUIRE(on.options);
    CHECK(on.options->overlay);

    std::string err;
    CHECK(parse({"--overlay"}, without_overlay(), &err).exit_status == 2);
    CHECK(err.find("--overlay") != std::string::npos);
    CHECK(parse({"--keys", "t"}, without_overlay(), &err).exit_status == 2);
    CHECK(err.find("\"t\"") != std::string::npos);
    CHECK(parse({"--overlay=1"}, kWithOverlay, &err).exit_status == 2);
    CHECK(parse({"--overlay-all=1"}, kWithOverlay, &err).exit_status == 2);
    CHECK(parse({"--overlay-all"}, without_overlay(), &err).exit_status == 2);

    const auto all = parse({"--overlay-all"}, kWithOverlay);
    REQUIRE(all.options);
    CHECK(all.options->overlay_all);
    const browser::Window window(*all.options);
    CHECK(window.overlay);  // every layer is the overlay on
    CHECK(window.overlay_all);
}

TEST_CASE(
    "overlay: the key t takes the window's overlay round (own layer, every layer, off) and never reaches the "
    "page") {
    const auto parsed = parse({"--overlay"}, kWithOverlay);
    REQUIRE(parsed.options);
    browser::Window window(*parsed.options);
    CHECK(window.overlay);
    CHECK_FALSE(window.overlay_all);  // --overlay: the stage's own layer
    CountingScripts scripts;
    browser::press_key(scripts, window, *parsed.options, browser::kOverlayKey);
    CHECK(window.overlay);
    CHECK(window.overlay_all);
    browser::press_key(scripts, window, *parsed.options, browser::kOverlayKey);
    CHECK_FALSE(window.overlay);
    CHECK_FALSE(window.overlay_all);
    browser::press_key(scripts, window, *parsed.options, browser::kOverlayKey);
    CHECK(window.overlay);
    CHECK_FALSE(window.overlay_all);
    CHECK(scripts.keys == 0);
    browser::press_key(scripts, window, *parsed.options, Key::F);
    CHECK(scripts.keys == 1);
}

TEST_CASE("overlay: an arrow is its shaft and a head of two strokes at its tip") {
    browser::Canvas canvas(100, 60);
    // Along the row of pixel centres y = 30.5, from x = 10.5 to 80.5.
    browser::overlay::arrow(canvas, {10.5, 30.5}, {80.5, 30.5}, kPurple);
    const browser::Image& pixels = canvas.pixels();
    CHECK(same(pixels.at(20, 30), kPurple));
    CHECK(same(pixels.at(79, 30), kPurple));
    CHECK(same(pixels.at(85, 30), browser::colors::kWhite));  // nothing past the tip
    // The head's strokes end kHeadLength back along the shaft, turned kHeadAngle off it:
    // 7 cos 0.45 = 6.30 px back, 7 sin 0.45 = 3.04 px to each side. Pixel (78, 29)'s
    // centre (78.5, 29.5) lies 0.03 px off the upper stroke, (78, 31)'s as far off the
    // lower one: both nearly fully purple. One pixel farther out, (78, 27), is clear.
    CHECK(pixels.at(78, 29).g < 30);
    CHECK(pixels.at(78, 29).r > 140);
    CHECK(pixels.at(78, 31).g < 30);
    CHECK(same(pixels.at(78, 27), browser::colors::kWhite));
    // Too short to have a direction: nothing.
    browser::Canvas blank(20, 20);
    browser::overlay::arrow(blank, {5.5, 5.5}, {5.5, 5.5}, kPurple);
    CHECK(blank.pixels().at(5, 5) == browser::colors::kWhite);
}

TEST_CASE("overlay: a label is the page's font in the fill style, from its top-left corner") {
    browser::Canvas canvas(100, 40);
    browser::overlay::label(canvas, {20, 10}, kPurple, "IIII");
    int inked = 0, left = 100, top = 40;
    for (int j = 0; j < 40; ++j) {
        for (int i = 0; i < 100; ++i) {
            if (canvas.pixels().at(i, j) == kPurple) {
                ++inked;
                left = std::min(left, i);
                top = std::min(top, j);
            }
        }
    }
    CHECK(inked > 0);
    CHECK(left >= 20);
    CHECK(top >= 10);
    CHECK(left < 26);
    CHECK(top < 16);
    CHECK(canvas.fillStyle() == browser::colors::kBlack);  // the label kept the canvas's style
}

TEST_CASE("overlay: fillRect fills the pixels whose centres it covers, translated") {
    browser::Canvas canvas(20, 20);
    canvas.setFillStyle(kPurple);
    canvas.translate(2, 3);
    canvas.fillRect(1, 1, 4, 2);  // x 3..7, y 4..6: pixels 3..6 by 4..5
    CHECK(canvas.pixels().at(3, 4) == kPurple);
    CHECK(canvas.pixels().at(6, 5) == kPurple);
    CHECK(canvas.pixels().at(7, 5) == browser::colors::kWhite);
    CHECK(canvas.pixels().at(3, 6) == browser::colors::kWhite);
    CHECK(canvas.pixels().at(2, 4) == browser::colors::kWhite);
}

TEST_CASE("overlay: the legend is a band under the page, a swatch a line, and covers no line of the echo") {
    // An echo that fills the panel to its bottom, as chapter 4's does.
    std::string echo;
    for (int line = 0; line < 20; ++line) echo += "echo line\n";
    browser::Document document{browser::Canvas(200, 300), echo};
    const browser::Image without = browser::render_page(document);
    document.legend = {{kPurple, "one"}, {browser::colors::kRed, "two"}};
    const browser::Image with = browser::render_page(document);
    // The page grew by the band: seven lines of 18 px and a margin of 10.
    REQUIRE(with.width == without.width);
    REQUIRE(with.height == 300 + 7 * 18 + 10);
    // Everything above the band is the page without a legend: every echo line whole.
    for (int j = 0; j < 300; ++j) {
        for (int i = 0; i < with.width; ++i) REQUIRE(with.at(i, j) == without.at(i, j));
    }
    // The swatches stand at the band's left, 12 px each, the first over the second.
    int purple_rows = 0, red_rows = 0, lowest_purple = 0, highest_red = with.height;
    for (int j = 300; j < with.height; ++j) {
        for (int i = 0; i < 40; ++i) {
            if (with.at(i, j) == kPurple) {
                ++purple_rows;
                lowest_purple = std::max(lowest_purple, j);
                break;
            }
        }
        for (int i = 0; i < 40; ++i) {
            if (with.at(i, j) == browser::colors::kRed) {
                ++red_rows;
                highest_red = std::min(highest_red, j);
                break;
            }
        }
    }
    CHECK(purple_rows == 12);
    CHECK(red_rows == 12);
    CHECK(lowest_purple < highest_red);
}

TEST_CASE("overlay: room kept for the legend keeps the page's size, and is blank while the overlay is off") {
    browser::Document document{browser::Canvas(200, 300), "echo"};
    const browser::Image book = browser::render_page(document);
    document.legend_room = true;
    const browser::Image room = browser::render_page(document);
    document.legend = {{kPurple, "one"}};
    const browser::Image shown = browser::render_page(document);
    CHECK(room.height == shown.height);
    CHECK(room.height > book.height);
    for (int j = 0; j < room.height; ++j) {
        for (int i = 0; i < room.width; ++i) {
            REQUIRE(room.at(i, j) == (j < book.height ? book.at(i, j) : browser::colors::kWhite));
        }
    }
}

TEST_CASE("overlay: a legend longer than its band counts the entries it has no room for") {
    browser::Document document{browser::Canvas(200, 300), "echo"};  // a page 580 px wide: one column
    for (int entry = 0; entry < 10; ++entry) document.legend.push_back({kPurple, "entry"});
    const browser::Image page = browser::render_page(document);
    // Seven rows: six swatches and the line "4 more entries", in black.
    int swatches = 0, black_rows = 0;
    for (int j = 300; j < page.height; ++j) {
        bool purple = false, black = false;
        for (int i = 0; i < 60; ++i) {
            purple = purple || page.at(i, j) == kPurple;
            black = black || page.at(i, j) == browser::colors::kBlack;
        }
        swatches += purple ? 1 : 0;
        black_rows += black ? 1 : 0;
    }
    CHECK(swatches == 6 * 12);
    CHECK(black_rows > 0);  // the count's text, where a seventh swatch would be
}

TEST_CASE("overlay: numbers read as fixed decimals, never in exponent notation, never -0") {
    using browser::overlay::fixed;
    CHECK(fixed(3.19e-10, 2) == "0.00");  // a resting contact's depth
    CHECK(fixed(-3.19e-10, 2) == "0.00");
    CHECK(fixed(2520.4, 2) == "2520.40");  // what to_precision(x, 3) printed as 2.52e+3
    CHECK(fixed(6.004, 2) == "6.00");
    CHECK(fixed(-1.5, 1) == "-1.5");
    CHECK(fixed(12.0, 0) == "12");
    CHECK(fixed(std::numeric_limits<double>::quiet_NaN(), 2) == "nan");
    CHECK(fixed(-std::numeric_limits<double>::infinity(), 2) == "-inf");
    CHECK(fixed(1e308, 2).size() == 309 + 3);  // every digit, none cut
}

TEST_CASE("overlay: two labels asked for one place stand apart, the second a line lower") {
    browser::Canvas canvas(200, 100);
    browser::overlay::LabelLayout labels;
    labels.place(canvas, {10, 10}, kPurple, "depth 6.00 px");
    // Asked for the spot just right of the first label's end: kLabelGap would be
    // crossed, so it goes a line lower instead of running into the first.
    labels.place(canvas, {10.0 + browser::text_width("depth 6.00 px") + 2.0, 10.0}, kPurple, "depth 6.02 px");
    int rows_with_ink = 0;
    for (int j = 0; j < 100; ++j) {
        for (int i = 0; i < 200; ++i) {
            if (same(canvas.pixels().at(i, j), kPurple)) {
                ++rows_with_ink;
                break;
            }
        }
    }
    // Two lines of text: more rows than one line's glyphs reach.
    CHECK(rows_with_ink > browser::text_line_height());
}
