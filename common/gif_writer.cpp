#include "gif_writer.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "png_io.h"  // FileError

#if BROWSER_HAS_GIF
#include <fcntl.h>
#include <gif_lib.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <system_error>
#include <unordered_map>
#include <utility>
#include <vector>
#endif

namespace browser {

int gif_delay_centiseconds(double frame_ms, int frames_per_picture) {
    constexpr double kMostCentiseconds = 65535.0;  // the GIF's delay field has 16 bits
    const double centiseconds = std::round(frame_ms * frames_per_picture / 10.0);
    if (!(centiseconds >= 1.0)) return 1;  // also catches NaN
    return static_cast<int>(std::min(centiseconds, kMostCentiseconds));
}

#if BROWSER_HAS_GIF

namespace {

constexpr int kMostGifSide = 65535;  // a GIF stores its width and height in 16 bits
constexpr int kPaletteSize = 256;    // the largest colour table a GIF can have

// The colours the page draws with. Anti-aliasing blends each with the white under it,
// so a ramp from white to each colour covers nearly every pixel exactly or within a
// step. kRampSteps shades a ramp: 1 + 6 * 42 = 253 entries, just inside the table.
constexpr std::array<Color, 6> kInks{colors::kBlack, colors::kBlue,   colors::kRed,
                                     colors::kGreen, colors::kOrange, colors::kGray};
constexpr int kRampSteps = 42;

std::uint8_t between(std::uint8_t from, std::uint8_t to, int step) {
    return static_cast<std::uint8_t>(std::lround(from + (to - from) * step / double(kRampSteps)));
}

// White first (index 0, the background), then each ramp from nearly white to the ink.
std::vector<Color> make_palette() {
    std::vector<Color> palette{colors::kWhite};
    for (const Color ink : kInks) {
        for (int step = 1; step <= kRampSteps; ++step) {
            palette.push_back({between(255, ink.r, step), between(255, ink.g, step), between(255, ink.b, step), 255});
        }
    }
    return palette;
}

// Maps colours to their nearest palette entry. A page has few distinct colours and long
// runs of one colour, so the last answer and a table of earlier ones make the search
// over the palette rare.
class Quantizer {
public:
    Quantizer() : palette_(make_palette()) {}

    const std::vector<Color>& palette() const { return palette_; }

    std::uint8_t index_of(Color c) {
        const std::uint32_t key =
            (std::uint32_t{c.r} << 24) | (std::uint32_t{c.g} << 16) | (std::uint32_t{c.b} << 8) | c.a;
        if (has_last_ && key == last_key_) return last_index_;
        auto [slot, added] = known_.try_emplace(key, std::uint8_t{0});
        if (added) slot->second = nearest(on_white(c));
        has_last_ = true;
        last_key_ = key;
        last_index_ = slot->second;
        return last_index_;
    }

private:
    // A GIF has no partial transparency; the page is opaque anyway, but a see-through
    // pixel would show on white paper.
    static Color on_white(Color c) {
        const auto mix = [&](std::uint8_t channel) {
            return static_cast<std::uint8_t>((channel * c.a + 255 * (255 - c.a) + 127) / 255);
        };
        return {mix(c.r), mix(c.g), mix(c.b), 255};
    }

    // Smallest squared distance in RGB; on a tie the earlier entry wins, so the
    // answer never depends on anything but the colour.
    std::uint8_t nearest(Color c) const {
        std::size_t best = 0;
        int best_distance = -1;
        for (std::size_t i = 0; i < palette_.size(); ++i) {
            const int dr = c.r - palette_[i].r, dg = c.g - palette_[i].g, db = c.b - palette_[i].b;
            const int distance = dr * dr + dg * dg + db * db;
            if (best_distance < 0 || distance < best_distance) {
                best = i;
                best_distance = distance;
            }
        }
        return static_cast<std::uint8_t>(best);
    }

    std::vector<Color> palette_;
    std::unordered_map<std::uint32_t, std::uint8_t> known_;
    bool has_last_ = false;
    std::uint32_t last_key_ = 0;
    std::uint8_t last_index_ = 0;
};

// The part of a picture that changed: columns [left, right), rows [top, bottom).
struct Box {
    int left = 0, top = 0, right = 0, bottom = 0;
};

// The smallest box holding every pixel where `now` differs from `before` (both
// width x height palette indices); a single pixel when nothing changed, because every
// GIF frame needs an image to carry its delay.
Box changed_part(const std::vector<GifPixelType>& before, const std::vector<GifPixelType>& now, int width, int height) {
    Box changed{width, height, 0, 0};
    for (int y = 0; y < height; ++y) {
        const auto row_before = before.begin() + static_cast<std::ptrdiff_t>(y) * width;
        const auto row_now = now.begin() + static_cast<std::ptrdiff_t>(y) * width;
        const auto first = std::mismatch(row_now, row_now + width, row_before).first;
        if (first == row_now + width) continue;
        // Searching backwards from the row's end finds the last difference.
        const auto reversed =
            std::mismatch(std::make_reverse_iterator(row_now + width), std::make_reverse_iterator(first),
                          std::make_reverse_iterator(row_before + width))
                .first;
        changed.left = std::min(changed.left, static_cast<int>(first - row_now));
        changed.right = std::max(changed.right, static_cast<int>(reversed.base() - row_now));
        changed.top = std::min(changed.top, y);
        changed.bottom = y + 1;
    }
    if (changed.bottom == 0) return {0, 0, 1, 1};
    return changed;
}

// giflib's handle; closing it also frees it.
struct CloseGif {
    void operator()(GifFileType* gif) const {
        int ignored = 0;
        EGifCloseFile(gif, &ignored);
    }
};

std::string gif_error(const std::filesystem::path& path, int code) {
    const char* text = GifErrorString(code);
    std::string message = path.filename().string();
    message += ": ";
    message += text != nullptr ? text : "GIF error";
    return message;
}

}  // namespace

struct GifWriter::Encoder {
    Encoder(const std::filesystem::path& file, int w, int h, int delay)
        : path(file), width(w), height(h), delay_cs(delay) {
        // Opened here rather than by EGifOpenFileName, which would make the file readable
        // by its owner only; like the PNGs, it gets the usual permissions (0666 less umask).
        const int descriptor = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0666);
        if (descriptor < 0) {
            const int reason = errno;  // before anything else can change it
            throw FileError(path.filename().string() + ": " + std::generic_category().message(reason));
        }
        int error = 0;
        gif.reset(EGifOpenFileHandle(descriptor, &error));
        if (!gif) {
            ::close(descriptor);  // giflib takes the file over only when it succeeds
            throw FileError(gif_error(path, error));
        }
        // Graphics control blocks (the delays) need the 1989 version of the format.
        EGifSetGifVersion(gif.get(), true);

        ColorMapObject* colors = GifMakeMapObject(kPaletteSize, nullptr);
        if (colors == nullptr) throw FileError(gif_error(path, E_GIF_ERR_NOT_ENOUGH_MEM));
        const std::vector<Color>& palette = quantizer.palette();
        for (int i = 0; i < kPaletteSize; ++i) {
            // Entries past the palette repeat white; nearest() never picks them.
            const std::size_t entry = static_cast<std::size_t>(i);
            const Color c = entry < palette.size() ? palette[entry] : colors::kWhite;
            colors->Colors[i] = {c.r, c.g, c.b};
        }
        const int written = EGifPutScreenDesc(gif.get(), width, height, 8, 0, colors);  // giflib keeps a copy
        GifFreeMapObject(colors);
        check(written);
        loop_forever();
    }
    void check(int result) const {
        if (result == GIF_ERROR) throw FileError(gif_error(path, gif->Error));
    }

    // The NETSCAPE2.0 application block, which every viewer reads as "repeat": its
    // sub-block 1 holds the number of repeats, 0 meaning forever.
    void loop_forever() {
        static constexpr char kApplication[] = "NETSCAPE2.0";  // 8 letters of name, 3 of version
        static constexpr GifByteType kRepeatForever[] = {1, 0, 0};
        check(EGifPutExtensionLeader(gif.get(), APPLICATION_EXT_FUNC_CODE));
        check(EGifPutExtensionBlock(gif.get(), sizeof kApplication - 1, kApplication));
        check(EGifPutExtensionBlock(gif.get(), sizeof kRepeatForever, kRepeatForever));
        check(EGifPutExtensionTrailer(gif.get()));
    }

    void add(const Image& picture, bool first) {
        if (picture.width != width || picture.height != height) {
            throw std::invalid_argument("GifWriter: every picture must have the size of the first");
        }
        current.resize(static_cast<std::size_t>(width) * static_cast<std::size_t>(height));
        for (std::size_t i = 0; i < current.size(); ++i) {
            const std::uint8_t* p = &picture.rgba[4 * i];
            current[i] = quantizer.index_of({p[0], p[1], p[2], p[3]});
        }
        const Box part = first ? Box{0, 0, width, height} : changed_part(previous, current, width, height);

        // "Do not dispose": the next frame is drawn over this one, so the pixels outside
        // its box keep showing this frame.
        GraphicsControlBlock timing{};
        timing.DisposalMode = DISPOSE_DO_NOT;
        timing.UserInputFlag = false;
        timing.DelayTime = delay_cs;
        timing.TransparentColor = NO_TRANSPARENT_COLOR;
        GifByteType extension[4];
        const std::size_t length = EGifGCBToExtension(&timing, extension);
        check(EGifPutExtension(gif.get(), GRAPHICS_EXT_FUNC_CODE, static_cast<int>(length), extension));

        const int part_width = part.right - part.left;
        check(EGifPutImageDesc(gif.get(), part.left, part.top, part_width, part.bottom - part.top, false, nullptr));
        for (int y = part.top; y < part.bottom; ++y) {
            GifPixelType* row = &current[static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
                                         static_cast<std::size_t>(part.left)];
            check(EGifPutLine(gif.get(), row, part_width));
        }
        std::swap(previous, current);
    }

    void close() {
        int error = 0;
        const int result = EGifCloseFile(gif.release(), &error);  // frees the handle even when it fails
        if (result == GIF_ERROR) throw FileError(gif_error(path, error));
    }

    std::filesystem::path path;
    int width, height, delay_cs;
    std::unique_ptr<GifFileType, CloseGif> gif;  // empty once closed
    Quantizer quantizer;
    std::vector<GifPixelType> previous, current;  // palette indices, one byte a pixel
};

GifWriter::GifWriter(const std::filesystem::path& path, int width, int height, int delay_cs) {
    if (width < 1 || height < 1 || width > kMostGifSide || height > kMostGifSide) {
        throw FileError(path.filename().string() + ": a GIF must be 1 to 65535 pixels wide and high");
    }
    encoder_ = std::make_unique<Encoder>(path, width, height, delay_cs);
}

GifWriter::~GifWriter() = default;

void GifWriter::add(const Image& picture) {
    if (!encoder_ || !encoder_->gif) throw std::logic_error("GifWriter: add() after close()");
    encoder_->add(picture, pictures_ == 0);
    ++pictures_;
}

void GifWriter::close() {
    if (!encoder_ || !encoder_->gif) return;
    encoder_->close();
}

#else  // built without giflib: only the refusal remains

struct GifWriter::Encoder {};

GifWriter::GifWriter(const std::filesystem::path&, int, int, int) { throw FileError(std::string(kNoGifSupport)); }
GifWriter::~GifWriter() = default;
void GifWriter::add(const Image&) {}
void GifWriter::close() {}

#endif

}  // namespace browser
