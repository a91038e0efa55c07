// Fuzz target: what compare_png reads, a PNG file's bytes (common/png_io.cpp's
// decode_png, stb_image underneath), and the comparison of what it decodes.
//
// Properties, besides "no crash, no sanitizer report, no exception but FileError":
//  - a refusal is one line;
//  - an accepted picture is within the limits of png_io.h (kMostPngPixels) and holds
//    exactly width x height RGBA pixels;
//  - a picture compared with itself has no differing pixel.

#include <cstddef>
#include <cstdint>
#include <span>

#include "fuzz_check.h"
#include "image_compare.h"
#include "png_io.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    browser::Image picture;
    try {
        picture = browser::decode_png(std::span<const unsigned char>(data, size));
    } catch (const browser::FileError& refusal) {
        fuzz::require(fuzz::one_line(refusal.what()), "a refusal is one line:", refusal.what());
        return 0;
    }
    fuzz::require(picture.width > 0 && picture.height > 0, "an accepted picture has pixels");
    fuzz::require(static_cast<double>(picture.width) * picture.height <= browser::kMostPngPixels,
                  "an accepted picture is within kMostPngPixels");
    fuzz::require(picture.rgba.size() == static_cast<std::size_t>(picture.width) * picture.height * 4,
                  "an accepted picture holds width x height RGBA pixels");
    const browser::Tolerance exact{.channel = 0, .pixel_share = 0.0};
    const browser::ImageDifference self = browser::compare_images(picture, picture, exact);
    fuzz::require(self.differing_pixels == 0 && self.within(exact), "a picture matches itself");
    return 0;
}
