// A stage's program played live, as a reader plays it: under SDL's dummy video driver
// (no display needed), key events pushed into the window's event queue by the
// --live-events test hook go the way real key presses go. The recorded key script,
// replayed by the very command the program prints, ends on the page the window showed
// last, pixel for pixel. Also: --scale draws the same page larger. LIVE_PROGRAM is
// stage 4.4's program (tests/live/CMakeLists.txt).
#include <catch2/catch.hpp>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <utility>
#include <vector>

#include <sys/stat.h>
#include <sys/wait.h>

#include "contact_sheet.h"
#include "gif_writer.h"
#include "image_compare.h"
#include "live_window.h"
#include "png_io.h"
#include "scratch_folder.h"

namespace fs = std::filesystem;
using browser::Image;
using test::ScratchFolder;

namespace {

struct Run {
    int status = -1;
    std::string out, err;
};

std::string read_text(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// Built by appending: g++ 12 gives a false -Wrestrict warning for "'" + text.
std::string quoted(const fs::path& path) {
    std::string text = "'";
    text += path.string();
    text += "'";
    return text;
}

// Runs `command` with `folder` as its working folder and SDL's dummy video driver; its
// output goes to files beside the folder, so the folder holds only what the command
// wrote.
Run run_in(const ScratchFolder& folder, const std::string& command) {
    const fs::path out = folder.path.string() + ".out", err = folder.path.string() + ".err";
    const std::string line = "cd " + quoted(folder.path) + " && SDL_VIDEODRIVER=dummy SDL_RENDER_DRIVER=software " +
                             command + " >" + quoted(out) + " 2>" + quoted(err);
    const int raw = std::system(line.c_str());
    Run run;
    if (raw != -1 && WIFEXITED(raw)) run.status = WEXITSTATUS(raw);
    run.out = read_text(out);
    run.err = read_text(err);
    fs::remove(out);
    fs::remove(err);
    return run;
}

std::string program() { return quoted(LIVE_PROGRAM); }

}  // namespace

#if BROWSER_HAS_SDL

namespace {

// The top `height` rows of a picture: a live window's page, without its status line.
Image top_rows(const Image& picture, int height) {
    Image top(picture.width, height);
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < picture.width; ++x) top.set(x, y, picture.at(x, y));
    }
    return top;
}

}  // namespace

TEST_CASE("live program: a session's recorded script replays to the last page the window showed") {
    ScratchFolder folder("live_program");
    // Refresh by refresh (live.h): f and g before frame 1; p is no key of 4.4's, let go;
    // paused at refresh 3; d waits and goes in with the step at 5 (frame 3); the next d
    // waits until Space goes on at 8 (frame 4); h and comma before frames 5 and 6.
    folder.write("events.txt", "F@1 G@1 P@2 Space@3 D@4 .@5 D@6 Space@8 H@9 ,@10 Escape@12\n");
    const Run live = run_in(folder, program() +
                                        " --live --record session.keys --live-events events.txt"
                                        " --live-screenshot shown.png --seed 5");
    INFO(live.err);
    REQUIRE(live.status == 0);
    CHECK(live.err.empty());
    CHECK(read_text(folder.path / "session.keys") == "f@1 g@1 d@3 d@4 h@5 comma@6\n");
    // Nothing but what was asked: the script, and the test hook's screenshot.
    CHECK(folder.files() == std::vector<std::string>{"events.txt", "session.keys", "shown.png"});

    // The one command it prints, run as printed, writes the pictures and the GIF.
    const std::string intro = std::string("recorded 6 key presses in 8 frames (0.13 s) to session.keys; ") +
                              "replay them into pictures" + (browser::gif_supported() ? " and a GIF" : "") +
                              " with:\n  ";
    REQUIRE(live.out.rfind(intro, 0) == 0);
    const std::string command = live.out.substr(intro.size(), live.out.size() - intro.size() - 1);
    CHECK(command == std::string(LIVE_PROGRAM) +
                         " --seed 5 --keys \"$(cat session.keys)\" --frames 8 --from 1 --every 30" +
                         (browser::gif_supported() ? " --gif" : ""));
    const Run replay = run_in(folder, command);
    REQUIRE(replay.status == 0);
    const fs::path pictures = folder.path / "out" / "s4_4";
    CHECK(fs::exists(pictures / "frame_0001.png"));  // from the first key on
    CHECK_FALSE(fs::exists(pictures / "frame_0000.png"));
    CHECK(fs::exists(pictures / "animation.gif") == browser::gif_supported());

    const Image final_page = browser::read_png(pictures / "final.png");
    const Image shown = browser::read_png(folder.path / "shown.png");
    REQUIRE(shown.width == final_page.width);
    REQUIRE(shown.height == final_page.height + 24);  // the status line under the page
    CHECK(top_rows(shown, final_page.height).rgba == final_page.rgba);
}

TEST_CASE("live program: F12 saves the page shown, which the replay draws as that frame") {
    ScratchFolder folder("live_program");
    // f before frame 1; paused at refresh 3 with frame 2 shown; F12 saves it; Escape.
    folder.write("events.txt", "F@1 Space@3 F12@4 Escape@5\n");
    const Run live = run_in(folder, program() + " --live --record session.keys --live-events events.txt");
    INFO(live.err);
    REQUIRE(live.status == 0);
    CHECK(live.err.empty());
    CHECK_THAT(live.out,
               Catch::StartsWith("F12: saved frame 2 to s4_4_frame_0002.png\nrecorded 1 key press in 3 frames"));
    CHECK(folder.files() == std::vector<std::string>{"events.txt", "s4_4_frame_0002.png", "session.keys"});
    const std::size_t indent = live.out.find("\n  ");
    REQUIRE(indent != std::string::npos);
    const std::string command = live.out.substr(indent + 3, live.out.size() - indent - 4);
    REQUIRE(run_in(folder, command).status == 0);
    const Image saved = browser::read_png(folder.path / "s4_4_frame_0002.png");
    const Image replayed = browser::read_png(folder.path / "out" / "s4_4" / "final.png");
    CHECK(saved.width == replayed.width);
    CHECK(saved.height == replayed.height);  // the page, without the window's status line
    CHECK(saved.rgba == replayed.rgba);
}

TEST_CASE("live program: the close button ends a session with status 0, and without --record nothing is written") {
    ScratchFolder folder("live_program");
    folder.write("events.txt", "F@1 close@3");
    const Run live = run_in(folder, program() + " --live --live-events events.txt");
    CHECK(live.status == 0);
    CHECK(live.err.empty());
    CHECK(live.out == "played 3 frames (0.05 s); --record FILE keeps the key presses of a session to replay them\n");
    CHECK(folder.files() == std::vector<std::string>{"events.txt"});  // no out/, no script
}

TEST_CASE("live program: a bad events file is one line and status 1, with nothing written") {
    ScratchFolder folder("live_program");
    folder.write("events.txt", "F@0");
    const Run live = run_in(folder, program() + " --live --record s.keys --live-events events.txt");
    CHECK(live.status == 1);
    CHECK(live.err ==
          "--live-events: bad token \"F@0\" (NAME@REFRESH, NAME an SDL key name, close, or press:X,Y, move:X,Y, "
          "release:X,Y)\n");
    CHECK(folder.files() == std::vector<std::string>{"events.txt"});
}

TEST_CASE("live program: --record never replaces a link, a FIFO, a device, a second name or the events file") {
    ScratchFolder folder("live_program");
    folder.write("events.txt", "close@1");
    folder.write("target.txt", "someone's\n");
    fs::create_symlink("target.txt", folder.path / "link");
    fs::create_hard_link(folder.path / "target.txt", folder.path / "second.txt");
    REQUIRE(::mkfifo((folder.path / "fifo").c_str(), 0600) == 0);
    struct Case {
        std::string record, says;
    };
    const Case cases[] = {
        {"link", "it is a symbolic link"},     {"fifo", "it is a FIFO"},
        {"/dev/null", "it is a device"},       {"second.txt", "it is a file with 2 names (hard links)"},
        {"events.txt", "which the run reads"}, {".", "it is the current folder or holds it"}};
    for (const Case& bad : cases) {
        INFO(bad.record);
        const Run live = run_in(folder, program() + " --live --live-events events.txt --record " + bad.record);
        CHECK(live.status == 2);
        CHECK(live.err.find('\n') == live.err.size() - 1);
        CHECK_THAT(live.err, Catch::StartsWith("--record: cannot write") && Catch::Contains(bad.says));
    }
    CHECK(fs::is_symlink(folder.path / "link"));
    CHECK(fs::is_fifo(folder.path / "fifo"));
    CHECK(fs::is_character_file("/dev/null"));
    CHECK(read_text(folder.path / "target.txt") == "someone's\n");
    CHECK(read_text(folder.path / "events.txt") == "close@1");
}

TEST_CASE("live program: with no display named, --live is one line and status 1, at once") {
    ScratchFolder folder("live_program");
    // run_in names SDL's dummy driver; env takes it away again, with any display.
    const Run live =
        run_in(folder, "timeout 20 env -u SDL_VIDEODRIVER -u DISPLAY -u WAYLAND_DISPLAY " + program() + " --live");
    CHECK(live.status == 1);
    CHECK(live.err ==
          "--live: no display to open a window on (DISPLAY and WAYLAND_DISPLAY are unset; "
          "SDL_VIDEODRIVER names a driver explicitly)\n");
    CHECK(folder.files().empty());
}

TEST_CASE("live program: SIGINT and SIGTERM end a live session as they end a run: 130 and 143") {
    ScratchFolder folder("live_program");
    // timeout sends the signal after a second and, preserving the status, exits as
    // the program did: 128 + the signal when the signal ended it.
    for (const auto& [signal, status] : {std::pair{"INT", 130}, std::pair{"TERM", 143}}) {
        INFO(signal);
        const Run live =
            run_in(folder, std::string("timeout --preserve-status -s ") + signal + " 1 " + program() + " --live");
        CHECK(live.status == status);
        CHECK(live.out.empty());
    }
    CHECK(folder.files().empty());
}

#else

TEST_CASE("live program: a build without SDL2 says so in one line, and writes nothing") {
    ScratchFolder folder("live_program");
    const Run live = run_in(folder, program() + " --live --record s.keys");
    CHECK(live.status == 2);
    CHECK(live.err == "s4_4_angular_impulse: " + std::string(browser::kNoLiveSupport) + "\n");
    CHECK(folder.files().empty());
}

#endif

TEST_CASE("live program: --scale 2 draws the same page at twice the size") {
    // The page at scale 2 shrunk by 2 (each pixel the mean of a 2 x 2 block) against the
    // page at scale 1, after 120 frames of the stage's default run:
    // - the echo panel is text only, whole blocks of 2 x 2 pixels: identical;
    // - the canvas differs only in how the pen's ink spreads. A 1 px pen's coverage falls
    //   from 1 to 0 over one pixel; at scale 2 the four sub-pixels of a pixel sit a
    //   quarter pixel either side of its centre, so beside a straight line the shrunk
    //   coverage is off by at most 0.25 (64 of 255), a little more at corners and line
    //   ends. Tolerance: no channel off by more than 96, and at most 1% of the pixels off
    //   by more than 32. (Measured: 71 at most; 0.57% of pixels off by more than 32.)
    //   Anything drawn in the wrong place would be off by up to 255.
    ScratchFolder folder("live_program");
    const std::string run = program() + " --frames 120 --every 0 --no-gif --out ";
    REQUIRE(run_in(folder, run + "one").status == 0);
    REQUIRE(run_in(folder, run + "two --scale 2").status == 0);
    const Image one = browser::read_png(folder.path / "one" / "final.png");
    const Image two = browser::read_png(folder.path / "two" / "final.png");
    REQUIRE(two.width == 2 * one.width);
    REQUIRE(two.height == 2 * one.height);
    const Image shrunk = browser::shrink(two, 2);

    const browser::ImageDifference any = browser::compare_images(one, shrunk, {.channel = 0});
    CHECK(any.largest_channel_difference <= 96);
    const browser::ImageDifference large = browser::compare_images(one, shrunk, {.channel = 32});
    CHECK(large.differing_share <= 0.01);
    constexpr int kCanvasWidth = 800;
    long panel_differences = 0;
    for (int y = 0; y < one.height; ++y) {
        for (int x = kCanvasWidth; x < one.width; ++x) panel_differences += one.at(x, y) == shrunk.at(x, y) ? 0 : 1;
    }
    CHECK(panel_differences == 0);
    // Not a magnified copy: the circles and slanted lines have detail of their own.
    CHECK(any.differing_pixels > 0);
}
