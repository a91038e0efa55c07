// xwd_to_png IN.xwd OUT.png [HEIGHT]: turns the window dump `xwd` writes into a PNG,
// keeping only the top HEIGHT rows when given (a live window's page, without its
// status line). Reads the dumps of windows with a TrueColor or DirectColor visual of
// 24 or 32 bits a pixel, as Xvfb's default screen gives them; anything else is refused
// in one line.
//
// The format (X11's XWDFile.h): a header of 25 big-endian 32-bit fields, the window's
// name, a colour map of 12-byte entries (pixel, then 16-bit red, green and blue), then
// the pixels row by row, bytes_per_line bytes a row, each pixel bits_per_pixel bits in
// the byte order the header names. The red, green and blue masks cut a pixel into three
// fields; in a TrueColor visual a field is the intensity itself, in a DirectColor one it
// indexes that channel of the colour map.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <fstream>
#include <iostream>
#include <iterator>
#include <stdexcept>
#include <string>
#include <vector>

#include "png_io.h"

namespace {

enum Field {
    kHeaderSize, kFileVersion, kPixmapFormat, kPixmapDepth, kWidth, kHeight, kXOffset, kByteOrder,
    kBitmapUnit, kBitmapBitOrder, kBitmapPad, kBitsPerPixel, kBytesPerLine, kVisualClass,
    kRedMask, kGreenMask, kBlueMask, kBitsPerRgb, kColormapEntries, kColourCount, kFieldCount = 25
};
constexpr std::uint32_t kZPixmap = 2, kTrueColor = 4, kDirectColor = 5, kLsbFirst = 0;
constexpr std::size_t kColourEntryBytes = 12;

std::uint32_t big_endian(const std::vector<unsigned char>& bytes, std::size_t at) {
    if (at + 4 > bytes.size()) throw std::runtime_error("the file ends inside its header");
    return std::uint32_t{bytes[at]} << 24 | std::uint32_t{bytes[at + 1]} << 16 | std::uint32_t{bytes[at + 2]} << 8 |
           std::uint32_t{bytes[at + 3]};
}

std::uint16_t big_endian_16(const std::vector<unsigned char>& bytes, std::size_t at) {
    return static_cast<std::uint16_t>(bytes[at] << 8 | bytes[at + 1]);
}

// One of a pixel's three fields (its mask 0xff0000 or the like), turned into 0..255.
class Channel {
public:
    explicit Channel(std::uint32_t mask) : mask_(mask) {
        if (mask == 0) throw std::runtime_error("a colour mask is empty");
        while (((mask >> shift_) & 1u) == 0) ++shift_;
        top_ = mask >> shift_;
    }
    std::uint32_t field(std::uint32_t pixel) const { return (pixel & mask_) >> shift_; }
    // TrueColor: the field is the intensity, 0 to top.
    std::uint8_t intensity(std::uint32_t pixel) const { return static_cast<std::uint8_t>(field(pixel) * 255u / top_); }

private:
    std::uint32_t mask_;
    int shift_ = 0;
    std::uint32_t top_ = 1;
};

browser::Image read_xwd(const std::string& file, int keep_rows) {
    std::ifstream in(file, std::ios::binary);
    if (!in) throw std::runtime_error("cannot read it");
    const std::vector<unsigned char> bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    std::uint32_t header[kFieldCount];
    for (int i = 0; i < kFieldCount; ++i) header[i] = big_endian(bytes, 4 * static_cast<std::size_t>(i));
    const std::uint32_t bits = header[kBitsPerPixel];
    const bool colour_visual = header[kVisualClass] == kTrueColor || header[kVisualClass] == kDirectColor;
    if (header[kFileVersion] != 7 || header[kPixmapFormat] != kZPixmap || !colour_visual || (bits != 24 && bits != 32)) {
        throw std::runtime_error("not a TrueColor or DirectColor ZPixmap dump of 24 or 32 bits a pixel");
    }
    const int width = static_cast<int>(header[kWidth]);
    const int height = static_cast<int>(header[kHeight]);
    const int rows = keep_rows > 0 ? keep_rows : height;
    if (width <= 0 || rows <= 0 || rows > height) throw std::runtime_error("no such rows in the picture");
    const std::size_t pixels_at = header[kHeaderSize] + header[kColourCount] * kColourEntryBytes;
    const std::size_t row_bytes = header[kBytesPerLine];
    if (pixels_at + row_bytes * static_cast<std::size_t>(height) > bytes.size()) {
        throw std::runtime_error("the file ends inside its pixels");
    }
    const std::size_t pixel_bytes = bits / 8;
    const Channel red(header[kRedMask]), green(header[kGreenMask]), blue(header[kBlueMask]);

    // DirectColor: each field indexes its channel of the colour map.
    std::vector<std::uint8_t> red_map, green_map, blue_map;
    const bool direct = header[kVisualClass] == kDirectColor;
    if (direct) {
        const std::size_t entries = std::min<std::size_t>(header[kColourCount], 256);
        red_map.assign(256, 0);
        green_map.assign(256, 0);
        blue_map.assign(256, 0);
        for (std::size_t e = 0; e < entries; ++e) {
            const std::size_t at = header[kHeaderSize] + e * kColourEntryBytes;
            const std::uint32_t pixel = big_endian(bytes, at);
            red_map[red.field(pixel) & 255u] = static_cast<std::uint8_t>(big_endian_16(bytes, at + 4) >> 8);
            green_map[green.field(pixel) & 255u] = static_cast<std::uint8_t>(big_endian_16(bytes, at + 6) >> 8);
            blue_map[blue.field(pixel) & 255u] = static_cast<std::uint8_t>(big_endian_16(bytes, at + 8) >> 8);
        }
    }
    browser::Image picture(width, rows);
    for (int y = 0; y < rows; ++y) {
        for (int x = 0; x < width; ++x) {
            const unsigned char* p = &bytes[pixels_at + static_cast<std::size_t>(y) * row_bytes +
                                            static_cast<std::size_t>(x) * pixel_bytes];
            std::uint32_t pixel = 0;
            for (std::size_t b = 0; b < pixel_bytes; ++b) {
                const std::size_t shift = header[kByteOrder] == kLsbFirst ? b : pixel_bytes - 1 - b;
                pixel |= std::uint32_t{p[b]} << (8 * shift);
            }
            if (direct) {
                picture.set(x, y, {red_map[red.field(pixel) & 255u], green_map[green.field(pixel) & 255u],
                                   blue_map[blue.field(pixel) & 255u], 255});
            } else {
                picture.set(x, y, {red.intensity(pixel), green.intensity(pixel), blue.intensity(pixel), 255});
            }
        }
    }
    return picture;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 3 && argc != 4) {
        std::cerr << "usage: xwd_to_png IN.xwd OUT.png [HEIGHT]\n";
        return 2;
    }
    try {
        const int keep_rows = argc == 4 ? std::stoi(argv[3]) : 0;
        browser::write_png(argv[2], read_xwd(argv[1], keep_rows));
    } catch (const std::exception& error) {
        std::cerr << "xwd_to_png: " << argv[1] << ": " << error.what() << '\n';
        return 2;
    }
    return 0;
}
