#pragma once
// PNG files in and out (stb_image_write / stb_image).

#include <filesystem>
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

// Throws FileError when the file is missing or not a PNG.
Image read_png(const std::filesystem::path& path);

}  // namespace browser
