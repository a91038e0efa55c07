#pragma once
// PNG files in and out (stb_image_write / stb_image).

#include <cstdint>
#include <filesystem>
#include <span>
#include <stdexcept>

#include "image.h"

namespace browser {

struct FileError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// A place the reader named that a run may not write to (an --out folder that is not a
// run's, a --dump that is a FIFO): a refusal, found before the run starts (exit status 2).
struct OutputRefused : FileError {
    using FileError::FileError;
};

// Writes to a temporary name beside `path` and renames it into place, so a reader never
// sees half a file. Throws FileError with a one-line message when it cannot.
void write_png(const std::filesystem::path& path, const Image& image);

// The largest picture read: twice the largest page a run saves (browser.h's
// kMaxDevicePixels), so that contact sheets fit, 128 MiB unpacked; and its file.
inline constexpr double kMostPngPixels = 2.0 * 4096 * 4096;
inline constexpr std::uintmax_t kLargestPngFile = 64u << 20;

// Throws FileError when the file is missing, not a regular file, larger than the limits
// above or not a PNG.
Image read_png(const std::filesystem::path& path);

// The picture a PNG file's bytes hold. Throws FileError with the reason (not a PNG,
// damaged, larger than the limits above).
Image decode_png(std::span<const unsigned char> bytes);

}  // namespace browser
