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

// The budget of a run, so that every run fits in memory and ends in minutes
// (docs/scene_format.md, "Limits", has the worst case measured):
//  - the page's device pixels (canvas size times --scale, each way): 64 MiB a picture;
//  - the pixels drawn over the whole run, frames times device pixels, as every frame
//    clears and draws the whole canvas;
//  - the pair tests of the whole run (pair_test_bound).
//  - the memory of the contacts of the most pairs the run can have (contact_memory_bound);
//  - the pixels encoded into PNG pictures and GIF frames (encoding_bound).
inline constexpr double kMaxDevicePixels = 4096.0 * 4096.0;
inline constexpr double kMaxPixelsDrawn = 5e11;
inline constexpr double kMaxPairTests = 5e9;
inline constexpr double kMaxContactBytes = 400e6;
inline constexpr double kMaxPixelsEncoded = 2e9;
// A pixel of a GIF frame costs about a tenth of a pixel of a PNG picture to encode
// (measured at --scale 4: 11 ns against 110 ns; stb's PNG encoder tries every filter).
inline constexpr double kGifPixelCost = 0.1;
// Drawing a pair's collision line costs about as much as this many pair tests (a line
// across a few hundred pixels against a separating-axis test, measured).
inline constexpr double kDrawnPairCost = 1000.0;

// An upper bound of the pair tests a run costs: its fixed steps (frames x frame_ms / dt,
// plus one) times sub-steps times passes times the pairs of the most shapes it can have
// (those at the start and one an F or G press), and for a page that draws its pairs,
// kDrawnPairCost a pair a frame.
double pair_test_bound(const StepCost& step, const Options& options);

// An upper bound of the bytes the contacts of a step can hold: the pairs of the most
// shapes the run can have, every one in contact, times step.bytes_a_contact.
double contact_memory_bound(const StepCost& step, const Options& options);

// The pixels a run encodes, in PNG pixels: final.png, the frame_NNNN.png pictures and the
// contact sheet, and kGifPixelCost for each pixel of each GIF frame. `page_pixels` is the
// size of one saved page (the canvas and the echo panel beside it, times --scale squared).
double encoding_bound(double page_pixels, const Options& options);

// The exit status of a run that ran out of memory although its budget let it start (a
// machine with less memory than the budget allows for): one line on stderr, nothing written.
inline constexpr int kOutOfMemoryStatus = 4;

// Runs options.frames (>= 1) frames. Before frame k the clock advances by one frame,
// the keys scripted for frame k are pressed, then the animation frame runs. The page is
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
// would go over its budget (kMaxDevicePixels to kMaxPixelsEncoded); kOutOfMemoryStatus
// with one line when memory runs out all the same.
// SIGINT and SIGTERM end a run after the frame they come in, with the staging folder
// and every partial file removed (interruption.h).
// With options.live.on it plays the page in a window instead (live.h), writing no
// pictures: 0 when the reader closes it, 1 with one line when no window can be opened
// (no display named at all, live_window.h) or the recorded key script or screenshot
// cannot be written, 2 when --record names a place write_guard.h refuses; SIGINT and
// SIGTERM end it as they end a run.
int run(PageScripts& scripts, Window& window, const Options& options);

}  // namespace browser
