// The live session (common/live.h) on a stand-in screen: which frame each key lands
// in, what pausing and stepping do, what is recorded, and that the replay of the
// recorded script ends on the very page the session showed last. The window itself
// (SDL) is tried by tests/live/.
#include <catch2/catch.hpp>

#include <algorithm>
#include <deque>
#include <functional>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

#include "captured_output.h"
#include "browser.h"
#include "gif_writer.h"
#include "live.h"
#include "page.h"
#include "png_io.h"
#include "scratch_folder.h"

namespace fs = std::filesystem;
using browser::Key;
using browser::LiveInput;
using Kind = browser::LiveInput::Kind;

namespace {

// A page whose picture tells its whole history: each frame draws a mark whose place
// depends on the frame number, and the echo lists every key pressed and the frame it
// came before.
class MarkingPage : public browser::PageScripts {
public:
    explicit MarkingPage(browser::Document& document) : document_(document) {}
    void onKeyDown(Key key) override {
        document_.ui_echo += browser::key_name(key) + "@" + std::to_string(frame_) + " ";
    }
    void onAnimationFrame() override {
        browser::Canvas& canvas = document_.canvas;
        canvas.clear();
        canvas.strokeRect(2 + frame_ % 30, 2 + frame_ / 30, 4, 4);
        ++frame_;
    }

private:
    browser::Document& document_;
    int frame_ = 0;
};

// Hands the session one batch of inputs per refresh, and keeps what it was shown.
class StandInScreen : public browser::Screen {
public:
    explicit StandInScreen(std::vector<std::vector<LiveInput>> batches) : batches_(batches.begin(), batches.end()) {}
    void show(const browser::Image& picture) override { shown.push_back(picture); }
    std::vector<LiveInput> nextFrame() override {
        if (batches_.empty()) return {{Kind::End}};  // a session must end
        std::vector<LiveInput> batch = batches_.front();
        batches_.pop_front();
        return batch;
    }
    void close() override {
        ++closed;
        if (on_close) on_close();
    }

    std::vector<browser::Image> shown;
    int closed = 0;
    std::function<void()> on_close;

private:
    std::deque<std::vector<LiveInput>> batches_;
};

std::string read_text(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

LiveInput key(Key k) { return {Kind::PageKey, k}; }
const LiveInput kPause{Kind::Pause};
const LiveInput kStep{Kind::Step};
const LiveInput kEnd{Kind::End};
const LiveInput kScreenshot{Kind::Screenshot};

constexpr int kCanvasWidth = 60, kCanvasHeight = 40;

browser::Options live_options(const std::string& stage_keys = "d f g h") {
    browser::Options options;
    options.frame_ms = 10.0;
    options.stage_keys = browser::KeySet::parse(stage_keys);
    options.live.on = true;
    options.live.replay_command = {"build/s9_9_test", "--seed", "7"};
    options.live.replay_every = 30;
    options.live.replay_gif = true;
    options.live.stage_id = "s9_9";
    return options;
}

struct Session {
    int status = -1;
    std::string out, err;
    std::vector<browser::Image> shown;
    int closed = 0;
};

Session play(const browser::Options& options, std::vector<std::vector<LiveInput>> batches,
             std::function<void()> on_close = {}) {
    browser::Window window(options.frame_ms, browser::Document{browser::Canvas(kCanvasWidth, kCanvasHeight), ""});
    MarkingPage page(window.document);
    StandInScreen screen(std::move(batches));
    screen.on_close = std::move(on_close);
    Session session;
    {
        const test::CapturedOutput captured;
        session.status = browser::run_live(page, window, options, screen);
        session.out = captured.out();
        session.err = captured.err();
    }
    session.shown = screen.shown;
    session.closed = screen.closed;
    return session;
}

// The final.png of a run of the marking page with these keys and frames.
browser::Image replay(const fs::path& out, const std::string& keys, int frames) {
    browser::Options options;
    options.out_dir = out;
    options.frames = frames;
    options.frame_ms = 10.0;
    options.keys = browser::KeyScript::parse(keys);
    browser::Window window(options.frame_ms, browser::Document{browser::Canvas(kCanvasWidth, kCanvasHeight), ""});
    MarkingPage page(window.document);
    int status = 0;
    {
        const test::CapturedOutput quiet;
        status = browser::run(page, window, options);
    }
    REQUIRE(status == 0);
    return browser::read_png(out / "final.png");
}

// A replay of the marking page as a recorded session's command runs it: pictures from
// frame `from` on, every `every`-th, and a GIF where the build has one. Returns what it
// printed.
std::string replay_from(const fs::path& out, const std::string& keys, int frames, int from, int every) {
    browser::Options options;
    options.out_dir = out;
    options.frames = frames;
    options.from = from;
    options.every = every;
    options.gif = browser::gif_supported();
    options.frame_ms = 10.0;
    options.keys = browser::KeyScript::parse(keys);
    browser::Window window(options.frame_ms, browser::Document{browser::Canvas(kCanvasWidth, kCanvasHeight), ""});
    MarkingPage page(window.document);
    int status = 0;
    std::string printed;
    {
        const test::CapturedOutput captured;
        status = browser::run(page, window, options);
        printed = captured.out();
    }
    REQUIRE(status == 0);
    return printed;
}

std::vector<std::string> pictures_in(const fs::path& folder) {
    std::vector<std::string> names;
    for (const fs::directory_entry& entry : fs::directory_iterator(folder)) {
        const std::string name = entry.path().filename().string();
        if (name.ends_with(".png") || name.ends_with(".gif")) names.push_back(name);
    }
    std::sort(names.begin(), names.end());
    return names;
}

// The page part of a picture the live window showed: all but the status line under it.
browser::Image page_part(const browser::Image& picture, int page_height) {
    browser::Image page(picture.width, page_height);
    for (int y = 0; y < page_height; ++y) {
        for (int x = 0; x < picture.width; ++x) page.set(x, y, picture.at(x, y));
    }
    return page;
}

}  // namespace

TEST_CASE("live: keys land in the next frame that runs; pausing stops the frames, a step runs one") {
    test::ScratchFolder folder("live");
    browser::Options options = live_options();
    options.live.record = folder.path / "my session.keys";  // a space, for the shell to see quoted
    // Refresh 0 shows frame 0. Then, one batch per refresh:
    const Session session = play(options, {
                                              {key(Key::F), key(Key::G)},   // 1: frame 1, after f and g
                                              {},                           // 2: frame 2
                                              {kPause},                     // 3: no frame
                                              {key(Key::D)},                // 4: d waits
                                              {kStep},                      // 5: frame 3, after d
                                              {key(Key::D), kStep, kStep},  // 6: frame 4, after d (one step a refresh)
                                              {},                           // 7: frame 5, the second step
                                              {},                           // 8: paused, no frame
                                              {kPause, key(Key::H)},        // 9: frame 6, after h
                                              {},                           // 10: frame 7
                                              {key(Key::F), kEnd},          // 11: ends; this f never reaches the page
                                          });
    CHECK(session.status == 0);
    CHECK(session.err.empty());
    CHECK(session.closed == 1);
    REQUIRE(session.shown.size() == 11);  // refreshes 0 to 10
    const std::string script = read_text(options.live.record);
    CHECK(script == "f@1 g@1 d@3 d@4 h@6\n");
    CHECK(folder.files() == std::vector<std::string>{"my session.keys"});  // nothing beside it

    // The one command that replays it, with what shaped the run and the frames it ran.
    CHECK(session.out == "recorded 5 key presses in 8 frames (0.08 s) to " + options.live.record.string() +
                             "; replay them into pictures" + (browser::gif_supported() ? " and a GIF" : "") +
                             " with:\n"
                             "  build/s9_9_test --seed 7 --keys \"$(cat '" +
                             options.live.record.string() + "')\" --frames 8 --from 1 --every 30 --gif\n");

    // The replay's last frame is the last page shown, pixel for pixel, and the page the
    // marks tell: keys before the frames the script names.
    const browser::Image final_page = replay(folder.path / "replay", script, 8);
    CHECK(page_part(session.shown.back(), final_page.height).rgba == final_page.rgba);
    // Paused refreshes show the same page again (frame 2 at refreshes 2 to 4).
    CHECK(page_part(session.shown[3], final_page.height).rgba == page_part(session.shown[2], final_page.height).rgba);
    CHECK(page_part(session.shown[4], final_page.height).rgba == page_part(session.shown[2], final_page.height).rgba);
    CHECK(page_part(session.shown[5], final_page.height).rgba != page_part(session.shown[4], final_page.height).rgba);
    // ... with the status line saying so: it differs from the running one.
    CHECK(session.shown[3].rgba != session.shown[2].rgba);
}

TEST_CASE("live: only the stage's keys reach the page; a script of the reader's plays along") {
    browser::Options options = live_options("f g");
    test::ScratchFolder folder("live");
    options.live.record = folder.path / "s.keys";
    options.keys = browser::KeyScript::parse("g@2 f@40");  // frame 40 is never reached
    // q and up are not the stage's: let go, never pressed, never recorded. The scripted
    // g is pressed before frame 2; the reader's g, at the refresh after, before frame 3.
    const Session session = play(options, {{key(Key::F), key(Key::Q), key(Key::Up)}, {}, {key(Key::G)}});
    CHECK(session.status == 0);
    CHECK(read_text(options.live.record) == "f@1 g@2 g@3\n");
}

TEST_CASE("live: without --record nothing is written, and the session still says what it played") {
    const Session session = play(live_options(), {{key(Key::F)}, {}});
    CHECK(session.status == 0);
    CHECK(session.out == "played 3 frames (0.03 s); --record FILE keeps the key presses of a session to replay them\n");
    CHECK(session.err.empty());
}

TEST_CASE("live: ending at once plays frame 0 only, and the replay of its empty script is that frame") {
    test::ScratchFolder folder("live");
    browser::Options options = live_options();
    options.live.record = folder.path / "empty.keys";
    const Session session = play(options, {{kEnd}});
    CHECK(session.status == 0);
    REQUIRE(session.shown.size() == 1);
    CHECK(read_text(options.live.record) == "\n");
    CHECK_THAT(session.out, Catch::Contains("--frames 1 "));
    const browser::Image final_page = replay(folder.path / "replay", "", 1);
    CHECK(page_part(session.shown.back(), final_page.height).rgba == final_page.rgba);
}

TEST_CASE("live: a record file in a folder that is not there stops the session before it starts") {
    test::ScratchFolder folder("live");
    browser::Options options = live_options();
    options.live.record = folder.path / "no such folder" / "s.keys";
    const Session session = play(options, {{key(Key::F)}});
    CHECK(session.status == 2);
    CHECK(session.shown.empty());
    CHECK_THAT(session.err, Catch::StartsWith("--record: cannot write"));
    CHECK(session.err.find('\n') == session.err.size() - 1);
    CHECK(folder.files().empty());
}

TEST_CASE("live: a key script that cannot be written is given on stderr, so the session is not lost") {
    test::ScratchFolder folder("live");
    browser::Options options = live_options();
    options.live.record = folder.path / "s.keys";
    // The folder goes away while the window is open.
    const Session session = play(options, {{key(Key::F)}}, [&] { fs::remove_all(folder.path); });
    CHECK(session.status == 1);
    CHECK(session.err ==
          "cannot write the key script to \"" + options.live.record.string() + "\": cannot write it; it was: f@1\n");
    CHECK(session.out.empty());
}

TEST_CASE("live: a folder where the record file should go is refused before the session starts") {
    test::ScratchFolder folder("live");
    browser::Options options = live_options();
    options.live.record = folder.path / "s.keys";
    fs::create_directory(options.live.record);
    const Session session = play(options, {{key(Key::F)}});
    CHECK(session.status == 2);
    CHECK(session.shown.empty());
}

TEST_CASE("live: F12 saves the page shown, which is the replay's picture of that frame") {
    test::ScratchFolder folder("live");
    browser::Options options = live_options();
    options.live.record = folder.path / "s.keys";
    options.live.screenshot_folder = folder.path;
    // Refresh 3 saves the page on screen, frame 2, then runs frame 3; paused at 4, the
    // save at 5 is of frame 3 again, the page still shown.
    const Session session = play(options, {{key(Key::F)}, {}, {kScreenshot}, {kPause}, {kScreenshot}, {kEnd}});
    CHECK(session.status == 0);
    CHECK(session.err.empty());
    CHECK(folder.files() == std::vector<std::string>{"s.keys", "s9_9_frame_0002.png", "s9_9_frame_0003.png"});
    CHECK_THAT(session.out,
               Catch::StartsWith("F12: saved frame 2 to " + (folder.path / "s9_9_frame_0002.png").string() +
                                 "\nF12: saved frame 3 to "));
    // The screenshots are the pages without the status line, as the replay draws them.
    const std::string script = read_text(options.live.record);
    CHECK(script == "f@1\n");
    replay_from(folder.path / "replay", script, 4, 1, 1);
    for (const char* frame : {"0002", "0003"}) {
        INFO("frame " << frame);
        const browser::Image saved = browser::read_png(folder.path / ("s9_9_frame_" + std::string(frame) + ".png"));
        const browser::Image replayed =
            browser::read_png(folder.path / "replay" / ("frame_" + std::string(frame) + ".png"));
        CHECK(saved.width == replayed.width);
        CHECK(saved.height == replayed.height);
        CHECK(saved.rgba == replayed.rgba);
    }
    // The page shown then, not the one after it.
    CHECK(browser::read_png(folder.path / "s9_9_frame_0002.png").rgba !=
          browser::read_png(folder.path / "s9_9_frame_0003.png").rgba);
}

TEST_CASE("live: a screenshot that cannot be saved is one line on stderr; the session goes on, status 1") {
    test::ScratchFolder folder("live");
    browser::Options options = live_options();
    options.live.screenshot_folder = folder.path / "no such folder";
    const Session session = play(options, {{kScreenshot}, {key(Key::F)}, {}});
    CHECK(session.status == 1);
    CHECK(session.shown.size() == 4);  // refreshes 0 to 3: the session went on
    CHECK_THAT(session.err,
               Catch::StartsWith("F12: cannot save frame 0 to \"" +
                                 (options.live.screenshot_folder / "s9_9_frame_0000.png").string() + "\": "));
    CHECK(session.err.find('\n') == session.err.size() - 1);
    CHECK(folder.files().empty());
}

TEST_CASE("live: a recording whose first key came late replays into the frames from that key on") {
    test::ScratchFolder folder("live");
    browser::Options options = live_options();
    options.live.record = folder.path / "late.keys";
    // 39 idle refreshes, f at refresh 40 (before frame 40), 5 more frames, then the end.
    std::vector<std::vector<LiveInput>> batches(39);
    batches.push_back({key(Key::F)});
    for (int i = 0; i < 5; ++i) batches.emplace_back();
    batches.push_back({kEnd});
    const Session session = play(options, batches);
    CHECK(session.status == 0);
    REQUIRE(session.shown.size() == 46);  // frames 0 to 45
    const std::string script = read_text(options.live.record);
    CHECK(script == "f@40\n");
    CHECK_THAT(session.out, Catch::EndsWith("\" --frames 46 --from 40 --every 30 --gif\n"));

    // The replay runs all 46 frames, and keeps 40 to 45: its first picture is frame 40,
    // the page the window showed as the key went in, its last the last one shown.
    const fs::path out = folder.path / "replay";
    const std::string printed = replay_from(out, script, 46, 40, 30);
    std::vector<std::string> expected{"contact_sheet.png", "final.png", "frame_0040.png"};
    if (browser::gif_supported()) expected.insert(expected.begin(), "animation.gif");
    CHECK(pictures_in(out) == expected);
    const int height = browser::read_png(out / "final.png").height;
    CHECK(browser::read_png(out / "frame_0040.png").rgba == page_part(session.shown[40], height).rgba);
    CHECK(browser::read_png(out / "final.png").rgba == page_part(session.shown[45], height).rgba);
    // Frames 40, 42 and 44 in the GIF: none of the 40 idle frames before the key.
    if (browser::gif_supported()) CHECK_THAT(printed, Catch::EndsWith("animation.gif (3 frames)\n"));
}
