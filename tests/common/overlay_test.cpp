// The overlay's plumbing: --overlay and the key t on a stage that has an overlay (and on
// no other), the key turning Window::overlay, the drawing words of overlay_draw.h, the
// canvas's fillText and fillRect, and the legend box at the bottom of the echo panel.
#include <catch2/catch.hpp>

#include <string>
#include <vector>

#include "browser.h"
#include "captured_output.h"
#include "command_line.h"
#include "overlay_draw.h"
#include "page.h"
#include "scratch_folder.h"

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
}

TEST_CASE("overlay: the key t turns the window's overlay and never reaches the page") {
    const auto parsed = parse({"--overlay"}, kWithOverlay);
    REQUIRE(parsed.options);
    browser::Window window(*parsed.options);
    CHECK(window.overlay);
    CountingScripts scripts;
    browser::press_key(scripts, window, *parsed.options, browser::kOverlayKey);
    CHECK_FALSE(window.overlay);
    browser::press_key(scripts, window, *parsed.options, browser::kOverlayKey);
    CHECK(window.overlay);
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

TEST_CASE("overlay: the legend is a box at the bottom of the echo panel, a swatch a line") {
    browser::Document document{browser::Canvas(200, 300), "echo"};
    const browser::Image without = browser::render_page(document);
    document.legend = {{kPurple, "one"}, {browser::colors::kRed, "two"}};
    const browser::Image with = browser::render_page(document);
    // The swatches stand at the panel's left, one over the other, in the lowest
    // 60 px of the page; nothing above the box changed.
    int purple_rows = 0, red_rows = 0, lowest_purple = 0, highest_red = 300;
    for (int j = 0; j < 300; ++j) {
        for (int i = 200; i < 240; ++i) {
            if (with.at(i, j) == kPurple) {
                ++purple_rows;
                lowest_purple = std::max(lowest_purple, j);
                break;
            }
        }
        for (int i = 200; i < 240; ++i) {
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
    CHECK(highest_red > 240);
    for (int j = 0; j < 200; ++j) {
        for (int i = 0; i < with.width; ++i) REQUIRE(with.at(i, j) == without.at(i, j));
    }
}
