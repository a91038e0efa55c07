#include "side_by_side.h"

#include <algorithm>
#include <stdexcept>

#include "page.h"  // kPanelWidth
#include "text.h"

namespace browser {

namespace {

// A tint keeps a quarter of the colour's distance from white: light enough to read as
// "where it was", and still one of the GIF palette's ramps from white to the colour.
constexpr int kTintShare = 4;

std::uint8_t tint(std::uint8_t channel) { return static_cast<std::uint8_t>(255 - (255 - channel) / kTintShare); }

// The text's top inside its band, and its left margin: the font's letters are about
// 14 px tall.
constexpr int kLabelTop = 5;
constexpr int kLabelLeft = 6;

}  // namespace

// The canvas's frame runs down its left edge, row after row; a band under the page (a
// stage's section beyond the book, page.h) is white paper there. The canvas ends with
// the frame.
Image canvas_of(const Image& page, int scale) {
    const int width = std::max(page.width - kPanelWidth * scale, 0);
    int height = page.height;
    while (height > 0 && width > 0 && page.at(0, height - 1) == colors::kWhite) --height;
    Image canvas(width, height);
    canvas.paste(page, 0, 0);
    return canvas;
}

Image cropped(const Image& picture, int x, int y, int width, int height) {
    Image part(width, height);
    part.paste(picture, -x, -y);
    return part;
}

Image with_start_ghost(const Image& picture, const Image& start) {
    if (picture.width != start.width || picture.height != start.height) {
        throw std::invalid_argument("with_start_ghost: the pictures differ in size");
    }
    Image ghosted = picture;
    for (int y = 0; y < picture.height; ++y) {
        for (int x = 0; x < picture.width; ++x) {
            const Color then = start.at(x, y);
            if (picture.at(x, y) != colors::kWhite || then == colors::kWhite) continue;
            ghosted.set(x, y, {tint(then.r), tint(then.g), tint(then.b), 255});
        }
    }
    return ghosted;
}

Image with_trail(const Image& picture, const Image& trail) {
    if (picture.width != trail.width || picture.height != trail.height) {
        throw std::invalid_argument("with_trail: the pictures differ in size");
    }
    Image trailed = picture;
    for (int y = 0; y < picture.height; ++y) {
        for (int x = 0; x < picture.width; ++x) {
            if (picture.at(x, y) == colors::kWhite) trailed.set(x, y, trail.at(x, y));
        }
    }
    return trailed;
}

Image side_by_side(const Image& left, std::string_view left_label, const Image& right, std::string_view right_label) {
    const int band = kHalfLabelHeight;
    const int gap = kGapWidth;
    Image joined(left.width + gap + right.width, band + std::max(left.height, right.height));
    joined.paste(left, 0, band);
    joined.paste(right, left.width + gap, band);
    draw_text(joined, left_label, kLabelLeft, kLabelTop, colors::kBlack);
    draw_text(joined, right_label, left.width + gap + kLabelLeft, kLabelTop, colors::kBlack);
    return joined;
}

}  // namespace browser
