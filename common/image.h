#pragma once
// An RGBA picture in memory: what the browser shows on screen and what a PNG file
// stores. Row-major, top row first, 4 bytes per pixel (red, green, blue, alpha).

#include <cstddef>
#include <cstdint>
#include <vector>

namespace browser {

struct Color {
    std::uint8_t r = 0, g = 0, b = 0, a = 255;
    friend bool operator==(const Color&, const Color&) = default;
};

// The named colours the book's code uses with strokeStyle.
namespace colors {
inline constexpr Color kBlack{0, 0, 0, 255};
inline constexpr Color kWhite{255, 255, 255, 255};
inline constexpr Color kBlue{0, 0, 255, 255};
inline constexpr Color kRed{255, 0, 0, 255};
inline constexpr Color kGreen{0, 128, 0, 255};     // CSS 'green'
inline constexpr Color kOrange{255, 165, 0, 255};  // CSS 'orange'
inline constexpr Color kGray{128, 128, 128, 255};
}  // namespace colors

struct Image {
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> rgba;  // width * height * 4 bytes

    Image() = default;
    Image(int w, int h, Color fill = colors::kWhite);

    // Outside the picture, reads give transparent black (as getImageData does beyond a
    // canvas's edge) and writes are dropped, so callers need not clip first. Defined
    // here, inline, because drawing calls them for every pixel it touches.
    Color at(int x, int y) const {
        if (!contains(x, y)) return {0, 0, 0, 0};
        const std::uint8_t* p = &rgba[offset(x, y)];
        return {p[0], p[1], p[2], p[3]};
    }
    void set(int x, int y, Color c) {
        if (!contains(x, y)) return;
        std::uint8_t* p = &rgba[offset(x, y)];
        p[0] = c.r;
        p[1] = c.g;
        p[2] = c.b;
        p[3] = c.a;
    }
    bool contains(int x, int y) const { return x >= 0 && y >= 0 && x < width && y < height; }
    // Copies `source` with its top-left corner at (x, y); parts outside are cut off.
    void paste(const Image& source, int x, int y);

private:
    // Byte index of pixel (x, y): rows one after another, 4 bytes a pixel.
    std::size_t offset(int x, int y) const {
        return (static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x)) * 4;
    }
};

}  // namespace browser
