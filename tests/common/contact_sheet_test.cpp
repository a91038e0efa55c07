// The contact sheet: which frames it shows, how a page shrinks, and where each
// thumbnail and label lands.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "contact_sheet.h"

using browser::Color;
using browser::ContactSheet;
using browser::Image;
using browser::kLabelHeight;
using browser::kSheetMargin;
using browser::kThumbnailScale;

namespace {

bool has_black_pixel(const Image& image, int left, int top, int right, int bottom) {
    for (int y = top; y < bottom; ++y) {
        for (int x = left; x < right; ++x) {
            if (image.at(x, y) == browser::colors::kBlack) return true;
        }
    }
    return false;
}

// A page whose every pixel differs, so a misplaced block would show.
Image pattern(int width, int height, std::uint8_t blue) {
    Image page(width, height);
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            page.set(x, y, {static_cast<std::uint8_t>(x * 4), static_cast<std::uint8_t>(y * 8), blue, 255});
        }
    }
    return page;
}

}  // namespace

TEST_CASE("contact_sheet: it shows the saved frames, then the last one") {
    using V = std::vector<int>;
    CHECK(browser::contact_sheet_frames(25, 10) == V{0, 10, 20, 24});
    CHECK(browser::contact_sheet_frames(21, 10) == V{0, 10, 20});  // the last frame was saved
    CHECK(browser::contact_sheet_frames(240, 30) == V{0, 30, 60, 90, 120, 150, 180, 210, 239});
    CHECK(browser::contact_sheet_frames(1, 5) == V{0});
    CHECK(browser::contact_sheet_frames(3, 1) == V{0, 1, 2});
    CHECK_THROWS_AS(browser::contact_sheet_frames(10, 0), std::invalid_argument);
}

TEST_CASE("contact_sheet: a long run shows every s-th saved frame, at most kMostThumbnails") {
    CHECK(browser::contact_sheet_frames(100, 1).size() == 100);  // exactly fits
    const std::vector<int> thinned = browser::contact_sheet_frames(101, 1);
    CHECK(thinned.size() == 51);  // every 2nd of 101
    CHECK(thinned[1] == 2);
    CHECK(thinned.back() == 100);
    const std::vector<int> long_run = browser::contact_sheet_frames(10'000'000, 1);
    CHECK(long_run.size() <= static_cast<std::size_t>(browser::kMostThumbnails));
    CHECK(long_run.front() == 0);
    CHECK(long_run.back() == 9'999'999);
    CHECK(std::is_sorted(long_run.begin(), long_run.end()));
}

TEST_CASE("contact_sheet: a thumbnail pixel is the rounded mean of its block") {
    Image page(7, 4);  // 3 x 2 thumbnail: the right column and bottom row are cut blocks
    // Block (0, 0): nine pixels made by hand.
    const std::uint8_t reds[3][3] = {{0, 10, 20}, {30, 40, 50}, {60, 70, 81}};
    for (int y = 0; y < 3; ++y) {
        for (int x = 0; x < 3; ++x) page.set(x, y, {reds[y][x], 255, 0, 255});
    }
    // Block (2, 0): a cut block, column 6 rows 0 to 2.
    page.set(6, 0, {0, 0, 0, 255});
    page.set(6, 1, {100, 100, 100, 255});
    page.set(6, 2, {101, 101, 101, 255});

    const Image small = browser::shrink(page, 3);
    CHECK(small.width == 3);
    CHECK(small.height == 2);
    CHECK(small.at(0, 0) == Color{40, 255, 0, 255});   // 361 / 9 = 40.1
    CHECK(small.at(2, 0) == Color{67, 67, 67, 255});   // 201 / 3 = 67
    CHECK(small.at(1, 1) == browser::colors::kWhite);  // untouched paper stays white
    CHECK(browser::shrink(page, 1).rgba == page.rgba);
}

TEST_CASE("contact_sheet: the sheet's size follows from the number of pages and the grid") {
    const int page_width = 60, page_height = 30;  // thumbnails of 20 x 10
    const int cell_width = page_width / kThumbnailScale + kSheetMargin;
    const int cell_height = kLabelHeight + page_height / kThumbnailScale + kSheetMargin;
    SECTION("six pages: two rows of four columns") {
        ContactSheet sheet(6);
        for (int i = 0; i < 6; ++i) sheet.add(Image(page_width, page_height), "frame 1");
        CHECK(sheet.picture().width == kSheetMargin + 4 * cell_width);
        CHECK(sheet.picture().height == kSheetMargin + 2 * cell_height);
        CHECK_THROWS_AS(sheet.add(Image(page_width, page_height), "one more"), std::logic_error);
    }
    SECTION("two pages: one row of two") {
        ContactSheet sheet(2);
        sheet.add(Image(page_width, page_height), "a");
        CHECK(sheet.picture().width == kSheetMargin + 2 * cell_width);
        CHECK(sheet.picture().height == kSheetMargin + cell_height);
        CHECK_THROWS_AS(sheet.add(Image(page_width + 1, page_height), "b"), std::invalid_argument);
    }
}

TEST_CASE("contact_sheet: each thumbnail sits under its label in its cell") {
    const int page_width = 300, page_height = 60;  // thumbnails of 100 x 20
    ContactSheet sheet(5);
    std::vector<Image> pages;
    for (int i = 0; i < 5; ++i) {
        pages.push_back(pattern(page_width, page_height, static_cast<std::uint8_t>(40 * i)));
        sheet.add(pages.back(), "frame " + std::to_string(10 * i));
    }
    const Image& picture = sheet.picture();
    const int cell_width = 100 + kSheetMargin, cell_height = kLabelHeight + 20 + kSheetMargin;
    for (int i = 0; i < 5; ++i) {
        INFO("page " << i);
        const int left = kSheetMargin + (i % 4) * cell_width;
        const int top = kSheetMargin + (i / 4) * cell_height;
        const Image thumbnail = browser::shrink(pages[static_cast<std::size_t>(i)], kThumbnailScale);
        CHECK(picture.at(left, top + kLabelHeight) == thumbnail.at(0, 0));
        CHECK(picture.at(left + 57, top + kLabelHeight + 13) == thumbnail.at(57, 13));
        CHECK(picture.at(left + 99, top + kLabelHeight + 19) == thumbnail.at(99, 19));
        CHECK(has_black_pixel(picture, left, top, left + 100, top + kLabelHeight));
        CHECK(picture.at(left - 1, top) == browser::kSheetBackground);  // the margin
    }
    // The sixth cell stays empty: background, no label.
    const int left = kSheetMargin + cell_width, top = kSheetMargin + cell_height;
    CHECK_FALSE(has_black_pixel(picture, left, top, left + 100, top + cell_height - kSheetMargin));
    CHECK(picture.at(left + 50, top + kLabelHeight + 10) == browser::kSheetBackground);
}
