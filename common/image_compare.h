#pragma once
// Comparing two pictures pixel by pixel (decoded pixels, never file bytes), so a reader
// can check a stage's output against its expected/ pictures.

#include "image.h"

namespace browser {

struct Tolerance {
    int channel = 0;           // a pixel differs when some channel differs by more than this
    double pixel_share = 0.0;  // the images match while at most this share of pixels differs
};

// The smallest box holding every differing pixel, edges included, in the picture's
// pixels (for a page at scale 1, the page's coordinates: the canvas's, left of x 800).
struct PixelBox {
    int left = 0, top = 0, right = -1, bottom = -1;  // right < left: no pixel in it
    bool empty() const { return right < left; }
    void add(int x, int y);
};

struct ImageDifference {
    bool same_size = true;
    long differing_pixels = 0;
    double differing_share = 0.0;  // differing_pixels / pixel count
    int largest_channel_difference = 0;
    PixelBox region;  // where the differing pixels are: what a failure names
    Image diff;       // differing pixels in red over a faded copy of the first image
    bool within(const Tolerance& t) const { return same_size && differing_share <= t.pixel_share; }
};

// Pictures of different sizes are compared over the box either one covers (same_size
// stays false, so they never match): a pixel only one of them has counts as differing.
ImageDifference compare_images(const Image& expected, const Image& actual, const Tolerance& tolerance);

}  // namespace browser
