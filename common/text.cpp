#include "text.h"

#include <cstddef>
#include <cstring>
#include <vector>

#include <stb_easy_font.h>

namespace browser {

namespace {

constexpr float kLetterSpacing = -1.0f;  // font units: tighter than the default, still clear;
                                         // a panel line then holds about 38 letters

}  // namespace

std::string font_text(std::string_view line) {
    std::string text;
    for (char c : line) {
        if (c == '\t') text += "    ";
        else if (c >= ' ' && c <= '~') text += c;
        else if (c != '\r') text += '?';
    }
    return text;
}

int text_width(std::string_view line) {
    std::string text = font_text(line);  // a copy: the font's functions take a mutable char*
    stb_easy_font_spacing(kLetterSpacing);
    return stb_easy_font_width(text.data()) * kTextScale;
}

// The font hands back quads (four corners each, x y z floats then 4 colour bytes);
// with kTextScale whole, every quad covers whole pixels, so each is a plain box
// fill.
void draw_text(Image& picture, std::string_view line, int x, int y, Color color, int scale) {
    std::string text = font_text(line);  // also a mutable copy, which the font's functions take
    constexpr std::size_t kVertexBytes = 16, kQuadBytes = 4 * kVertexBytes;
    constexpr std::size_t kMostQuadsPerLetter = 16;
    std::vector<char> quads((text.size() + 1) * kMostQuadsPerLetter * kQuadBytes);
    stb_easy_font_spacing(kLetterSpacing);
    const int count =
        stb_easy_font_print(0.0f, 0.0f, text.data(), nullptr, quads.data(), static_cast<int>(quads.size()));
    for (int q = 0; q < count; ++q) {
        float top_left[2], bottom_right[2];  // corners 0 and 2 of the quad
        const char* quad = quads.data() + static_cast<std::size_t>(q) * kQuadBytes;
        std::memcpy(top_left, quad, sizeof top_left);
        std::memcpy(bottom_right, quad + 2 * kVertexBytes, sizeof bottom_right);
        const int units = kTextScale * scale;  // device pixels a font unit
        const int x0 = x + static_cast<int>(top_left[0] * units);
        const int y0 = y + static_cast<int>(top_left[1] * units);
        const int x1 = x + static_cast<int>(bottom_right[0] * units);
        const int y1 = y + static_cast<int>(bottom_right[1] * units);
        for (int j = y0; j < y1; ++j) {
            for (int i = x0; i < x1; ++i) picture.set(i, j, color);
        }
    }
}

}  // namespace browser
