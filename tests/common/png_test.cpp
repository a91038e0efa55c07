// PNG files: what is written reads back pixel for pixel, and failures are one clear
// FileError that names the file, with nothing half-written left behind.

#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

#include "png_io.h"
#include "scratch_folder.h"

namespace fs = std::filesystem;
using browser::Color;
using browser::FileError;
using browser::Image;

namespace {

using test::ScratchFolder;

// Every pixel different, every channel value used, alpha included.
Image test_pattern(int width, int height) {
    Image image(width, height);
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            image.set(x, y,
                      Color{static_cast<std::uint8_t>(x * 7 + y), static_cast<std::uint8_t>(y * 13),
                            static_cast<std::uint8_t>(x ^ y), static_cast<std::uint8_t>(255 - x)});
        }
    }
    return image;
}

}  // namespace

TEST_CASE("png: a written picture reads back identical, and no temporary file stays") {
    ScratchFolder folder("roundtrip");
    const fs::path file = folder.path / "picture.png";
    const Image original = test_pattern(37, 23);
    browser::write_png(file, original);
    CHECK(folder.files() == std::vector<std::string>{"picture.png"});

    const Image back = browser::read_png(file);
    CHECK(back.width == 37);
    CHECK(back.height == 23);
    CHECK(back.rgba == original.rgba);

    // Writing again replaces the file.
    const Image white(5, 4);
    browser::write_png(file, white);
    CHECK(browser::read_png(file).rgba == white.rgba);
    CHECK(folder.files() == std::vector<std::string>{"picture.png"});
}

TEST_CASE("png: writing into a missing folder throws a FileError naming the file") {
    ScratchFolder folder("missing");
    const fs::path file = folder.path / "no_such_folder" / "picture.png";
    try {
        browser::write_png(file, Image(4, 4));
        FAIL("write_png did not throw");
    } catch (const FileError& error) {
        const std::string message = error.what();
        CHECK(message.find(file.string()) != std::string::npos);
        CHECK(message.find("does not exist") != std::string::npos);
        CHECK(message.find('\n') == std::string::npos);
    }
    CHECK(folder.files().empty());  // nothing written anywhere near
}

TEST_CASE("png: reading a missing, foreign or damaged file throws a FileError") {
    ScratchFolder folder("bad");
    CHECK_THROWS_AS(browser::read_png(folder.path / "absent.png"), FileError);
    CHECK_THROWS_AS(browser::read_png(folder.path), FileError);  // a folder

    const fs::path text = folder.path / "text.png";
    std::ofstream(text) << "not a picture at all\n";
    CHECK_THROWS_AS(browser::read_png(text), FileError);

    // The first 40 bytes of a real PNG: the right signature, but the data cut short.
    const fs::path good = folder.path / "good.png";
    browser::write_png(good, test_pattern(16, 16));
    std::string bytes(40, '\0');
    std::ifstream(good, std::ios::binary).read(bytes.data(), 40);
    const fs::path cut = folder.path / "cut.png";
    std::ofstream(cut, std::ios::binary) << bytes;
    CHECK_THROWS_WITH(browser::read_png(cut), Catch::Contains(cut.string()));
}
