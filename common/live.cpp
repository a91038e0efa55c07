#include "live.h"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <optional>
#include <string>
#include <system_error>

#include "build_features.h"  // gif_supported
#include "interruption.h"
#include "message_text.h"
#include "page.h"
#include "png_io.h"  // FileError, OutputRefused
#include "write_guard.h"

namespace browser {
namespace {

namespace fs = std::filesystem;

// Seconds with two decimals, for the reader's eye ("0.68").
std::string seconds_text(double seconds) {
    char text[32];
    std::snprintf(text, sizeof text, "%.2f", seconds);
    return text;
}

// A word as a POSIX shell reads it back: bare when it holds only characters the shell
// takes literally, else in single quotes (a quote inside written as '\'').
std::string shell_word(const std::string& word) {
    const bool plain = !word.empty() && word.find_first_not_of(
                                            "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ"
                                            "0123456789_-+=./,:@%") == std::string::npos;
    if (plain) return word;
    std::string quoted = "'";
    for (const char c : word) {
        if (c == '\'') quoted += "'\\''";
        else quoted += c;
    }
    return quoted + "'";
}

// The one command that replays a recorded session into pictures and a GIF, from the
// frame of its first key press on (-1: none).
std::string replay_command(const LiveOptions& live, int frames, int first_press) {
    std::string command;
    for (const std::string& word : live.replay_command) {
        if (!command.empty()) command += ' ';
        command += shell_word(word);
    }
    command += " --keys \"$(cat " + shell_word(live.record.string()) + ")\"";
    command += " --frames " + std::to_string(frames);
    if (first_press > 0) command += " --from " + std::to_string(first_press);
    command += " --every " + std::to_string(live.replay_every);
    if (live.replay_gif) command += " --gif";
    return command;
}

// Writes the script beside its place and renames it in, so a reader never finds half
// a script. Throws FileError with a one-line reason.
void write_script(const fs::path& file, const std::string& text) {
    fs::path partial = file;
    partial += ".partial" + process_suffix();
    {
        std::ofstream out(partial, std::ios::binary | std::ios::trunc);
        out << text << '\n';
        out.close();
        if (!out) {
            std::error_code ignored;
            fs::remove(partial, ignored);
            throw FileError("cannot write it");
        }
    }
    std::error_code error;
    try {
        check_may_write(file, WriteTarget::file);  // again: the name may lead elsewhere by now
    } catch (const OutputRefused& refused) {
        fs::remove(partial, error);
        throw FileError(refused.what());
    }
    fs::rename(partial, file, error);
    if (error) {
        std::error_code ignored;
        fs::remove(partial, ignored);
        throw FileError(error.message());
    }
}

// Why the recorded script may not go to `file`, if it may not: the place must pass
// write_guard.h's rule, and its folder must be there before the session starts, or the
// reader would only learn at the end that it cannot be kept.
std::optional<std::string> record_refused(const fs::path& file, const Options& options) {
    try {
        check_may_write(file, WriteTarget::file, files_read(options));
    } catch (const OutputRefused& refused) {
        return refused.what();
    }
    const fs::path folder = file.parent_path();
    std::error_code error;
    if (!folder.empty() && !fs::is_directory(folder, error)) return "its folder does not exist";
    return std::nullopt;
}

class LiveSession {
public:
    LiveSession(PageScripts& scripts, Window& window, const Options& options)
        : scripts_(scripts), window_(window), options_(options) {}

    // Runs frame `frames_run()`: the clock moves on one frame, the scripted keys and
    // then the waiting ones are pressed, and the animation frame runs.
    void runFrame() {
        const int frame = frames_run_;
        window_.clock.advanceFrame();
        for (const Key key : options_.keys.pressesAt(frame)) press(frame, key);
        for (const Key key : waiting_) press(frame, key);
        waiting_.clear();
        for (const PointerEvent& event : options_.keys.pointerAt(frame)) scripts_.onPointer(event);
        recordScriptedDrag(frame);
        movePointer(frame);
        scripts_.onAnimationFrame();
        page_ = render_page(window_.document);
        ++frames_run_;
    }

    // Takes in what the reader did; false when they ended the session.
    bool take(const std::vector<LiveInput>& inputs) {
        for (const LiveInput& input : inputs) {
            switch (input.kind) {
                case LiveInput::Kind::End: return false;
                case LiveInput::Kind::Pause: paused_ = !paused_; break;
                case LiveInput::Kind::Step:
                    if (paused_) ++steps_;
                    break;
                case LiveInput::Kind::Screenshot: saveShownPage(); break;
                case LiveInput::Kind::PointerPress:
                    if (const auto point = onCanvas(input, false); point && !drag_ && !press_) press_ = point;
                    break;
                case LiveInput::Kind::PointerMove: pointer_ = *onCanvas(input, true); break;
                case LiveInput::Kind::PointerRelease:
                    pointer_ = *onCanvas(input, true);
                    if (drag_ || press_) release_ = true;
                    break;
                case LiveInput::Kind::PageKey:
                    if (options_.stage_keys.empty() || options_.stage_keys.contains(input.key)) {
                        waiting_.push_back(input.key);
                    }
                    break;
            }
        }
        return true;
    }

    // One refresh of the display: the next frame runs unless the session is paused
    // (a step asked for while paused runs one). A key script cannot name a frame past
    // KeyScript::kMaxFrame, so a session stops there (after about 46 hours at 60 Hz).
    void refresh() {
        if (notice_refreshes_ > 0 && --notice_refreshes_ == 0) notice_.clear();
        if (frames_run_ >= KeyScript::kMaxFrame) return;
        if (!paused_) {
            runFrame();
        } else if (steps_ > 0) {
            --steps_;
            runFrame();
        }
    }

    // The session is over: a drag still held is recorded up to its last frame.
    void finish() {
        if (drag_) recorded_.drag(std::move(*drag_));
        drag_.reset();
    }
    int drags() const { return static_cast<int>(recorded_.drags().size()); }

    Image picture() const { return with_status_line(page_, status(), window_.document.canvas.scale()); }
    int framesRun() const { return frames_run_; }
    const KeyScript& recorded() const { return recorded_; }
    int presses() const { return presses_; }
    bool screenshotFailed() const { return screenshot_failed_; }

private:
    // The page the reader is looking at, as the replay names that frame's picture, with
    // the stage's id in front so that screenshots of several stages can share a folder.
    void saveShownPage() {
        const int frame = frames_run_ - 1;
        char name[48];
        std::snprintf(name, sizeof name, "%s_frame_%04d.png", options_.live.stage_id.c_str(), frame);
        const fs::path file = options_.live.screenshot_folder / name;
        try {
            check_may_write(file, WriteTarget::file, files_read(options_));
            write_png(file, page_);
            std::cout << "F12: saved frame " << frame << " to " << file.string() << '\n';
            notice_ = std::string("F12: saved ") + name;
        } catch (const FileError& error) {
            std::cerr << "F12: cannot save frame " << frame << " to " << in_quotes(file.string()) << ": "
                      << printable(error.what()) << '\n';
            notice_ = std::string("F12: cannot save ") + name + " (see the terminal)";
            screenshot_failed_ = true;
        }
        notice_refreshes_ = kNoticeRefreshes;
    }

    // The picture's point as a canvas point, whole px (its top-left corner is the
    // canvas's, --scale device pixels a px); outside the canvas, nothing, or with
    // `held`, the nearest canvas point.
    std::optional<PointerPoint> onCanvas(const LiveInput& input, bool held) const {
        const Canvas& canvas = window_.document.canvas;
        const int scale = canvas.scale();
        // Floor, not truncation: -1 device px is outside, not at 0.
        const auto floor_div = [scale](int v) { return v >= 0 ? v / scale : -((-v + scale - 1) / scale); };
        PointerPoint point{floor_div(input.x), floor_div(input.y)};
        const bool inside = point.x >= 0 && point.y >= 0 && point.x < canvas.width() && point.y < canvas.height();
        if (!inside && !held) return std::nullopt;
        point.x = std::clamp(point.x, 0, canvas.width() - 1);
        point.y = std::clamp(point.y, 0, canvas.height() - 1);
        return point;
    }

    // Before frame `frame` the pointer does what the reader did since the last frame:
    // the drag under way lets go, or follows the pointer one point more; then a press
    // waiting starts a new one. Each event comes from the drag itself (Drag::eventAt),
    // as in the replay, so the two cannot tell the page different things.
    void movePointer(int frame) {
        if (drag_ && release_) {
            deliver(*drag_, frame);
            recorded_.drag(std::move(*drag_));
            drag_.reset();
            release_ = false;
        } else if (drag_) {
            drag_->points.push_back(pointer_);
            deliver(*drag_, frame);
        }
        if (press_ && frame > scripted_until_) {
            drag_ = Drag{frame, {*press_}};
            pointer_ = *press_;
            press_.reset();
            deliver(*drag_, frame);
        }
    }

    // A drag of --keys starting at `frame` is recorded as its keys are, so the replay has
    // it too; the reader's pointer waits while it is under way.
    void recordScriptedDrag(int frame) {
        for (const Drag& scripted : options_.keys.drags()) {
            if (scripted.frame > frame) break;
            if (frame <= scripted.releaseFrame()) scripted_until_ = scripted.releaseFrame();
            if (scripted.frame != frame || drag_) continue;  // the reader's, under way, is recorded instead
            recorded_.drag(scripted);
        }
    }

    void deliver(const Drag& drag, int frame) {
        if (const auto event = drag.eventAt(frame)) scripts_.onPointer(*event);
    }

    void press(int frame, Key key) {
        press_key(scripts_, window_, options_, key);
        recorded_.press(frame, key);
        ++presses_;
    }

    // "frame 41 (0.68 s)   F12: save page   Space: pause   Esc: end", or while paused
    // "paused after frame 41 (0.68 s)   waiting: f g   F12: save page   period: one frame
    // Space: go on   Esc: end", with "F12: saved <id>_frame_0041.png" for a while after F12.
    std::string status() const {
        const int shown = frames_run_ - 1;
        const double seconds = frames_run_ * options_.frame_ms / 1000.0;
        std::string text = paused_ ? "paused after frame " : "frame ";
        text += std::to_string(shown) + " (" + seconds_text(seconds) + " s)";
        if (!waiting_.empty()) {
            text += "   waiting:";
            for (const Key key : waiting_) text += ' ' + key_name(key);
        }
        if (!options_.live.record.empty()) text += "   recording";
        // What F12 did takes the place of its hint for a while: the line has room for one.
        text += "   " + (notice_.empty() ? std::string("F12: save page") : notice_);
        text += paused_ ? "   period: one frame   Space: go on   Esc: end" : "   Space: pause   Esc: end";
        return text;
    }

    PageScripts& scripts_;
    Window& window_;
    const Options& options_;
    Image page_;
    std::vector<Key> waiting_;  // pressed by the reader, for the next frame that runs
    KeyScript recorded_;
    std::optional<Drag> drag_;           // the reader's drag under way, its points so far
    std::optional<PointerPoint> press_;  // a press on the canvas, for the next frame that runs
    bool release_ = false;               // the button came up, for the next frame that runs
    int scripted_until_ = -1;            // the release frame of the last drag of --keys begun
    PointerPoint pointer_;               // where the pointer last was, held on the canvas
    int presses_ = 0;
    int frames_run_ = 0;
    bool paused_ = false;
    int steps_ = 0;
    // What F12 did, shown on the status line for a couple of seconds.
    static constexpr int kNoticeRefreshes = 120;
    std::string notice_;
    int notice_refreshes_ = 0;
    bool screenshot_failed_ = false;
};

}  // namespace

int run_live(PageScripts& scripts, Window& window, const Options& options, Screen& screen) {
    const fs::path& record = options.live.record;
    if (const auto refused = record.empty() ? std::nullopt : record_refused(record, options)) {
        std::cerr << "--record: cannot write " << in_quotes(record.string()) << ": " << *refused << '\n';
        return 2;
    }

    LiveSession session(scripts, window, options);
    session.runFrame();
    screen.show(session.picture());
    while (session.take(screen.nextFrame())) {
        session.refresh();
        screen.show(session.picture());
        stop_if_interrupted();  // a session with --dump notes Ctrl-C (interruption.h)
    }
    session.finish();
    try {
        screen.close();
    } catch (const FileError& error) {
        std::cerr << "--live-screenshot: " << error.what() << '\n';
        return 1;
    }

    const int frames = session.framesRun();
    const std::string seconds = seconds_text(frames * options.frame_ms / 1000.0);
    if (record.empty()) {
        std::cout << "played " << frames << (frames == 1 ? " frame" : " frames") << " (" << seconds
                  << " s); --record FILE keeps the key presses of a session to replay them\n";
        return session.screenshotFailed() ? 1 : 0;
    }
    const std::string script = session.recorded().text();
    try {
        write_script(record, script);
    } catch (const FileError& error) {
        std::cerr << "cannot write the key script to " << in_quotes(record.string()) << ": " << error.what()
                  << "; it was: " << script << '\n';
        return 1;
    }
    const int drags = session.drags();
    std::cout << "recorded " << session.presses() << (session.presses() == 1 ? " key press" : " key presses")
              << (drags == 0   ? ""
                  : drags == 1 ? " and 1 drag"
                               : " and " + std::to_string(drags) + " drags")
              << " in " << frames << (frames == 1 ? " frame" : " frames") << " (" << seconds << " s) to "
              << record.string() << "; replay them into pictures" << (gif_supported() ? " and a GIF" : "") << " with:\n"
              << "  " << replay_command(options.live, frames, session.recorded().firstFrame()) << '\n';
    return session.screenshotFailed() ? 1 : 0;
}

}  // namespace browser
