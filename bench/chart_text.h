#pragma once
// Text on a chart: the browser's one font (draw_text) drawn as ink, measured, shrunk,
// turned and laid on the picture, and broken into lines that fit.

#include <string>
#include <string_view>
#include <vector>

#include "image.h"

namespace bench::chart {

using browser::Color;
using browser::Image;

// draw_text's letters: capitals 14 px tall from the line's top, descenders down to 18 px.
constexpr int kCapHeight = 14;
constexpr int kInkHeight = 18;
constexpr int kLineStep = 20;

// A line of text as ink: black letters on white, exactly as wide as the letters reach.
Image ink_of(std::string_view text);
int text_width(std::string_view text);
// The font has a single size; halving its ink gives letters 7 px tall, with grey edges
// where a letter's stroke fell on half a pixel.
Image small_ink_of(std::string_view text);
// The ink turned a quarter turn anticlockwise, so the line reads from bottom to top.
Image turned_up(const Image& ink);

// Lays the ink on the picture with its top-left corner at (x, y): the darker an ink pixel,
// the more `color` covers the pixel beneath, as an anti-aliased stroke would.
void stamp(Image& picture, const Image& ink, int x, int y, Color color);

// The text in lines at most max_width pixels wide, broken at spaces where it can be,
// inside a word too long for a line of its own where it cannot.
std::vector<std::string> wrapped(std::string_view text, int max_width);

// A pixel position as a whole pixel, kept well inside int even if the layout went wild.
int whole(double pixel);

}  // namespace bench::chart
