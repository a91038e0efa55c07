// animation.gif: written frame by frame as the page moves, read back with giflib's own
// decoder. In a build without giflib the same file checks that --gif is refused.
#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "captured_output.h"
#include "browser.h"
#include "command_line.h"
#include "gif_writer.h"
#include "png_io.h"
#include "scratch_folder.h"

#if BROWSER_HAS_GIF
#include <gif_lib.h>

#include <cstring>
#include <limits>
#endif

namespace fs = std::filesystem;
using browser::Color;
using browser::Image;
using test::ScratchFolder;

namespace {

// A page that changes every frame: a growing square on the canvas, a count in the panel.
class GrowingSquare : public browser::PageScripts {
public:
    explicit GrowingSquare(browser::Document& document) : document_(document) {}
    void onKeyDown(browser::Key) override {}
    void onAnimationFrame() override {
        ++frames_;
        document_.ui_echo = "frame " + std::to_string(frames_);
        document_.canvas.clear();
        document_.canvas.setStrokeStyle(browser::colors::kBlue);
        document_.canvas.strokeRect(3.5, 3.5, frames_, frames_);  // on pixel centres: crisp lines
    }

private:
    browser::Document& document_;
    int frames_ = 0;
};

browser::Options gif_options(const fs::path& out, int frames, int gif_every) {
    browser::Options options;
    options.out_dir = out;
    options.frames = frames;
    options.gif = true;
    options.gif_every = gif_every;
    options.frame_ms = 10.0;
    return options;
}

struct RunResult {
    int status = 0;
    std::string out, err;
    Image last_page;
};

using test::CapturedOutput;

// Runs the growing square on a 40 x 30 canvas (a 420 x 30 page).
RunResult run_square(const browser::Options& options) {
    browser::Window window(options.frame_ms, browser::Document{browser::Canvas(40, 30), ""});
    GrowingSquare scripts(window.document);
    RunResult result;
    {
        CapturedOutput captured;
        result.status = browser::run(scripts, window, options);
        result.out = captured.out();
        result.err = captured.err();
    }
    result.last_page = browser::render_page(window.document);
    return result;
}

}  // namespace

TEST_CASE("gif: a GIF frame lasts N animation frames, in whole centiseconds") {
    CHECK(browser::gif_delay_centiseconds(1000.0 / 60.0, 2) == 3);  // 33.3 ms
    CHECK(browser::gif_delay_centiseconds(1000.0 / 60.0, 3) == 5);  // 50 ms
    CHECK(browser::gif_delay_centiseconds(1000.0 / 60.0, 1) == 2);  // 16.7 ms
    CHECK(browser::gif_delay_centiseconds(10.0, 1) == 1);
    CHECK(browser::gif_delay_centiseconds(14.0, 1) == 1);                   // 1.4 cs rounds down
    CHECK(browser::gif_delay_centiseconds(1.0, 1) == 1);                    // never 0: viewers treat 0 oddly
    CHECK(browser::gif_delay_centiseconds(10'000.0, 10'000'000) == 65535);  // the format's limit
}

#if BROWSER_HAS_GIF

namespace {

// A GIF as a viewer shows it: each frame drawn over the one before (our frames all say
// "do not dispose"), as RGBA pictures, with each frame's delay.
struct DecodedGif {
    int width = 0, height = 0;
    std::vector<Image> frames;
    std::vector<int> delays_cs;
    std::vector<Color> palette;       // the global colour table
    std::vector<GifImageDesc> parts;  // where each frame's image lies
    bool loops_forever = false;
};

DecodedGif decode(const fs::path& path) {
    int error = 0;
    GifFileType* gif = DGifOpenFileName(path.c_str(), &error);
    REQUIRE(gif != nullptr);
    REQUIRE(DGifSlurp(gif) == GIF_OK);
    DecodedGif decoded;
    decoded.width = gif->SWidth;
    decoded.height = gif->SHeight;
    REQUIRE(gif->SColorMap != nullptr);
    for (int i = 0; i < gif->SColorMap->ColorCount; ++i) {
        const GifColorType c = gif->SColorMap->Colors[i];
        decoded.palette.push_back({c.Red, c.Green, c.Blue, 255});
    }
    Image screen(decoded.width, decoded.height);
    for (int f = 0; f < gif->ImageCount; ++f) {
        const SavedImage& image = gif->SavedImages[f];
        const GifImageDesc& part = image.ImageDesc;
        const ColorMapObject* colors = part.ColorMap != nullptr ? part.ColorMap : gif->SColorMap;
        for (int y = 0; y < part.Height; ++y) {
            for (int x = 0; x < part.Width; ++x) {
                const GifColorType c = colors->Colors[image.RasterBits[y * part.Width + x]];
                screen.set(part.Left + x, part.Top + y, {c.Red, c.Green, c.Blue, 255});
            }
        }
        decoded.frames.push_back(screen);
        decoded.parts.push_back(part);
        GraphicsControlBlock timing{};
        REQUIRE(DGifSavedExtensionToGCB(gif, f, &timing) == GIF_OK);
        decoded.delays_cs.push_back(timing.DelayTime);
        for (int b = 0; b + 1 < image.ExtensionBlockCount; ++b) {
            const ExtensionBlock& name = image.ExtensionBlocks[b];
            const ExtensionBlock& data = image.ExtensionBlocks[b + 1];
            if (name.Function == APPLICATION_EXT_FUNC_CODE && name.ByteCount == 11 &&
                std::memcmp(name.Bytes, "NETSCAPE2.0", 11) == 0 && data.ByteCount == 3) {
                decoded.loops_forever = data.Bytes[0] == 1 && data.Bytes[1] == 0 && data.Bytes[2] == 0;
            }
        }
    }
    DGifCloseFile(gif, &error);
    return decoded;
}

std::vector<std::string> names_in(const fs::path& folder) {
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(folder)) names.push_back(entry.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
}

int distance2(Color a, Color b) {
    const int dr = a.r - b.r, dg = a.g - b.g, db = a.b - b.b;
    return dr * dr + dg * dg + db * db;
}

// How far `c` is from the palette entry nearest to it.
int nearest_distance2(const std::vector<Color>& palette, Color c) {
    int best = std::numeric_limits<int>::max();
    for (const Color entry : palette) best = std::min(best, distance2(entry, c));
    return best;
}

}  // namespace

TEST_CASE("gif: a run writes animation.gif with ceil(frames / N) frames of the whole page") {
    ScratchFolder temp("gif_test");
    const fs::path out = temp.path / "out";
    // Frames 0, 2, 4 and 6 of 7.
    const RunResult result = run_square(gif_options(out, 7, 2));
    REQUIRE(result.status == 0);
    CHECK(result.err.empty());
    CHECK(names_in(out) == std::vector<std::string>{".manifest", "animation.gif", "final.png"});
    CHECK_THAT(result.out, Catch::Contains("animation.gif (4 frames)"));

    const DecodedGif gif = decode(out / "animation.gif");
    CHECK(gif.width == result.last_page.width);
    CHECK(gif.height == result.last_page.height);
    CHECK(gif.frames.size() == 4);
    CHECK(gif.delays_cs == std::vector<int>(4, 2));  // 2 frames of 10 ms
    CHECK(gif.loops_forever);
    // The first frame covers the page; later ones only what changed: here the square
    // and the panel's count, not the whole page.
    REQUIRE(gif.parts.size() == 4);
    CHECK(gif.parts[0].Width == gif.width);
    CHECK(gif.parts[0].Height == gif.height);
    CHECK(gif.parts[1].Width < gif.width);
}

TEST_CASE("gif: the picture of frame 6 is the page after frame 6, in palette colours") {
    ScratchFolder temp("gif_test");
    const fs::path out = temp.path / "out";
    const RunResult result = run_square(gif_options(out, 7, 2));  // the last GIF frame is the last frame
    REQUIRE(result.status == 0);
    const DecodedGif gif = decode(out / "animation.gif");
    REQUIRE(gif.frames.size() == 4);
    const Image& page = result.last_page;
    const Image& shown = gif.frames.back();
    int exact = 0;
    for (int y = 0; y < page.height; ++y) {
        for (int x = 0; x < page.width; ++x) {
            const Color wanted = page.at(x, y);
            const Color got = shown.at(x, y);
            // Nearest: no other palette entry is closer to the page's colour.
            if (distance2(got, wanted) != nearest_distance2(gif.palette, wanted)) {
                FAIL("pixel (" << x << ", " << y << ") is not the nearest palette colour");
            }
            exact += got == wanted;
        }
    }
    // White paper, black text, the gray frame and the pure blue stroke are in the
    // palette itself; only anti-aliased edges move to a neighbour.
    CHECK(exact > page.width * page.height * 9 / 10);
    CHECK(page.at(3, 3) == browser::colors::kBlue);
    CHECK(shown.at(3, 3) == browser::colors::kBlue);  // a corner of the square
    CHECK(shown.at(0, 0) == browser::colors::kGray);  // the canvas frame
    CHECK(shown.at(page.width - 1, 0) == browser::colors::kWhite);
}

TEST_CASE("gif: a known colour decodes to the palette entry nearest to it") {
    ScratchFolder temp("gif_test");
    const fs::path file = temp.path / "colours.gif";
    Image first(8, 6);
    first.set(1, 1, browser::colors::kOrange);
    first.set(2, 1, browser::colors::kGreen);
    first.set(3, 1, {255, 128, 128, 255});  // red half blended with white: on the red ramp
    first.set(4, 1, {200, 100, 50, 255});   // on no ramp at all
    first.set(5, 1, {0, 0, 255, 0});        // fully transparent: white paper shows
    Image second = first;
    second.set(6, 4, browser::colors::kRed);
    {
        browser::GifWriter writer(file, 8, 6, 7);
        writer.add(first);
        writer.add(second);
        writer.add(second);  // nothing changed: still a frame, to keep the timing
        CHECK(writer.pictures() == 3);
        writer.close();
    }
    const DecodedGif gif = decode(file);
    REQUIRE(gif.frames.size() == 3);
    CHECK(gif.delays_cs == std::vector<int>{7, 7, 7});
    CHECK(gif.palette.size() == 256);
    const Image& shown = gif.frames[0];
    CHECK(shown.at(1, 1) == browser::colors::kOrange);
    CHECK(shown.at(2, 1) == browser::colors::kGreen);
    CHECK(distance2(shown.at(3, 1), {255, 128, 128, 255}) <= 3 * 3 * 3);
    CHECK(distance2(shown.at(4, 1), {200, 100, 50, 255}) == nearest_distance2(gif.palette, {200, 100, 50, 255}));
    CHECK(shown.at(5, 1) == browser::colors::kWhite);
    // The second frame holds only the changed pixel; drawn over the first it gives the
    // second picture.
    CHECK(gif.parts[1].Left == 6);
    CHECK(gif.parts[1].Top == 4);
    CHECK(gif.parts[1].Width == 1);
    CHECK(gif.parts[1].Height == 1);
    CHECK(gif.frames[1].at(6, 4) == browser::colors::kRed);
    CHECK(gif.frames[1].at(1, 1) == browser::colors::kOrange);
    CHECK(gif.frames[2].rgba == gif.frames[1].rgba);
}

TEST_CASE("gif: misuse and write failures") {
    ScratchFolder temp("gif_test");
    SECTION("a picture of another size is a programming error") {
        browser::GifWriter writer(temp.path / "a.gif", 8, 6, 1);
        writer.add(Image(8, 6));
        CHECK_THROWS_AS(writer.add(Image(9, 6)), std::invalid_argument);
    }
    SECTION("a missing folder is a FileError naming the file") {
        try {
            browser::GifWriter writer(temp.path / "missing" / "a.gif", 8, 6, 1);
            FAIL("no error");
        } catch (const browser::FileError& error) {
            CHECK_THAT(error.what(), Catch::StartsWith("a.gif: "));
        }
    }
    SECTION("a size a GIF cannot store") {
        CHECK_THROWS_AS(browser::GifWriter(temp.path / "a.gif", 70'000, 6, 1), browser::FileError);
        CHECK_THROWS_AS(browser::GifWriter(temp.path / "b.gif", 0, 6, 1), browser::FileError);
    }
}

TEST_CASE("gif: --gif-every 1 puts every frame in, and the contact sheet comes too") {
    ScratchFolder temp("gif_test");
    const fs::path out = temp.path / "out";
    browser::Options options = gif_options(out, 3, 1);
    options.every = 2;
    const RunResult result = run_square(options);
    REQUIRE(result.status == 0);
    CHECK(names_in(out) == std::vector<std::string>{".manifest", "animation.gif", "contact_sheet.png", "final.png",
                                                    "frame_0000.png", "frame_0002.png"});
    CHECK_THAT(result.out, Catch::EndsWith(", contact_sheet.png and animation.gif (3 frames)\n"));
    CHECK(decode(out / "animation.gif").frames.size() == 3);
}

#else  // a build without giflib

TEST_CASE("gif: without giflib, --gif stops the run with one line and writes nothing") {
    ScratchFolder temp("gif_test");
    CHECK_FALSE(browser::gif_supported());
    const RunResult result = run_square(gif_options(temp.path / "out", 3, 1));
    CHECK(result.status == 2);
    CHECK(result.err == std::string(browser::kNoGifSupport) + "\n");
    CHECK(result.out.empty());
    CHECK(temp.files().empty());
    CHECK_THROWS_AS(browser::GifWriter(temp.path / "a.gif", 8, 6, 1), browser::FileError);
}

#endif
