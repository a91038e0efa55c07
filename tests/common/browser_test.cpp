// The browser session: the order of callbacks, the clock, and the folder of pictures.
#include <catch2/catch.hpp>

#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "captured_output.h"
#include "browser.h"
#include "output_folder.h"
#include "contact_sheet.h"
#include "png_io.h"
#include "scratch_folder.h"

namespace fs = std::filesystem;
using browser::Key;

namespace {

using test::ScratchFolder;

// The names in `folder`, sorted.
std::vector<std::string> names_in(const fs::path& folder) {
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(folder)) names.push_back(entry.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
}

// The names a run's manifest lists, in its order (output_folder.h).
std::vector<std::string> manifest_names(const fs::path& folder) {
    std::ifstream in(folder / browser::kManifest);
    std::vector<std::string> names;
    for (std::string line; std::getline(in, line);) {
        if (!line.empty() && line.front() != '#') names.push_back(line);
    }
    return names;
}

// Writes down every callback with the clock's time, and changes the page each frame so
// pictures of different frames differ.
class RecordingScripts : public browser::PageScripts {
public:
    RecordingScripts(browser::Document& document, const browser::Clock& clock) : document_(document), clock_(clock) {}

    void onKeyDown(Key key) override { log.push_back("key " + browser::key_name(key) + " at " + now()); }
    void onAnimationFrame() override {
        log.push_back("frame at " + now());
        document_.ui_echo = "frame " + std::to_string(++frames_);
        document_.canvas.clear();
        document_.canvas.strokeRect(2, 2, frames_, frames_);
    }

    std::vector<std::string> log;

private:
    std::string now() const {
        std::ostringstream text;
        text << clock_.nowMs();
        return text.str();
    }

    browser::Document& document_;
    const browser::Clock& clock_;
    int frames_ = 0;
};

class ThrowingScripts : public browser::PageScripts {
public:
    void onKeyDown(Key) override {}
    void onAnimationFrame() override { throw std::runtime_error("the page's script failed"); }
};

browser::Options options_for(const fs::path& out, int frames, int every, const std::string& keys = "") {
    browser::Options options;
    options.out_dir = out;
    options.frames = frames;
    options.every = every;
    options.keys_text = keys;
    options.keys = browser::KeyScript::parse(keys);
    options.frame_ms = 10.0;
    return options;
}

struct Result {
    int status = 0;
    std::string out, err;
    std::vector<std::string> log;
    browser::Image last_page;
};

// Runs the recording page with a small canvas, capturing what the browser prints.
Result run(const browser::Options& options) {
    browser::Window window(options.frame_ms, browser::Document{browser::Canvas(40, 30), ""});
    RecordingScripts scripts(window.document, window.clock);
    Result result;
    {
        const test::CapturedOutput captured;
        result.status = browser::run(scripts, window, options);
        result.out = captured.out();
        result.err = captured.err();
    }
    result.log = scripts.log;
    result.last_page = browser::render_page(window.document);
    return result;
}

bool is_one_line(const std::string& text) { return !text.empty() && text.find('\n') == text.size() - 1; }

}  // namespace

TEST_CASE("browser: keys for frame k come before frame k, with the clock at (k+1) frames") {
    ScratchFolder temp("browser_test");
    const Result result = run(options_for(temp.path / "out", 3, 0, "f*2 G@2"));
    REQUIRE(result.status == 0);
    const std::vector<std::string> expected{
        "key f at 10", "key f at 10", "frame at 10", "frame at 20", "key g at 30", "frame at 30",
    };
    CHECK(result.log == expected);
}

TEST_CASE("browser: final.png and every K-th frame are written") {
    ScratchFolder temp("browser_test");
    const fs::path out = temp.path / "out";

    SECTION("every 10 of 25 frames") {
        const Result result = run(options_for(out, 25, 10));
        REQUIRE(result.status == 0);
        CHECK(names_in(out) == std::vector<std::string>{".manifest", "contact_sheet.png", "final.png", "frame_0000.png",
                                                        "frame_0010.png", "frame_0020.png"});
        CHECK(is_one_line(result.out));
        CHECK_THAT(result.out, Catch::StartsWith("wrote 4 pictures to "));
        CHECK_THAT(result.out,
                   Catch::EndsWith("(final.png, frame_0000.png ... frame_0020.png) and contact_sheet.png\n"));
        CHECK(result.err.empty());
    }
    SECTION("every 0: the final picture only") {
        const Result result = run(options_for(out, 5, 0));
        REQUIRE(result.status == 0);
        CHECK(names_in(out) == std::vector<std::string>{".manifest", "final.png"});
        CHECK_THAT(result.out, Catch::StartsWith("wrote 1 picture to "));
        CHECK_THAT(result.out, Catch::EndsWith("(final.png)\n"));
    }
    SECTION("every frame") {
        const Result result = run(options_for(out, 3, 1));
        REQUIRE(result.status == 0);
        CHECK(names_in(out) == std::vector<std::string>{".manifest", "contact_sheet.png", "final.png", "frame_0000.png",
                                                        "frame_0001.png", "frame_0002.png"});
    }
    SECTION("from frame 7, every 5 of 20 frames: 7, 12, 17, and none before") {
        browser::Options options = options_for(out, 20, 5);
        options.from = 7;
        const Result result = run(options);
        REQUIRE(result.status == 0);
        CHECK(names_in(out) == std::vector<std::string>{".manifest", "contact_sheet.png", "final.png", "frame_0007.png",
                                                        "frame_0012.png", "frame_0017.png"});
        // Every frame ran all the same, those before 7 unseen.
        CHECK(result.log.size() == 20);
        CHECK(browser::read_png(out / "frame_0007.png").rgba != browser::read_png(out / "frame_0012.png").rgba);
    }
    SECTION("frame numbers past 9999 grow beyond four digits") {
        const Result result = run(options_for(out, 10001, 10000));
        REQUIRE(result.status == 0);
        CHECK(names_in(out) == std::vector<std::string>{".manifest", "contact_sheet.png", "final.png", "frame_0000.png",
                                                        "frame_10000.png"});
    }
}

TEST_CASE("browser: final.png shows the page after the last frame") {
    ScratchFolder temp("browser_test");
    const Result result = run(options_for(temp.path / "out", 4, 2));
    REQUIRE(result.status == 0);
    const browser::Image final_picture = browser::read_png(temp.path / "out" / "final.png");
    CHECK(final_picture.width == result.last_page.width);
    CHECK(final_picture.height == result.last_page.height);
    CHECK(final_picture.rgba == result.last_page.rgba);
    const browser::Image frame0 = browser::read_png(temp.path / "out" / "frame_0000.png");
    CHECK(frame0.rgba != final_picture.rgba);
}

TEST_CASE("browser: the contact sheet shows the saved frames and the final one, small") {
    ScratchFolder temp("browser_test");
    const fs::path out = temp.path / "out";
    const Result result = run(options_for(out, 25, 10));  // frames 0, 10, 20 and 24
    REQUIRE(result.status == 0);
    const browser::Image sheet = browser::read_png(out / "contact_sheet.png");
    const browser::Image thumbnail = browser::shrink(result.last_page, browser::kThumbnailScale);
    const int cell_width = thumbnail.width + browser::kSheetMargin;
    CHECK(sheet.width == browser::kSheetMargin + 4 * cell_width);
    CHECK(sheet.height == browser::kSheetMargin + browser::kLabelHeight + thumbnail.height + browser::kSheetMargin);
    // The fourth cell holds the final page.
    const int left = browser::kSheetMargin + 3 * cell_width, top = browser::kSheetMargin + browser::kLabelHeight;
    for (int y = 0; y < thumbnail.height; ++y) {
        for (int x = 0; x < thumbnail.width; ++x) {
            if (sheet.at(left + x, top + y) != thumbnail.at(x, y)) FAIL("thumbnail pixel (" << x << ", " << y << ")");
        }
    }
}

TEST_CASE("browser: a run replaces the whole output folder and leaves nothing beside it") {
    ScratchFolder temp("browser_test");
    const fs::path out = temp.path / "out";
    REQUIRE(run(options_for(out, 3, 1)).status == 0);
    CHECK(manifest_names(out) == std::vector<std::string>{"contact_sheet.png", "final.png", "frame_0000.png",
                                                          "frame_0001.png", "frame_0002.png"});

    const Result result = run(options_for(out, 2, 0));
    REQUIRE(result.status == 0);
    CHECK(names_in(out) == std::vector<std::string>{".manifest", "final.png"});
    CHECK(names_in(temp.path) == std::vector<std::string>{"out"});
}

TEST_CASE("browser: a run's folder that came to hold a file no run wrote is refused, naming it, and kept whole") {
    ScratchFolder temp("browser_test");
    const fs::path out = temp.path / "out";
    REQUIRE(run(options_for(out, 3, 1)).status == 0);
    std::ofstream(out / "notes.txt") << "the reader's\n";
    const Result result = run(options_for(out, 2, 0));
    CHECK(result.status == 2);
    CHECK(is_one_line(result.err));
    CHECK_THAT(result.err, Catch::Contains("it holds \"notes.txt\", which no run wrote"));
    CHECK(names_in(out) == std::vector<std::string>{".manifest", "contact_sheet.png", "final.png", "frame_0000.png",
                                                    "frame_0001.png", "frame_0002.png", "notes.txt"});
}

TEST_CASE("browser: an empty output folder may be replaced, and a trailing slash is fine") {
    ScratchFolder temp("browser_test");
    fs::create_directories(temp.path / "out");
    const Result result = run(options_for(temp.path / "out" / "", 1, 0));
    REQUIRE(result.status == 0);
    CHECK(names_in(temp.path / "out") == std::vector<std::string>{".manifest", "final.png"});
    CHECK(names_in(temp.path) == std::vector<std::string>{"out"});
}

TEST_CASE("browser: missing parent folders are created") {
    ScratchFolder temp("browser_test");
    const fs::path out = temp.path / "a" / "b" / "out";
    REQUIRE(run(options_for(out, 1, 0)).status == 0);
    CHECK(fs::exists(out / "final.png"));
}

TEST_CASE("browser: an output folder that cannot be made is refused with status 2, leaving nothing behind") {
    ScratchFolder temp("browser_test");
    std::ofstream(temp.path / "plain_file") << "not a folder\n";
    const Result result = run(options_for(temp.path / "plain_file" / "out", 3, 1));
    CHECK(result.status == 2);
    CHECK(is_one_line(result.err));
    CHECK_THAT(result.err, Catch::StartsWith("cannot write pictures to \""));
    CHECK(result.out.empty());
    CHECK(names_in(temp.path) == std::vector<std::string>{"plain_file"});
}

TEST_CASE("browser: a folder that no run wrote is left alone") {
    ScratchFolder temp("browser_test");
    const fs::path out = temp.path / "important";
    fs::create_directories(out);
    std::ofstream(out / "thesis.txt") << "years of work\n";

    const Result result = run(options_for(out, 1, 0));
    CHECK(result.status == 2);  // refused, as every other bad option is
    CHECK(is_one_line(result.err));
    CHECK_THAT(result.err, Catch::Contains("important"));
    CHECK(names_in(out) == std::vector<std::string>{"thesis.txt"});
    CHECK(names_in(temp.path) == std::vector<std::string>{"important"});

    SECTION("and so is a file in the folder's place") {
        const fs::path file = temp.path / "file.png";
        std::ofstream(file) << "x";
        CHECK(run(options_for(file, 1, 0)).status == 2);
        CHECK(fs::is_regular_file(file));
    }
    SECTION("and so is a symbolic link in the folder's place, even to a run's folder") {
        REQUIRE(run(options_for(temp.path / "real", 1, 0)).status == 0);
        fs::create_directory_symlink(temp.path / "real", temp.path / "link");
        CHECK(run(options_for(temp.path / "link", 1, 0)).status == 2);
        CHECK(fs::is_symlink(temp.path / "link"));
    }
    SECTION("and so are the current and parent folders") {
        CHECK(run(options_for(".", 1, 0)).status == 2);
        CHECK(run(options_for("..", 1, 0)).status == 2);
    }
}

TEST_CASE("browser: a failing page script leaves no staging folder") {
    ScratchFolder temp("browser_test");
    const fs::path out = temp.path / "out";
    browser::Window window(10.0, browser::Document{browser::Canvas(10, 10), ""});
    ThrowingScripts scripts;
    CHECK_THROWS_AS(browser::run(scripts, window, options_for(out, 2, 1)), std::runtime_error);
    CHECK(fs::is_empty(temp.path));
}

TEST_CASE("browser: staging folders of runs that are gone are removed; a living run's and strangers' stay") {
    ScratchFolder temp("browser_test");
    const fs::path out = temp.path / "out";
    // A process id that names no process: one past the largest the kernel hands out.
    const std::string gone = "4194305";
    fs::create_directories(temp.path / ("out.partial-" + gone));
    fs::create_directories(temp.path / ("out.old-" + gone));
    fs::create_directories(temp.path / "out.partial-1");                // init's: alive
    fs::create_directories(temp.path / ("out.partial-" + gone + "x"));  // not a process id: not ours
    std::ofstream(temp.path / ("final.png.partial-" + gone)) << "x";    // another target's: not this one's
    REQUIRE(run(options_for(out, 1, 0)).status == 0);
    CHECK(names_in(temp.path) ==
          std::vector<std::string>{"final.png.partial-" + gone, "out", "out.partial-1", "out.partial-" + gone + "x"});
}

namespace {

// The cost a stage's world reports for `shapes` shapes, 15 passes over their pairs a
// 1/60 s step, each pair holding `bytes` (the stages' page_world.cpp says this for itself).
browser::WorldCost costOf(double shapes, double bytes = 100.0) {
    const double pairs = shapes * (shapes - 1) / 2;
    return {.step_work = 15 * pairs + shapes,
            .bytes = pairs * bytes,
            .objects = shapes,
            .objects_word = "shapes",
            .work_word = "pair tests",
            .memory_word = "of contacts",
            .lighter = "passes"};
}

class QuietScripts : public browser::PageScripts {
public:
    void onKeyDown(Key) override {}
    void onAnimationFrame() override {}
};

}  // namespace

TEST_CASE("browser: the work bound counts the steps, each step's work and each frame's") {
    browser::Options options = options_for("unused", 10, 0);
    options.frame_ms = 1000.0 / 60.0;
    // 10 frames of one 1/60 s step each, plus the one the clock's rounding may add: 11 steps.
    CHECK(browser::work_bound({.step_work = 685}, options) == 11.0 * 685);
    // dt = 1/600 s runs ten steps a frame.
    CHECK(browser::work_bound({.step_s = 1.0 / 600.0, .step_work = 220}, options) == 101.0 * 220);
    // A page that draws its world's work every frame.
    CHECK(browser::work_bound({.step_work = 685, .frame_work = 45000}, options) == 11.0 * 685 + 10 * 45000);
    // A page that says nothing costs nothing but its pixels.
    CHECK(browser::work_bound({}, options) == 0);
}

TEST_CASE("browser: a run over its budget is refused with status 2 before anything is written") {
    ScratchFolder temp("browser_test");
    const fs::path out = temp.path / "out";
    struct Case {
        browser::WorldCost cost;
        int frames;
        int width, height, scale;
        const char* says;
    };
    const Case cases[] = {
        // 2,500 shapes: 3.1e6 pairs, 15 passes, 108 steps: 5.05e9 pair tests, in the stage's words.
        {costOf(2500), 107, 40, 30, 1,
         "the run is too long: 107 frames of up to 2500 shapes may cost 5.06e+09 pair tests, more than the 5e+09 a "
         "run may (fewer --frames, key presses, shapes, passes)"},
        // A world that says nothing of what makes it cheaper, nor names its objects.
        {{.step_work = 5e7},
         100,
         40,
         30,
         1,
         "the run is too long: 100 frames of up to 0 objects may cost 5.05e+09 units of work, more than the 5e+09 a "
         "run may (fewer --frames, key presses or objects)"},
        // 785 shapes all in contact at 1,300 bytes a pair: 400.04 MB; one fewer fits (below).
        {costOf(785, 1300), 1, 40, 30, 1,
         "the run may need too much memory: up to 785 shapes may hold 400 MB of contacts, more than the 400 MB a run "
         "may (fewer shapes or key presses that add them)"},
        // The page is the canvas and the 380 px panel beside it: (4096 + 380) x 2 wide.
        {{}, 1, 4096, 4096, 2, "the page is too large: 8952 x 8192 device pixels (the canvas and the 380 px panel"},
        {{}, 1, 3717, 4096, 1, "the page is too large: 4097 x 4096 device pixels"},
        // A page of 4096 x 4096 px, 29,803 frames: 5.0e11 pixels drawn.
        {{}, 29803, 3716, 4096, 1, "the run is too long: 29803 frames of 1.68e+07 device pixels draw 5e+11 pixels"},
    };
    for (const Case& c : cases) {
        INFO(c.says);
        browser::Options options = options_for(out, c.frames, 0);
        options.frame_ms = 1000.0 / 60.0;
        options.scale = c.scale;
        browser::Window window(options, browser::Document{browser::Canvas(c.width, c.height), ""});
        QuietScripts scripts;
        const test::CapturedOutput captured;
        const int status = browser::run(scripts, window, options, c.cost);
        const std::string err = captured.err();
        CHECK(status == 2);
        CHECK(is_one_line(err));
        CHECK_THAT(err, Catch::StartsWith(c.says));
        CHECK(fs::is_empty(temp.path));
    }
    // Inside the budget: 100 frames, 101 steps, 4.7e9 pair tests; 784 shapes, 399 MB (never run here).
    browser::Options inside = options_for(out, 100, 0);
    inside.frame_ms = 1000.0 / 60.0;
    CHECK(browser::work_bound(costOf(2500), inside) <= browser::kMaxWork);
    CHECK(costOf(784, 1300).bytes <= browser::kMaxWorldBytes);
}

TEST_CASE("browser: the encoding bound counts each saved page, its place on the sheet, and GIF frames at a tenth") {
    // 10 frames, every 5th saved (0 and 5): final.png and 2 pictures, each also a quarter
    // page on the contact sheet; a GIF of every 2nd frame: 5 frames at a tenth of a PNG's cost.
    browser::Options options = options_for("unused", 10, 5);
    CHECK(browser::encoding_bound(1000.0, options) == 1000.0 * (1 + 2 * 1.25));
    options.gif = true;
    options.gif_every = 2;
    CHECK(browser::encoding_bound(1000.0, options) == 1000.0 * (1 + 2 * 1.25 + 5 * 0.1));
}

TEST_CASE("browser: the names of a run's own files") {
    for (const char* name : {"final.png", "contact_sheet.png", "animation.gif", "animation.gif.partial",
                             "frame_0000.png", "frame_10000.png"}) {
        CHECK(browser::is_picture_name(name));
    }
    for (const char* name : {"frame_.png", "frame_00a0.png", "final.png.tmp", "dump.csv", ".manifest", "Final.png"}) {
        CHECK_FALSE(browser::is_picture_name(name));
    }
}
