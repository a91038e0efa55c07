#pragma once
// The browser session: it gives the page's scripts a window (the document with its
// canvas and echo panel, and the clock behind Date.now()), presses the scripted keys,
// calls the scripts back every animation frame, and saves the page as PNG pictures.
// The page's side of it (Window, PageScripts) is page_scripts.h, which the live session
// (live.h) shares: it plays the same page, and browser::run hands it over with --live.

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>
#include <utility>

#include "command_line.h"
#include "page_scripts.h"

namespace browser {

// What a page's world may cost over a run, for its budget: only the stage knows what
// its world does, so it counts its own work (its page_world.cpp) and the browser adds it
// up. Work is counted in units of about 45 ns of one core, in the stage's own words (a
// pair test, in this book's stages); with n objects at most, a fixed step costs
// step_work units and holds `bytes` of memory, and drawing a frame costs frame_work
// units beyond clearing its pixels. A page that says nothing costs nothing but its
// pixels.
struct WorldCost {
    double step_s = 1.0 / 60.0;  // the fixed step: a run makes floor(frames x frame_ms / step) + 1 of them
    double step_work = 0.0;
    double frame_work = 0.0;
    double bytes = 0.0;
    double objects = 0.0;  // the most objects the world may hold: at the start, and what key presses add
    // The stage's words, for a refusal: what it calls its objects and a unit of its work,
    // what its memory holds, and what makes a step cheaper.
    std::string objects_word = "objects";
    std::string work_word = "units of work";
    std::string memory_word;  // after "may hold 120 MB ": "of contacts (all of them in contact)"
    std::string lighter;      // after "(fewer --frames, key presses, <objects_word>, ": "passes or sub-steps"
};

// The budget of a run, so that every run fits in memory and ends in minutes
// (docs/scene_format.md, "Limits", has the worst case measured):
//  - the page's device pixels (canvas size times --scale, each way): 64 MiB a picture;
//  - the pixels drawn over the whole run, frames times device pixels, as every frame
//    clears and draws the whole canvas;
//  - the world's work over the whole run (work_bound);
//  - the memory the world may hold (WorldCost::bytes);
//  - the pixels encoded into PNG pictures and GIF frames (encoding_bound).
inline constexpr double kMaxDevicePixels = 4096.0 * 4096.0;
inline constexpr double kMaxPixelsDrawn = 5e11;
inline constexpr double kMaxWork = 5e9;
inline constexpr double kMaxWorldBytes = 400e6;
inline constexpr double kMaxPixelsEncoded = 2e9;
// A pixel of a GIF frame costs about a tenth of a pixel of a PNG picture to encode
// (measured at --scale 4: 11 ns against 110 ns; stb's PNG encoder tries every filter).
inline constexpr double kGifPixelCost = 0.1;

// The work of a run at most: its fixed steps (frames x frame_ms / step_s, plus one)
// times the work of a step, and its frames times the work of drawing one.
double work_bound(const WorldCost& cost, const Options& options);

// The pixels a run encodes, in PNG pixels: final.png, the frame_NNNN.png pictures and the
// contact sheet, and kGifPixelCost for each pixel of each GIF frame. `page_pixels` is the
// size of one saved page (the canvas and the echo panel beside it, times --scale squared).
double encoding_bound(double page_pixels, const Options& options);

// The exit status of a run that ran out of memory although its budget let it start (a
// machine with less memory than the budget allows for): one line on stderr, nothing written.
inline constexpr int kOutOfMemoryStatus = 4;

// Runs options.frames (>= 1) frames. Before frame k the clock advances by one frame,
// the keys scripted for frame k are pressed, the pointer does what the script's drags do
// before it (pointer.h), then the animation frame runs. The page is
// saved as frame_NNNN.png after every K-th frame (options.every, k % K == 0) and as
// final.png after the last one. With K > 0, contact_sheet.png shows those pages and the
// last one small in a grid (contact_sheet.h). With options.gif, animation.gif gets the
// page after every N-th frame (options.gif_every, k % N == 0: ceil(frames / N) GIF
// frames, each shown for N frames' time). Everything is written into a fresh folder
// that replaces options.out_dir only when the run succeeded, so a failed run never
// leaves a half-written folder.
// Returns the exit status: 0; 1 with a one-line message on stderr when the pictures
// cannot be written; 2 with one line, before anything is written, when the run is
// refused: options.gif asks for a GIF that this build cannot write (build_features.h's
// kNoGifSupport), options.out_dir may not be replaced (output_folder.h), or the run
// would go over its budget (kMaxDevicePixels to kMaxPixelsEncoded, with `cost` the
// page's world's); kOutOfMemoryStatus
// with one line when memory runs out all the same.
// SIGINT and SIGTERM end a run after the frame they come in, with the staging folder
// and every partial file removed (interruption.h).
// With options.live.on it plays the page in a window instead (live.h), writing no
// pictures: 0 when the reader closes it, 1 with one line when no window can be opened
// (no display named at all, live_window.h) or the recorded key script or screenshot
// cannot be written, 2 when --record names a place write_guard.h refuses; SIGINT and
// SIGTERM end it as they end a run.
int run(PageScripts& scripts, Window& window, const Options& options, const WorldCost& cost = {});

}  // namespace browser
