#include "image_compare.h"

#include <algorithm>
#include <cstdlib>

namespace browser {

namespace {

constexpr Color kDifferentColor = colors::kRed;

// The diff picture shows the expected picture faded three quarters of the way to white,
// so the red marks stand out while the scene stays recognisable.
constexpr int kFadeDivisor = 4;

Color faded(Color c) {
    auto fade = [](std::uint8_t v) { return static_cast<std::uint8_t>(255 - (255 - v) / kFadeDivisor); };
    return {fade(c.r), fade(c.g), fade(c.b), 255};
}

int largest_channel_difference(Color a, Color b) {
    return std::max({std::abs(a.r - b.r), std::abs(a.g - b.g), std::abs(a.b - b.b), std::abs(a.a - b.a)});
}

}  // namespace

void PixelBox::add(int x, int y) {
    if (empty()) {
        *this = {x, y, x, y};
        return;
    }
    left = std::min(left, x);
    top = std::min(top, y);
    right = std::max(right, x);
    bottom = std::max(bottom, y);
}

ImageDifference compare_images(const Image& expected, const Image& actual, const Tolerance& tolerance) {
    ImageDifference result;
    result.same_size = expected.width == actual.width && expected.height == actual.height;

    // Pictures of different sizes are compared over the area either one covers: where only
    // one of them has a pixel, that pixel differs.
    const int width = std::max(expected.width, actual.width);
    const int height = std::max(expected.height, actual.height);
    result.diff = Image(width, height, colors::kWhite);
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            const bool in_expected = expected.contains(x, y), in_actual = actual.contains(x, y);
            bool differs = in_expected != in_actual;
            if (in_expected && in_actual) {
                const int difference = largest_channel_difference(expected.at(x, y), actual.at(x, y));
                result.largest_channel_difference = std::max(result.largest_channel_difference, difference);
                differs = difference > tolerance.channel;
            }
            if (differs) {
                ++result.differing_pixels;
                result.region.add(x, y);
                result.diff.set(x, y, kDifferentColor);
            } else if (in_expected) {
                result.diff.set(x, y, faded(expected.at(x, y)));
            }
        }
    }
    const long pixel_count = static_cast<long>(width) * height;
    result.differing_share = pixel_count > 0 ? static_cast<double>(result.differing_pixels) / pixel_count : 0.0;
    return result;
}

}  // namespace browser
