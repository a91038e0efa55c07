// Stage 1.1: the user control script draws within the book's ranges, repeatably.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdint>

#include "core.h"
#include "near.h"
#include "user_control.h"

namespace s1_1_test {

namespace {

struct InkBox {  // the smallest box around every pixel that is not white
    int left = 1 << 30, top = 1 << 30, right = -1, bottom = -1;
    bool empty() const { return right < 0; }
    int width() const { return right - left + 1; }
    int height() const { return bottom - top + 1; }
};

InkBox inkBox(const browser::Image& image) {
    InkBox box;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x)
            if (image.at(x, y) != browser::colors::kWhite) {
                box.left = std::min(box.left, x);
                box.right = std::max(box.right, x);
                box.top = std::min(box.top, y);
                box.bottom = std::max(box.bottom, y);
            }
    return box;
}

browser::Image drawOne(browser::Key key, std::uint64_t seed) {
    browser::Canvas canvas;
    browser::Random random(seed);
    engine::Core core(canvas);
    engine::UserControl control(core, random);
    control.onKeyDown(key);
    return canvas.pixels();
}

// A 1 px anti-aliased outline can darken the pixel on either side of the exact edge.
constexpr int kInkSlack = 2;

}  // namespace

TEST_CASE("s1_1: F strokes a rectangle 10 to 40 px a side with its corner in the top-left 80%") {
    int smallest = 1000, largest = 0;
    for (std::uint64_t seed = 1; seed <= 300; ++seed) {
        const InkBox box = inkBox(drawOne(browser::Key::F, seed));
        REQUIRE_FALSE(box.empty());
        // Corner x in [0, 640), y in [0, 360): 80% of 800 x 450.
        CHECK(box.left >= -kInkSlack);
        CHECK(box.left < 640 + kInkSlack);
        CHECK(box.top < 360 + kInkSlack);
        for (int side : {box.width(), box.height()}) {
            CHECK(side >= 10 - kInkSlack);
            CHECK(side <= 40 + kInkSlack);
            smallest = std::min(smallest, side);
            largest = std::max(largest, side);
        }
    }
    // 600 uniform sides in [10, 40) all but surely reach both ends of the range.
    CHECK(smallest <= 13);
    CHECK(largest >= 38);
}

TEST_CASE("s1_1: G strokes a circle of radius 10 to 40 px centred in the top-left 80%") {
    int smallest = 1000, largest = 0;
    for (std::uint64_t seed = 1; seed <= 300; ++seed) {
        const InkBox box = inkBox(drawOne(browser::Key::G, seed));
        REQUIRE_FALSE(box.empty());
        const double diameter = box.width();
        const double centre_x = box.left + diameter / 2;
        const double centre_y = box.top + box.height() / 2.0;
        if (box.left > 0 && box.top > 0) {  // wholly on the canvas: the box is the circle's
            // 1 px: each side of the inked box rounds the outline to whole pixels.
            CHECK_THAT(box.width(), test::near(box.height(), 1));
            CHECK(diameter >= 20 - kInkSlack);
            CHECK(diameter <= 80 + kInkSlack);
            smallest = std::min<int>(smallest, box.width());
            largest = std::max<int>(largest, box.width());
        }
        CHECK(centre_x < 640 + kInkSlack);
        CHECK(centre_y < 360 + kInkSlack);
    }
    CHECK(smallest <= 26);
    CHECK(largest >= 76);
}

TEST_CASE("s1_1: the same seed draws the same picture, another seed another") {
    auto scene = [](std::uint64_t seed) {
        browser::Canvas canvas;
        browser::Random random(seed);
        engine::Core core(canvas);
        engine::UserControl control(core, random);
        for (browser::Key key : {browser::Key::F, browser::Key::G, browser::Key::F, browser::Key::G})
            control.onKeyDown(key);
        return canvas.pixels().rgba;
    };
    CHECK(scene(42) == scene(42));
    CHECK(scene(42) != scene(43));
}

TEST_CASE("s1_1: keys other than F and G draw nothing") {
    for (browser::Key key : {browser::Key::A, browser::Key::Digit0, browser::Key::Up, browser::Key::Comma})
        CHECK(inkBox(drawOne(key, 1)).empty());
}

// The README's walkthrough ("Play it live"): F G F G, each press one more outline.
TEST_CASE("s1_1: README walkthrough: each press draws one more outline") {
    browser::Canvas canvas;
    browser::Random random(browser::Random::kDefaultSeed);
    engine::Core core(canvas);
    engine::UserControl control(core, random);
    const auto inked = [&canvas] {
        int count = 0;
        for (int y = 0; y < canvas.height(); ++y)
            for (int x = 0; x < canvas.width(); ++x) count += canvas.pixels().at(x, y) != browser::colors::kWhite;
        return count;
    };
    int before = inked();
    CHECK(before == 0);
    for (const browser::Key key : browser::KeyScript::parse("f g f g").pressesAt(0)) {
        control.onKeyDown(key);
        const int after = inked();
        CHECK(after > before);  // nothing is erased, and the new outline adds ink
        before = after;
    }
}

}  // namespace s1_1_test
