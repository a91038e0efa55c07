#pragma once
// The page's one font: a line of text drawn into a picture, and measured. The echo
// panel (page.h), the canvas's fillText (canvas.h), the contact sheet's labels and the
// live window's status line all write with it, so every text in every picture has the
// same letters.

#include <string>
#include <string_view>

#include "image.h"

namespace browser {

// stb_easy_font draws on a grid of font units: letters about 7 units tall. Two pixels a
// unit makes text about the size of a browser's default font, and a whole number of
// pixels a unit keeps every stroke of every letter on whole pixels. Lines 9 units apart
// (the font's own spacing is 12) let the longest echo of chapter 4, some 24 lines, fit.
inline constexpr int kTextScale = 2;

// How far apart the panel's lines are, in pixels at scale 1.
constexpr int text_line_height() { return 9 * kTextScale; }

// Writes one line of text in the page's font and size (letters about 14 pixels tall,
// times `scale`) with its top-left corner at (x, y); what falls outside `picture` is
// cut off. The font has printable ASCII only: see font_text.
void draw_text(Image& picture, std::string_view text, int x, int y, Color color, int scale = 1);

// How wide draw_text writes `line` at scale 1, in pixels.
int text_width(std::string_view line);

// `line` as the font writes it: a tab becomes four spaces, a carriage return nothing,
// any other character outside printable ASCII a '?' (it would index past the font's
// tables).
std::string font_text(std::string_view line);

}  // namespace browser
