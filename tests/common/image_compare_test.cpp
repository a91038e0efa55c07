// Comparing pictures: identical ones match, one changed pixel is found and measured,
// the tolerance decides, and pictures of different sizes never match.

#include <catch2/catch.hpp>

#include "image_compare.h"

using browser::Color;
using browser::Image;
using browser::Tolerance;

namespace {

Image scene() {  // white with a black bar: something to fade in the diff picture
    Image image(40, 30);
    for (int x = 5; x < 35; ++x) image.set(x, 10, browser::colors::kBlack);
    return image;
}

}  // namespace

TEST_CASE("image_compare: identical pictures match with no differing pixel") {
    const auto result = browser::compare_images(scene(), scene(), Tolerance{});
    CHECK(result.same_size);
    CHECK(result.differing_pixels == 0);
    CHECK(result.differing_share == 0.0);
    CHECK(result.largest_channel_difference == 0);
    CHECK(result.within(Tolerance{}));
}

TEST_CASE("image_compare: one changed pixel is found and measured") {
    Image changed = scene();
    changed.set(3, 4, Color{255, 218, 240, 255});  // white with green down by 37, blue by 15
    const auto result = browser::compare_images(scene(), changed, Tolerance{});
    CHECK(result.differing_pixels == 1);
    CHECK(result.differing_share == Approx(1.0 / (40 * 30)));
    CHECK(result.largest_channel_difference == 37);
    CHECK_FALSE(result.within(Tolerance{}));

    // The diff picture: the changed pixel red, the rest the expected picture faded
    // towards white (black becomes 255 - 255/4 = 192, white stays white).
    REQUIRE(result.diff.width == 40);
    REQUIRE(result.diff.height == 30);
    CHECK(result.diff.at(3, 4) == browser::colors::kRed);
    CHECK(result.diff.at(10, 10) == Color{192, 192, 192, 255});
    CHECK(result.diff.at(0, 0) == browser::colors::kWhite);
}

TEST_CASE("image_compare: the tolerance decides what differs and what matches") {
    Image changed = scene();
    changed.set(3, 4, Color{255, 218, 240, 255});
    changed.set(20, 10, Color{20, 0, 0, 255});  // the black bar, red up by 20

    // Channel tolerance: a pixel differs only when some channel is off by MORE than it.
    CHECK(browser::compare_images(scene(), changed, Tolerance{.channel = 19}).differing_pixels == 2);
    CHECK(browser::compare_images(scene(), changed, Tolerance{.channel = 20}).differing_pixels == 1);
    CHECK(browser::compare_images(scene(), changed, Tolerance{.channel = 37}).differing_pixels == 0);

    // Share tolerance: two pixels of 1200 differ.
    const auto result = browser::compare_images(scene(), changed, Tolerance{});
    CHECK(result.within(Tolerance{.channel = 0, .pixel_share = 2.0 / 1200}));
    CHECK_FALSE(result.within(Tolerance{.channel = 0, .pixel_share = 1.9 / 1200}));
}

TEST_CASE("image_compare: the region is the smallest box holding every differing pixel") {
    CHECK(browser::compare_images(scene(), scene(), Tolerance{}).region.empty());

    Image changed = scene();
    changed.set(3, 4, Color{255, 218, 240, 255});
    changed.set(20, 10, Color{20, 0, 0, 255});
    changed.set(12, 25, Color{250, 250, 250, 255});  // white, each colour down by 5
    // Columns 3, 20 and 12, rows 4, 10 and 25: x from 3 to 20, y from 4 to 25.
    const browser::PixelBox box = browser::compare_images(scene(), changed, Tolerance{}).region;
    CHECK(box.left == 3);
    CHECK(box.right == 20);
    CHECK(box.top == 4);
    CHECK(box.bottom == 25);
    // A pixel within the channel tolerance is no difference, and leaves the box: above a
    // tolerance of 20 only (3, 4) is left (green off by 37; the others by 20 and 5).
    const browser::PixelBox strict = browser::compare_images(scene(), changed, Tolerance{.channel = 20}).region;
    CHECK(strict.left == 3);
    CHECK(strict.right == 3);
    CHECK(strict.top == 4);
    CHECK(strict.bottom == 4);
}

TEST_CASE("image_compare: pictures of different sizes are reported, never matched") {
    const Image small(30, 20), wide(40, 10);
    const auto result = browser::compare_images(small, wide, Tolerance{.channel = 255, .pixel_share = 1.0});
    CHECK_FALSE(result.same_size);
    CHECK_FALSE(result.within(Tolerance{.channel = 255, .pixel_share = 1.0}));
    // Over the 40 x 20 box either covers: 30 x 10 shared pixels (all white, the same),
    // 30 x 10 only in `small`, 10 x 10 only in `wide`.
    CHECK(result.differing_pixels == 300 + 100);
    CHECK(result.diff.width == 40);
    CHECK(result.diff.height == 20);

    const auto empty = browser::compare_images(Image(), small, Tolerance{});
    CHECK_FALSE(empty.same_size);
    CHECK(empty.differing_pixels == 600);
}
