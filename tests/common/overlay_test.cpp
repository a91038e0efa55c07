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

// Whether every pixel of `color` on `canvas` lies at least `margin` px inside its edges;
// and how many there are.
int inkInside(const browser::Canvas& canvas, Color color, int margin, bool& inside) {
    int ink = 0;
    inside = true;
    for (int j = 0; j < canvas.height(); ++j) {
        for (int i = 0; i < canvas.width(); ++i) {
            if (canvas.pixels().at(i, j) != color) continue;
            ++ink;
            if (i < margin || j < margin || i >= canvas.width() - margin || j >= canvas.height() - margin)
                inside = false;
        }
    }
    return ink;
}

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
    // The page grew by the band: a line of 18 px for each of the two entries (the page,
    // 200 + 380 px wide, holds one column of 390 px) and a margin of 10.
    REQUIRE(with.width == without.width);
    REQUIRE(with.height == 300 + 2 * 18 + 10);
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

TEST_CASE("overlay: the legend's band has a row for every entry the stage's overlay can show, in columns") {
    // A page 200 + 380 = 580 px wide holds one column of 390 px; 800 + 380 = 1180 three.
    CHECK(browser::legend_band_height(0, 580) == 0);
    CHECK(browser::legend_band_height(1, 580) == 1 * 18 + 10);
    CHECK(browser::legend_band_height(10, 580) == 10 * 18 + 10);
    CHECK(browser::legend_band_height(10, 1180) == 4 * 18 + 10);  // 4 + 3 + 3
    CHECK(browser::legend_band_height(9, 1180) == 3 * 18 + 10);

    browser::Document document{browser::Canvas(200, 300), "echo"};
    document.legend_room = true;
    document.legend_entries = 10;  // the most the stage's overlay shows
    document.legend = {{kPurple, "entry"}, {kPurple, "entry"}, {kPurple, "entry"}};
    const browser::Image three = browser::render_page(document);
    // The band keeps the stage's ten rows while three are shown: one height a run.
    CHECK(three.height == 300 + 10 * 18 + 10);
    // A legend longer than the stage said grows the band, and shows every entry.
    document.legend.assign(12, {kPurple, "entry"});
    const browser::Image twelve = browser::render_page(document);
    CHECK(twelve.height == 300 + 12 * 18 + 10);
    int swatch_rows = 0;
    for (int j = 300; j < twelve.height; ++j) {
        for (int i = 0; i < 60; ++i) {
            if (twelve.at(i, j) == kPurple) {
                ++swatch_rows;
                break;
            }
        }
    }
    CHECK(swatch_rows == 12 * 12);  // twelve swatches of 12 px, one under the other
}

// The stage says how wide its widest entry can be (Document::legend_text_width): each
// column is that, a 12 px swatch, a 6 px gap before the text and 6 px after it. 366 px
// (the default) makes columns 390 px apart: three on a page 1180 px wide (1170 px inside
// its 10 px of margins); 460 px makes them 484 px apart: two.
TEST_CASE("overlay: the legend's columns are as wide as the stage's widest entry, and every entry lies in one") {
    CHECK(browser::legend_band_height(43, 1180) == 15 * 18 + 10);       // 15 + 14 + 14
    CHECK(browser::legend_band_height(43, 1180, 460) == 22 * 18 + 10);  // 22 + 21
    CHECK(browser::legend_band_height(31, 980, 460) == 16 * 18 + 10);   // 970 px: two columns
    CHECK(browser::legend_band_height(31, 980, 490) == 31 * 18 + 10);   // 514 px apart: one

    // A page 800 + 380 = 1180 px wide, an echo of one line (no band under it) and five
    // entries in columns of 460 px: rows of three (5 entries, 2 columns), the first column
    // at x = 10, the second 484 px on, the first row 5 px under the canvas.
    browser::Document document{browser::Canvas(800, 300), "echo"};
    document.legend_text_width = 460;
    document.legend.assign(5, {kPurple, "entry"});
    const std::vector<browser::LegendBox> boxes = browser::legend_boxes(document);
    REQUIRE(boxes.size() == 5);
    const int entry = 12 + 6 + browser::text_width("entry");
    CHECK(boxes[0].left == 10);
    CHECK(boxes[0].top == 300 + 5);
    CHECK(boxes[0].right == 10 + entry);
    CHECK(boxes[0].bottom == 300 + 5 + 18);
    CHECK(boxes[2].top == 300 + 5 + 2 * 18);
    CHECK(boxes[3].left == 10 + 484);
    CHECK(boxes[3].top == 300 + 5);
    CHECK(boxes[4].top == 300 + 5 + 18);
    // Where the page draws them: the swatch of the fourth entry at (494, 305 + 2).
    const browser::Image page = browser::render_page(document);
    CHECK(page.height == 300 + 3 * 18 + 10);
    CHECK(page.at(494, 305 + 4) == kPurple);
    CHECK(page.at(494 - 1, 305 + 4) == browser::colors::kWhite);
}

TEST_CASE("overlay: a note on a line of the echo is a dim mark after it and its text under the panel") {
    const std::string echo = "Selected Object:\n  Mass: 6.993006993006993\n  Friction: 0.300\n";
    browser::Document document{browser::Canvas(200, 300), echo};
    const browser::Image plain = browser::render_page(document);
    document.echo_notes = {{"Mass:", "*", "the book's quirk"}};
    const browser::Image noted = browser::render_page(document);
    CHECK(document.ui_echo == echo);  // the echo itself is the book's, letter for letter
    // The page grew by a band of one line: a gap of 5, the line of 18 and 5 under it.
    REQUIRE(noted.width == plain.width);
    REQUIRE(noted.height == 300 + 5 + 18 + 5);
    // In the panel, the only change is the mark, gray, on the Mass line (the second:
    // rows 10 + 18 to 10 + 36), after its text.
    const int mass_text_end = 200 + 10 + browser::text_width("  Mass: 6.993006993006993");
    int changed = 0, gray_on_mass_line = 0;
    for (int j = 0; j < 300; ++j) {
        for (int i = 0; i < noted.width; ++i) {
            if (noted.at(i, j) == plain.at(i, j)) continue;
            ++changed;
            const bool on_mass_line = j >= 10 + 18 && j < 10 + 36 && i >= mass_text_end;
            if (on_mass_line && noted.at(i, j) == browser::colors::kGray) ++gray_on_mass_line;
        }
    }
    CHECK(changed > 0);
    CHECK(gray_on_mass_line == changed);
    // Under the panel, the note's line is gray ink, at the panel's left.
    int gray_under = 0;
    for (int j = 300; j < noted.height; ++j) {
        for (int i = 0; i < noted.width; ++i) gray_under += noted.at(i, j) == browser::colors::kGray ? 1 : 0;
    }
    CHECK(gray_under > 0);
    // An echo without the line keeps the note's band (the page keeps its height), no mark.
    document.ui_echo = "Selected Object:\n  Id: none\n";
    CHECK(browser::render_page(document).height == noted.height);
}

TEST_CASE("overlay: an echo longer than the panel stops at its last whole line, clear of the band under it") {
    std::string echo;
    for (int line = 0; line < 30; ++line) echo += "echo line\n";  // 30 lines of 18 px: more than 300 px
    browser::Document document{browser::Canvas(200, 300), echo};
    document.echo_notes = {{"none", "*", "a note"}};
    const browser::Image page = browser::render_page(document);
    // Lines start at 10, 28, ..., 280, 298: a line is drawn when its 18 px end by 305, where
    // the band's first line starts; the one at 280 does (298), the one at 298 does not
    // (316). So the panel's rows from the canvas's bottom to the band's line are white.
    for (int j = 300; j < 305; ++j) {
        for (int i = 200; i < page.width; ++i) REQUIRE(page.at(i, j) == browser::colors::kWhite);
    }
    int black_under = 0;  // and the band holds the note alone, gray
    for (int j = 300; j < page.height; ++j) {
        for (int i = 200; i < page.width; ++i) black_under += page.at(i, j) == browser::colors::kBlack ? 1 : 0;
    }
    CHECK(black_under == 0);
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

TEST_CASE("overlay: a label asked for at the canvas's edge is moved wholly onto it, every letter drawn") {
    const std::string text = "depth 1.50 px";
    // The whole label, drawn in the middle: its ink.
    browser::Canvas middle(200, 100);
    browser::overlay::LabelLayout{}.place(middle, {50, 40}, kPurple, text);
    bool inside = false;
    const int whole = inkInside(middle, kPurple, 2, inside);
    REQUIRE(whole > 0);
    // Asked for past each corner and edge: the same ink, all of it 2 px inside the edges.
    for (const Vec2 at : {Vec2{-20, -30}, Vec2{190, 95}, Vec2{-20, 95}, Vec2{190, -30}, Vec2{100, 99}, Vec2{199, 40}}) {
        browser::Canvas canvas(200, 100);
        browser::overlay::LabelLayout{}.place(canvas, at, kPurple, text);
        INFO("asked for (" << at.x << ", " << at.y << ")");
        CHECK(inkInside(canvas, kPurple, 2, inside) == whole);
        CHECK(inside);
    }
}

TEST_CASE("overlay: labels crowded at the canvas's foot stand apart above each other, all on the canvas") {
    const std::string text = "depth 1.50 px";
    browser::Canvas middle(200, 100);
    browser::overlay::LabelLayout{}.place(middle, {50, 40}, kPurple, text);
    bool inside = false;
    const int one = inkInside(middle, kPurple, 2, inside);
    // Three labels asked for one spot below the canvas: the first stands at its foot, the
    // others a line higher each, since lower would leave the canvas; the ink of all three
    // is three labels' (none covers another), all inside.
    browser::Canvas canvas(200, 100);
    browser::overlay::LabelLayout labels;
    for (int label = 0; label < 3; ++label) labels.place(canvas, {10, 120}, kPurple, text);
    CHECK(inkInside(canvas, kPurple, 2, inside) == 3 * one);
    CHECK(inside);
    int top_ink_row = canvas.height();
    for (int j = 0; j < canvas.height() && top_ink_row == canvas.height(); ++j) {
        for (int i = 0; i < canvas.width(); ++i) {
            if (canvas.pixels().at(i, j) == kPurple) {
                top_ink_row = j;
                break;
            }
        }
    }
    // Three lines of 18 px stacked on the foot (100 - 2): the top one starts at 44 or
    // lower, and its ink a few px under its top.
    CHECK(top_ink_row >= 100 - 2 - 3 * browser::text_line_height());
    CHECK(top_ink_row < 100 - 2 - 2 * browser::text_line_height());
}

TEST_CASE("overlay: the page keeps room for every layer's legend only in a run where every layer can come on") {
    const auto possible = [](std::vector<std::string> arguments) {
        const auto parsed = parse(std::move(arguments), kWithOverlay);
        REQUIRE(parsed.options);
        return browser::Window(*parsed.options).every_layer_possible;
    };
    CHECK_FALSE(possible({}));
    CHECK_FALSE(possible({"--overlay"}));           // the own layer, all the run
    CHECK_FALSE(possible({"--keys", "t"}));         // off -> own
    CHECK(possible({"--keys", "t t@1"}));           // off -> own -> every layer
    CHECK(possible({"--overlay", "--keys", "t"}));  // own -> every layer
    CHECK(possible({"--overlay-all"}));
    // A key pressed that the script did not hold (a live session's) takes it there too,
    // and the page keeps the room from then on.
    const auto live = parse({}, kWithOverlay);
    REQUIRE(live.options);
    browser::Window window(*live.options);
    CountingScripts scripts;
    browser::press_key(scripts, window, *live.options, browser::kOverlayKey);
    CHECK_FALSE(window.every_layer_possible);
    browser::press_key(scripts, window, *live.options, browser::kOverlayKey);
    CHECK(window.every_layer_possible);
    browser::press_key(scripts, window, *live.options, browser::kOverlayKey);  // off again: the room stays
    CHECK(window.every_layer_possible);
}
