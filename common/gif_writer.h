#pragma once
// Animated GIF files of the page: what a reader can put in a web page or a chat to show
// a run moving. giflib is an optional dependency (Debian: libgif-dev); a build without
// it still has this header, but gif_supported() (build_features.h) says no and a
// GifWriter cannot be made.
//
// The page uses a handful of colours (white paper, black text, a gray frame, blue, red,
// green and orange strokes) and their anti-aliased blends with white, so one fixed
// palette of ramps from white to each of them serves every frame; each pixel takes the
// nearest palette entry. Frames are encoded as they come, so a long run never holds
// more than two frames of palette indices in memory.

#include <filesystem>
#include <memory>

#include "build_features.h"  // gif_supported, kNoGifSupport
#include "image.h"

namespace browser {

// How long a GIF frame that stands for `frames_per_picture` animation frames of
// frame_ms each is shown: rounded to whole centiseconds (the GIF's unit), at least 1 cs
// and at most 65535 cs (the largest delay a GIF can store).
int gif_delay_centiseconds(double frame_ms, int frames_per_picture);

// Writes one GIF that loops forever, picture by picture. Every picture must have the
// size given at construction and is shown for delay_cs centiseconds. After the first,
// a picture is stored as the smallest box that differs from the one before, so
// a still background costs almost nothing. Errors throw FileError with a one-line
// message; a writer destroyed without close() leaves an unfinished file behind (the
// browser writes into a staging folder that it discards on failure).
class GifWriter {
public:
    GifWriter(const std::filesystem::path& path, int width, int height, int delay_cs);
    ~GifWriter();
    GifWriter(const GifWriter&) = delete;
    GifWriter& operator=(const GifWriter&) = delete;

    void add(const Image& picture);
    void close();  // writes the GIF's end; the file is complete only after this
    int pictures() const { return pictures_; }

private:
    struct Encoder;  // giflib's state and the previous picture's palette indices
    std::unique_ptr<Encoder> encoder_;
    int pictures_ = 0;
};

}  // namespace browser
