// compare_png as a reader runs it, against hostile input (issue 28): inputs that are not
// regular files are refused at once rather than read for ever, a picture whose header
// claims more pixels than a run ever writes is refused before it is unpacked, and the
// diff pictures follow write_guard.h's rule, as every file a program here writes does.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include <sys/stat.h>
#include <sys/wait.h>

#include "image.h"
#include "png_io.h"
#include "scratch_folder.h"

namespace fs = std::filesystem;

namespace {

struct Run {
    int status = -1;
    std::string err;
};

std::string quoted(const fs::path& path) {
    std::string text = "'";
    text += path.string();
    text += "'";
    return text;
}

// compare_png with `arguments`, stopped after 20 s should it wait for ever (status 124).
Run compare(const test::ScratchFolder& folder, const std::string& arguments) {
    const fs::path err = folder.path.string() + ".err";
    const std::string line =
        "timeout 20 " + quoted(COMPARE_PNG_PROGRAM) + " " + arguments + " >/dev/null 2>" + quoted(err);
    const int raw = std::system(line.c_str());
    Run run;
    if (raw != -1 && WIFEXITED(raw)) run.status = WEXITSTATUS(raw);
    std::ifstream in(err);
    run.err.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    fs::remove(err);
    return run;
}

std::string textOf(const fs::path& file) {
    std::ifstream in(file);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

bool isOneLine(const std::string& text) { return !text.empty() && text.find('\n') == text.size() - 1; }

void checkTrouble(const test::ScratchFolder& folder, const std::string& arguments, const std::string& says) {
    const Run run = compare(folder, arguments);
    INFO(arguments << "\n" << run.err);
    CHECK(run.status == 2);
    CHECK(isOneLine(run.err));
    CHECK_THAT(run.err, Catch::Contains(says));
}

}  // namespace

TEST_CASE("compare_png: an input that is no regular file is refused at once") {
    const test::ScratchFolder folder("compare_png_inputs");
    const fs::path picture = folder.path / "a.png";
    browser::write_png(picture, browser::Image(2, 2));
    REQUIRE(::mkfifo((folder.path / "fifo").c_str(), 0600) == 0);  // no writer: reading it would wait for ever
    checkTrouble(folder, quoted(picture) + " " + quoted(folder.path / "fifo"), "it is a FIFO, not a regular file");
    checkTrouble(folder, quoted(folder.path / "fifo") + " " + quoted(picture), "it is a FIFO, not a regular file");
    checkTrouble(folder, quoted(picture) + " /dev/zero", "/dev/zero: it is a device, not a regular file");
    checkTrouble(folder, "/dev/urandom " + quoted(picture), "/dev/urandom: it is a device, not a regular file");
}

TEST_CASE("compare_png: a picture whose header claims 16000 x 16000 pixels is refused before it is unpacked") {
    const test::ScratchFolder folder("compare_png_huge");
    const fs::path picture = folder.path / "a.png";
    browser::write_png(picture, browser::Image(2, 2));
    // The seed of the fuzz target: a valid header, next to no pixel data.
    const fs::path huge = fs::path(FUZZ_SEEDS_DIR) / "png_reader" / "huge_header.png";
    checkTrouble(folder, quoted(picture) + " " + quoted(huge),
                 "it is 16000 x 16000 pixels, more than the 33554432 a picture may have");
}

TEST_CASE("compare_png: a damaged picture is refused in one line, the bytes stb quotes escaped") {
    const test::ScratchFolder folder("compare_png_damaged");
    const fs::path picture = folder.path / "a.png";
    browser::write_png(picture, browser::Image(2, 2));
    // Found by fuzz/png_reader: stb names an unknown chunk by its four raw bytes.
    const fs::path damaged = fs::path(FUZZ_SEEDS_DIR) / "png_reader" / "unknown_chunk.png";
    const Run run = compare(folder, quoted(picture) + " " + quoted(damaged));
    CHECK(run.status == 2);
    CHECK(isOneLine(run.err));
    CHECK_THAT(run.err, Catch::Contains("PNG chunk not known)"));
    CHECK(std::none_of(run.err.begin(), run.err.end(), [](char c) { return static_cast<unsigned char>(c) >= 0x80; }));
}

TEST_CASE("compare_png: --diff and --diff-dir never replace a link, a FIFO, a device, a second name or an input") {
    const test::ScratchFolder folder("compare_png_diff");
    const fs::path a = folder.path / "a.png", b = folder.path / "b.png";
    browser::write_png(a, browser::Image(2, 2));
    browser::Image other(2, 2);
    other.set(0, 0, browser::Color{255, 0, 0, 255});
    browser::write_png(b, other);
    std::ofstream(folder.path / "target.txt") << "someone's\n";
    fs::create_symlink("target.txt", folder.path / "link");
    fs::create_hard_link(folder.path / "target.txt", folder.path / "second.txt");
    REQUIRE(::mkfifo((folder.path / "fifo").c_str(), 0600) == 0);
    const std::string pair = quoted(a) + " " + quoted(b);
    checkTrouble(folder, pair + " --diff " + quoted(folder.path / "link"), "it is a symbolic link");
    checkTrouble(folder, pair + " --diff " + quoted(folder.path / "fifo"), "it is a FIFO");
    checkTrouble(folder, pair + " --diff /dev/null", "it is a device");
    checkTrouble(folder, pair + " --diff " + quoted(folder.path / "second.txt"),
                 "it is a file with 2 names (hard links)");
    checkTrouble(folder, pair + " --diff " + quoted(a), "which the run reads");
    fs::create_directory(folder.path / "elsewhere");
    fs::create_directory_symlink("elsewhere", folder.path / "diffs");
    checkTrouble(folder, pair + " --diff-dir " + quoted(folder.path / "diffs"), "it is a symbolic link");
    checkTrouble(folder, pair + " --diff-dir " + quoted(folder.path), "it holds");
    CHECK(fs::is_symlink(folder.path / "link"));
    CHECK(fs::is_fifo(folder.path / "fifo"));
    CHECK(fs::is_character_file("/dev/null"));
    std::ifstream target(folder.path / "target.txt");
    CHECK(std::string(std::istreambuf_iterator<char>(target), {}) == "someone's\n");
    CHECK(browser::read_png(a).rgba == browser::Image(2, 2).rgba);
    CHECK(fs::is_empty(folder.path / "elsewhere"));
}

TEST_CASE("compare_png: --share must be a number from 0 to 1, and NaN is none") {
    const test::ScratchFolder folder("compare_png_share");
    const fs::path a = folder.path / "a.png";
    browser::write_png(a, browser::Image(2, 2));
    checkTrouble(folder, quoted(a) + " " + quoted(a) + " --share nan", "--share: must be a number from 0 to 1");
    CHECK(compare(folder, quoted(a) + " " + quoted(a) + " --share 0.5").status == 0);
}

TEST_CASE("compare_png: --diff-dir removes an old diff picture only when it wrote it") {
    const test::ScratchFolder folder("compare_png_diff_dir");
    const fs::path a = folder.path / "a.png", b = folder.path / "b.png", diffs = folder.path / "diffs";
    browser::write_png(a, browser::Image(2, 2));
    browser::Image other(2, 2);
    other.set(0, 0, browser::Color{255, 0, 0, 255});
    browser::write_png(b, other);
    // a against b differ: the diff picture diffs/a.png is written and listed.
    CHECK(compare(folder, quoted(a) + " " + quoted(b) + " --diff-dir " + quoted(diffs)).status == 1);
    CHECK(fs::is_regular_file(diffs / "a.png"));
    // a against itself matches: the old diff would mislead, and it was compare_png's.
    CHECK(compare(folder, quoted(a) + " " + quoted(a) + " --diff-dir " + quoted(diffs)).status == 0);
    CHECK_FALSE(fs::exists(diffs / "a.png"));
    // A picture of the reader's under the name of a match stays.
    std::ofstream(diffs / "b.png") << "the reader's\n";
    CHECK(compare(folder, quoted(b) + " " + quoted(b) + " --diff-dir " + quoted(diffs)).status == 0);
    CHECK(fs::exists(diffs / "b.png"));
}

TEST_CASE("compare_png: --diff-dir replaces no file it did not write, and writes nothing into a run's folder") {
    const test::ScratchFolder folder("compare_png_diff_dir_own");
    const fs::path a = folder.path / "final.png", b = folder.path / "b.png", diffs = folder.path / "dd";
    browser::write_png(a, browser::Image(2, 2));
    browser::Image other(2, 2);
    other.set(0, 0, browser::Color{255, 0, 0, 255});
    browser::write_png(b, other);
    // A file of the reader's under the name of a diff picture (issue 36: it was replaced).
    fs::create_directory(diffs);
    std::ofstream(diffs / "final.png") << "mine\n";
    checkTrouble(folder, quoted(a) + " " + quoted(b) + " --diff-dir " + quoted(diffs),
                 "it holds a file compare_png did not write");
    CHECK(textOf(diffs / "final.png") == "mine\n");
    // A stage run's --out folder: its final.png is the run's, listed in its manifest.
    const fs::path run = folder.path / "run";
    fs::create_directory(run);
    browser::write_png(run / "final.png", other);
    std::ofstream(run / ".manifest") << "# The files a run wrote here.\nfinal.png\n";
    checkTrouble(folder, quoted(a) + " " + quoted(b) + " --diff-dir " + quoted(run), "is another program's");
    CHECK(browser::read_png(run / "final.png").rgba == other.rgba);
    // Its own diff pictures it replaces, run after run.
    const fs::path own = folder.path / "own";
    for (int time = 0; time < 2; ++time) {
        CHECK(compare(folder, quoted(a) + " " + quoted(b) + " --diff-dir " + quoted(own)).status == 1);
    }
    CHECK(fs::is_regular_file(own / "final.png"));
}

TEST_CASE("compare_png: the partial file of a diff is its own, never a file or a link already there") {
    const test::ScratchFolder folder("compare_png_partial");
    const fs::path a = folder.path / "a.png", b = folder.path / "b.png";
    browser::write_png(a, browser::Image(2, 2));
    browser::Image other(2, 2);
    other.set(0, 0, browser::Color{255, 0, 0, 255});
    browser::write_png(b, other);
    // The name the partial file once had, beside the diff: a link to someone's file.
    std::ofstream(folder.path / "victim.txt") << "someone's\n";
    fs::create_symlink("victim.txt", folder.path / "diff.png.tmp");
    CHECK(compare(folder, quoted(a) + " " + quoted(b) + " --diff " + quoted(folder.path / "diff.png")).status == 1);
    CHECK(textOf(folder.path / "victim.txt") == "someone's\n");
    CHECK(fs::is_symlink(folder.path / "diff.png.tmp"));
    CHECK(browser::read_png(folder.path / "diff.png").width == 2);
}

TEST_CASE("compare_png: pictures match pixel for pixel by default, and a difference names its region") {
    const test::ScratchFolder folder("compare_png_region");
    const fs::path a = folder.path / "a.png", b = folder.path / "b.png", out = folder.path / "out.txt";
    browser::write_png(a, browser::Image(10, 10));
    browser::Image other(10, 10);
    other.set(2, 3, browser::Color{254, 255, 255, 255});  // off by 1 in red: our pages need no slack
    other.set(7, 5, browser::Color{0, 0, 0, 255});
    browser::write_png(b, other);
    const std::string line = quoted(COMPARE_PNG_PROGRAM) + " " + quoted(a) + " " + quoted(b) + " >" + quoted(out);
    const int raw = std::system(line.c_str());
    REQUIRE(WIFEXITED(raw));
    CHECK(WEXITSTATUS(raw) == 1);
    std::ifstream in(out);
    const std::string said(std::istreambuf_iterator<char>(in), {});
    // 2 of 100 pixels; the box from column 2 to 7 and row 3 to 5.
    CHECK(said == "a.png: differing pixels 2 (2.0000%) in x 2-7, y 3-5, largest channel difference 255: DIFFERENT\n");
    // The old slack of 2 per channel no longer hides the first pixel; asked for, it does.
    CHECK(compare(folder, quoted(a) + " " + quoted(b) + " --channel 2 --share 0.01").status == 0);
}
