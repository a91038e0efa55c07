#include "browser.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <iostream>
#include <memory>
#include <new>
#include <optional>
#include <stdexcept>
#include <vector>

#include "contact_sheet.h"
#include "gif_writer.h"
#include "live.h"
#include "interruption.h"
#include "live_window.h"
#include "message_text.h"
#include "output_folder.h"
#include "png_io.h"

namespace browser {
namespace {

namespace fs = std::filesystem;

std::string frame_picture_name(int frame) {
    char name[32];
    std::snprintf(name, sizeof name, "frame_%04d.png", frame);
    return name;
}

std::string sheet_label(int frame, bool last) {
    std::string label = "frame ";
    label += std::to_string(frame);
    if (last) label += " (final)";
    return label;
}

// Everything a run writes into the staging folder, frame by frame: the saved pages,
// final.png, the contact sheet and the GIF. A frame's page is drawn once at most,
// however many of them want it, and only when one does.
class Recorder {
public:
    Recorder(const Options& options, fs::path folder) : options_(options), folder_(std::move(folder)) {
        if (options.every > 0) {
            sheet_frames_ = contact_sheet_frames(options.frames - options.from, options.every);
            for (int& frame : sheet_frames_) frame += options.from;
            sheet_.emplace(static_cast<int>(sheet_frames_.size()), options.scale);
        }
    }

    // Called after animation frame k (0 to options.frames - 1) has run. Counting starts
    // at options.from: frames before it are never drawn.
    void after_frame(int k, const Document& document) {
        const int shown = k - options_.from;
        if (shown < 0) return;
        const bool last = k == options_.frames - 1;
        const bool saved = options_.every > 0 && shown % options_.every == 0;
        const bool on_sheet = next_on_sheet_ < sheet_frames_.size() && sheet_frames_[next_on_sheet_] == k;
        const bool in_gif = options_.gif && shown % options_.gif_every == 0;
        if (!last && !saved && !on_sheet && !in_gif) return;

        const Image page = render_page(document);
        if (saved) {
            frame_names_.push_back(frame_picture_name(k));
            write_png(folder_ / frame_names_.back(), page);
        }
        if (last) write_png(folder_ / kFinalPicture, page);
        if (on_sheet) {
            sheet_->add(page, sheet_label(k, last));
            ++next_on_sheet_;
        }
        if (in_gif) {
            if (!gif_) {
                const int delay_cs = gif_delay_centiseconds(options_.frame_ms, options_.gif_every);
                gif_ = std::make_unique<GifWriter>(folder_ / kUnfinishedAnimation, page.width, page.height, delay_cs);
            }
            gif_->add(page);
        }
    }

    // Called after the last frame: writes what needed the whole run.
    void finish() {
        if (sheet_) write_png(folder_ / kContactSheet, sheet_->picture());
        if (gif_) {
            gif_->close();
            fs::rename(folder_ / kUnfinishedAnimation, folder_ / kAnimation);
        }
    }

    // The one line a successful run prints, e.g. "wrote 3 pictures to out/<id>/
    // (final.png, frame_0000.png, frame_0030.png), contact_sheet.png and
    // animation.gif (30 frames)".
    std::string summary(const fs::path& out) const {
        const std::size_t pictures = frame_names_.size() + 1;
        std::string text = "wrote ";
        text += std::to_string(pictures);
        text += pictures == 1 ? " picture to " : " pictures to ";
        text += (out / "").string();
        text += " (";
        text += kFinalPicture;
        if (frame_names_.size() == 1) text += ", " + frame_names_.front();
        if (frame_names_.size() == 2) text += ", " + frame_names_.front() + ", " + frame_names_.back();
        if (frame_names_.size() > 2) text += ", " + frame_names_.front() + " ... " + frame_names_.back();
        text += ")";

        std::vector<std::string> others;
        if (sheet_) others.emplace_back(kContactSheet);
        if (gif_) {
            std::string gif = kAnimation;
            gif += " (";
            gif += std::to_string(gif_->pictures());
            gif += gif_->pictures() == 1 ? " frame)" : " frames)";
            others.push_back(gif);
        }
        for (std::size_t i = 0; i < others.size(); ++i) {
            text += i + 1 < others.size() ? ", " : " and ";
            text += others[i];
        }
        return text;
    }

private:
    const Options& options_;
    fs::path folder_;
    std::vector<std::string> frame_names_;
    std::vector<int> sheet_frames_;  // ascending frame numbers
    std::size_t next_on_sheet_ = 0;  // index into sheet_frames_
    std::optional<ContactSheet> sheet_;
    std::unique_ptr<GifWriter> gif_;
};

std::string out_of_memory_text() {
    return "out of memory: the run needs more memory than this machine gives it (fewer objects, frames or "
           "pictures, or a smaller canvas); nothing was written";
}

// How the budget's figure reads in a message: "3.21e+10".
std::string rounded(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3g", value);
    return text;
}

// "1 frame", "480 frames".
std::string frames_text(int frames) { return std::to_string(frames) + (frames == 1 ? " frame" : " frames"); }

// The pixels of one saved page: the canvas and the echo panel, times --scale each way.
double page_pixels(const Canvas& canvas) {
    return static_cast<double>(canvas.width() + kPanelWidth) * canvas.scale() * static_cast<double>(canvas.height()) *
           canvas.scale();
}

// How many of `frames` frames are taken when every `every`-th is, from the first on.
double frames_taken(int frames, int every) { return every > 0 ? static_cast<double>((frames - 1) / every + 1) : 0.0; }

std::optional<std::string> page_excess(const Canvas& canvas) {
    if (page_pixels(canvas) <= kMaxDevicePixels) return std::nullopt;
    const int scale = canvas.scale();
    return "the page is too large: " + std::to_string((canvas.width() + kPanelWidth) * scale) + " x " +
           std::to_string(canvas.height() * scale) + " device pixels (the canvas and the " +
           std::to_string(kPanelWidth) + " px panel beside it) at --scale " + std::to_string(scale) +
           ", more than the " + std::to_string(static_cast<long>(kMaxDevicePixels)) +
           " a page may have (a smaller canvas or --scale)";
}

std::optional<std::string> drawing_excess(const Canvas& canvas, const Options& options) {
    const double drawn = page_pixels(canvas) * options.frames;
    if (drawn <= kMaxPixelsDrawn) return std::nullopt;
    return "the run is too long: " + frames_text(options.frames) + " of " + rounded(page_pixels(canvas)) +
           " device pixels draw " + rounded(drawn) + " pixels, more than the " + rounded(kMaxPixelsDrawn) +
           " a run may (fewer --frames, a smaller canvas or --scale)";
}

std::optional<std::string> work_excess(const WorldCost& cost, const Options& options) {
    const double work = work_bound(cost, options);
    if (work <= kMaxWork) return std::nullopt;
    std::string cheaper = "fewer --frames, key presses";
    cheaper += cost.lighter.empty() ? " or " + cost.objects_word : ", " + cost.objects_word + ", " + cost.lighter;
    return "the run is too long: " + frames_text(options.frames) + " of up to " +
           std::to_string(std::lround(cost.objects)) + " " + cost.objects_word + " may cost " + rounded(work) + " " +
           cost.work_word + ", more than the " + rounded(kMaxWork) + " a run may (" + cheaper + ")";
}

std::optional<std::string> memory_excess(const WorldCost& cost) {
    if (cost.bytes <= kMaxWorldBytes) return std::nullopt;
    std::string held = std::to_string(std::lround(cost.bytes / 1e6)) + " MB";
    if (!cost.memory_word.empty()) held += " " + cost.memory_word;
    return "the run may need too much memory: up to " + std::to_string(std::lround(cost.objects)) + " " +
           cost.objects_word + " may hold " + held + ", more than the " +
           std::to_string(std::lround(kMaxWorldBytes / 1e6)) + " MB a run may (fewer " + cost.objects_word +
           " or key presses that add them)";
}

std::optional<std::string> encoding_excess(const Canvas& canvas, const Options& options) {
    const double pixels = encoding_bound(page_pixels(canvas), options);
    if (pixels <= kMaxPixelsEncoded) return std::nullopt;
    return "the run is too long: its pictures and GIF frames may cost " + rounded(pixels) +
           " pixels to encode, more than the " + rounded(kMaxPixelsEncoded) +
           " a run may (a larger --every or --gif-every, --no-gif, a smaller canvas or --scale)";
}

// Why a run goes over its budget, in one line, or nothing when it does not: the first
// limit it passes, in the order of browser.h.
std::optional<std::string> over_budget(const WorldCost& cost, const Canvas& canvas, const Options& options) {
    if (auto excess = page_excess(canvas)) return excess;
    if (auto excess = drawing_excess(canvas, options)) return excess;
    if (auto excess = work_excess(cost, options)) return excess;
    if (auto excess = memory_excess(cost)) return excess;
    return encoding_excess(canvas, options);
}

}  // namespace

double work_bound(const WorldCost& cost, const Options& options) {
    const double run_ms = static_cast<double>(options.frames) * options.frame_ms;
    const double steps = std::floor(run_ms / (cost.step_s * 1000.0)) + 1.0;
    return steps * cost.step_work + static_cast<double>(options.frames) * cost.frame_work;
}

double encoding_bound(double page_pixels, const Options& options) {
    // The contact sheet holds every saved page at a quarter of its pixels or less.
    const int shown = options.frames - options.from;
    const double pictures = 1.0 + frames_taken(shown, options.every) * 1.25;
    const double gif_frames = options.gif ? frames_taken(shown, options.gif_every) : 0.0;
    return page_pixels * (pictures + kGifPixelCost * gif_frames);
}

int run(PageScripts& scripts, Window& window, const Options& options, const WorldCost& cost) {
    // parse_command_line never gives these; a test or a stage that builds Options by hand might.
    if (options.frames < 1 || (options.gif && options.gif_every < 1) || options.from < 0 ||
        options.from >= options.frames) {
        throw std::invalid_argument(
            "browser::run: options.frames and options.gif_every must be at least 1, options.from below options.frames");
    }
    // A stage that made its window without the options would draw --scale K at scale 1.
    if (window.document.canvas.scale() != options.scale) {
        throw std::invalid_argument(
            "browser::run: the window's canvas scale is not options.scale (make it with Window(options))");
    }
    if (options.live.on) {
        note_interruptions();  // a live session ends by SIGINT or SIGTERM as a run does
        try {
            const std::unique_ptr<Screen> screen = open_live_window({.title = options.live.title,
                                                                     .frame_ms = options.frame_ms,
                                                                     .events = options.live.events,
                                                                     .screenshot = options.live.screenshot});
            return run_live(scripts, window, options, *screen);
        } catch (const LiveWindowError& error) {
            std::cerr << error.what() << '\n';
            return 1;
        } catch (const std::bad_alloc&) {
            std::cerr << out_of_memory_text() << '\n';
            return kOutOfMemoryStatus;
        }
    }
    if (options.gif && !gif_supported()) {
        std::cerr << kNoGifSupport << '\n';
        return 2;
    }
    if (const std::optional<std::string> excess = over_budget(cost, window.document.canvas, options)) {
        std::cerr << *excess << '\n';
        return 2;
    }
    Document& document = window.document;
    Clock& clock = window.clock;
    const fs::path out = OutputFolder::normalized(options.out_dir);
    std::string reason;
    try {
        OutputFolder folder(out, files_read(options));
        Recorder recorder(options, folder.staging());
        for (int k = 0; k < options.frames; ++k) {
            clock.advanceFrame();
            for (const Key key : options.keys.pressesAt(k)) press_key(scripts, window, options, key);
            for (const PointerEvent& event : options.keys.pointerAt(k)) scripts.onPointer(event);
            scripts.onAnimationFrame();
            recorder.after_frame(k, document);
            stop_if_interrupted();
        }
        recorder.finish();
        folder.commit();
        std::cout << recorder.summary(out) << '\n';
        return 0;
    } catch (const OutputRefused& error) {
        std::cerr << "cannot write pictures to " << in_quotes(out.string()) << ": " << error.what() << '\n';
        return 2;
    } catch (const FileError& error) {
        reason = error.what();
    } catch (const fs::filesystem_error& error) {
        reason = error.code().message();
    } catch (const std::bad_alloc&) {
        std::cerr << out_of_memory_text() << '\n';
        return kOutOfMemoryStatus;
    }
    // A failing page script is not ours to report: its exception goes on, and the
    // output folder's staging folder is gone all the same.
    std::cerr << "cannot write pictures to " << in_quotes(out.string()) << ": " << printable(reason) << '\n';
    return 1;
}

}  // namespace browser
