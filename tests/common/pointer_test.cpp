// The pointer (common/pointer.h): a drag in a key script, read and written back; the
// events a replay gives the page before each frame; and a live session on a stand-in
// screen whose drag, recorded, replays to the very same events before the very same
// frames, at --scale 1 and 2. The window itself (SDL's mouse) is tried by tests/live/.
#include <catch2/catch.hpp>

#include <deque>
#include <fstream>
#include <string>
#include <vector>

#include "browser.h"
#include "captured_output.h"
#include "keys.h"
#include "live.h"
#include "pointer.h"
#include "scratch_folder.h"

namespace pointer_test {

using browser::KeyScript;
using browser::LiveInput;
using browser::PointerEvent;
using Kind = browser::LiveInput::Kind;

namespace {

// A page that writes down every pointer event and key with the frame it came before:
// "press 10,5 @2; move 12,5 @3; ...".
class PointerLog : public browser::PageScripts {
public:
    void onKeyDown(browser::Key key) override { log += browser::key_name(key) + " @" + std::to_string(frame_) + "; "; }
    void onPointer(const PointerEvent& event) override {
        const char* kind = event.kind == PointerEvent::Kind::press  ? "press"
                           : event.kind == PointerEvent::Kind::move ? "move"
                                                                    : "release";
        log += std::string(kind) + " " + std::to_string(event.point.x) + "," + std::to_string(event.point.y) + " @" +
               std::to_string(frame_) + "; ";
    }
    void onAnimationFrame() override { ++frame_; }
    std::string log;

private:
    int frame_ = 0;
};

constexpr int kCanvasWidth = 60, kCanvasHeight = 40;

class BatchScreen : public browser::Screen {
public:
    explicit BatchScreen(std::vector<std::vector<LiveInput>> batches) : batches_(batches.begin(), batches.end()) {}
    void show(const browser::Image&) override {}
    std::vector<LiveInput> nextFrame() override {
        if (batches_.empty()) return {{Kind::End}};
        std::vector<LiveInput> batch = batches_.front();
        batches_.pop_front();
        return batch;
    }

private:
    std::deque<std::vector<LiveInput>> batches_;
};

LiveInput pointer(Kind kind, int x, int y) { return {.kind = kind, .x = x, .y = y}; }

struct Played {
    std::string log;
    std::string script;
};

// A live session of the logging page, its script recorded to `folder`.
Played play(const test::ScratchFolder& folder, std::vector<std::vector<LiveInput>> batches, int scale = 1) {
    browser::Options options;
    options.frame_ms = 10.0;
    options.scale = scale;
    options.stage_keys = browser::KeySet::parse("f");
    options.live.on = true;
    options.live.record = folder.path / "session.keys";
    options.live.replay_command = {"build/s9_9_test"};
    options.live.stage_id = "s9_9";
    browser::Window window(options.frame_ms, browser::Document{browser::Canvas(kCanvasWidth, kCanvasHeight), ""});
    window.document.canvas.setScale(scale);
    PointerLog page;
    BatchScreen screen(std::move(batches));
    Played played;
    {
        const test::CapturedOutput quiet;
        REQUIRE(browser::run_live(page, window, options, screen) == 0);
    }
    played.log = page.log;
    std::ifstream in(options.live.record);
    std::getline(in, played.script);
    return played;
}

// What a replay of `script` over `frames` frames gives the logging page.
std::string replayed(const test::ScratchFolder& folder, const std::string& script, int frames) {
    browser::Options options;
    options.out_dir = folder.path / "replay";
    options.frames = frames;
    options.every = 0;
    options.frame_ms = 10.0;
    options.keys = KeyScript::parse(script);
    browser::Window window(options.frame_ms, browser::Document{browser::Canvas(kCanvasWidth, kCanvasHeight), ""});
    PointerLog page;
    const test::CapturedOutput quiet;
    REQUIRE(browser::run(page, window, options) == 0);
    return page.log;
}

}  // namespace

TEST_CASE("pointer: a drag token is read into one point a frame and written back the same", "[pointer]") {
    const KeyScript script = KeyScript::parse("f@1 drag:10,5*3/12,5/12,6@2 g@9");
    REQUIRE(script.drags().size() == 1);
    const browser::Drag& drag = script.drags()[0];
    CHECK(drag.frame == 2);
    CHECK(drag.points.size() == 5);  // 3 + 1 + 1
    CHECK(drag.releaseFrame() == 7);
    CHECK(script.text() == "f@1 drag:10,5*3/12,5/12,6@2 g@9");
    CHECK(KeyScript::parse(script.text()) == script);
    CHECK(script.firstFrame() == 1);
    CHECK(script.lastFrame() == 9);
    // A token without @ takes the frame before it, as a key does; keys of a frame come
    // before its drag in the text.
    CHECK(KeyScript::parse("drag:1,1@4 h").text() == "h@4 drag:1,1@4");
}

TEST_CASE("pointer: a replay presses, moves where the pointer went and lets go, frame by frame", "[pointer]") {
    const KeyScript script = KeyScript::parse("drag:10,5*3/12,5/12,6@2");
    using PK = PointerEvent::Kind;
    CHECK(script.pointerAt(1).empty());
    CHECK(script.pointerAt(2) == std::vector<PointerEvent>{{PK::press, {10, 5}}});
    CHECK(script.pointerAt(3).empty());  // held still
    CHECK(script.pointerAt(4).empty());
    CHECK(script.pointerAt(5) == std::vector<PointerEvent>{{PK::move, {12, 5}}});
    CHECK(script.pointerAt(6) == std::vector<PointerEvent>{{PK::move, {12, 6}}});
    CHECK(script.pointerAt(7) == std::vector<PointerEvent>{{PK::release, {12, 6}}});
    CHECK(script.pointerAt(8).empty());
    // One drag let go before the frame the next is pressed at: the release first.
    const KeyScript two = KeyScript::parse("drag:1,1@0 drag:2,2@1");
    CHECK(two.pointerAt(1) == std::vector<PointerEvent>{{PK::release, {1, 1}}, {PK::press, {2, 2}}});
}

TEST_CASE("pointer: a bad drag is refused in one line naming the token", "[pointer]") {
    const auto refusal = [](const std::string& script) -> std::string {
        try {
            KeyScript::parse(script);
        } catch (const browser::KeyScriptError& error) {
            return error.what();
        }
        return "accepted";
    };
    CHECK(refusal("drag:@3").find("\"drag:@3\": a drag needs at least one point") != std::string::npos);
    CHECK(refusal("drag:1@3").find("a point must be X,Y") != std::string::npos);
    CHECK(refusal("drag:1,2/@3").find("a point must be X,Y") != std::string::npos);
    CHECK(refusal("drag:1.5,2").find("a point must be X,Y") != std::string::npos);
    CHECK(refusal("drag:1,2*0").find("*N must be") != std::string::npos);
    CHECK(refusal("drag:1,2@x").find("frame must be") != std::string::npos);
    CHECK(refusal("drag:1,2*3@5 drag:1,1@7").find("it starts before frame 8") != std::string::npos);
    CHECK(refusal("drag:1,2*600000/1,1*600000").find("more than 1000000 frames") != std::string::npos);
    CHECK(refusal("drag:1,2/3,-4@5") == "accepted");
}

TEST_CASE("pointer: a live drag is recorded as one token that replays to the same events", "[pointer]") {
    const test::ScratchFolder folder("pointer-live");
    // Refresh k's batch lands before frame k. Pressed at (10, 5) before frame 2, moved
    // twice between two frames (only where it ends counts), held still, let go.
    const Played played = play(folder, {{},
                                        {pointer(Kind::PointerPress, 10, 5)},
                                        {pointer(Kind::PointerMove, 11, 5), pointer(Kind::PointerMove, 14, 7)},
                                        {},
                                        {pointer(Kind::PointerRelease, 15, 7)},
                                        {{Kind::PageKey, browser::Key::F}},
                                        {}});
    CHECK(played.script == "drag:10,5/14,7*2@2 f@6");
    CHECK(played.log == "press 10,5 @2; move 14,7 @3; release 14,7 @5; f @6; ");
    CHECK(replayed(folder, played.script, 8) == played.log);
}

TEST_CASE("pointer: at --scale 2 the window's px are halved; a press off the canvas does nothing", "[pointer]") {
    const test::ScratchFolder folder("pointer-scale");
    const Played played = play(folder,
                               {{pointer(Kind::PointerPress, 500, 5)},  // on the echo panel
                                {pointer(Kind::PointerRelease, 500, 5)},
                                {pointer(Kind::PointerPress, 21, 11)},
                                {pointer(Kind::PointerMove, 300, -9)},  // off the canvas: held at its edge
                                {pointer(Kind::PointerRelease, 300, -9)},
                                {pointer(Kind::PointerPress, 2, 2), pointer(Kind::PointerRelease, 2, 2)},
                                {}},
                               2);
    CHECK(played.script == "drag:10,5/59,0@3 drag:1,1@6");
    CHECK(played.log == "press 10,5 @3; move 59,0 @4; release 59,0 @5; press 1,1 @6; release 1,1 @7; ");
    CHECK(replayed(folder, played.script, 8) == played.log);
}

}  // namespace pointer_test
