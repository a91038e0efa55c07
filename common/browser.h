#pragma once
// The browser session: it gives the page's scripts a window (the document with its
// canvas and echo panel, and the clock behind Date.now()), presses the scripted keys,
// calls the scripts back every animation frame, and saves the page as PNG pictures.

#include <filesystem>
#include <string>
#include <utility>

#include "clock.h"
#include "command_line.h"
#include "keys.h"
#include "page.h"

namespace browser {

// What the page's scripts can reach: window.document and Date.now().
struct Window {
    explicit Window(double frame_ms, Document page = Document()) : document(std::move(page)), clock(frame_ms) {}
    // A stage's window: the clock runs at options.frame_ms, and the canvas has
    // options.scale device pixels a unit (--scale), which blanks it.
    explicit Window(const Options& options, Document page = Document());
    Document document;
    Clock clock;
    // Whether the page draws its overlay (overlay_draw.h) this frame: set from --overlay,
    // turned by kOverlayKey. The page reads it; the browser owns it, as it owns the
    // clock, so the page's own scripts stay the book's.
    bool overlay = false;
};

// What one fixed step of a page's world costs at most, for the run's budget: every
// step tests every pair of shapes once a collision pass, `passes` times a sub-step; and
// a page that draws the collisions it found (chapter 3 to 4.2) draws a line a pair.
struct StepCost {
    double dt_s = 1.0 / 60.0;  // the fixed step, s
    int substeps = 1;
    int passes = 1;            // collision passes a sub-step (0 counts as 1: the pairs are still found)
    std::size_t shapes = 0;    // at the start; each F or G press may add one more
    bool draws_pairs = true;   // every frame draws a line for every pair that collides
};

// The budget of a run, so that every run fits in memory and ends in minutes
// (docs/scene_format.md, "Limits", has the worst case measured):
//  - the page's device pixels (canvas size times --scale, each way): 64 MiB a picture;
//  - the pixels drawn over the whole run, frames times device pixels, as every frame
//    clears and draws the whole canvas;
//  - the pair tests of the whole run (pair_test_bound).
inline constexpr double kMaxDevicePixels = 4096.0 * 4096.0;
inline constexpr double kMaxPixelsDrawn = 5e11;
inline constexpr double kMaxPairTests = 5e9;
// Drawing a pair's collision line costs about as much as this many pair tests (a line
// across a few hundred pixels against a separating-axis test, measured).
inline constexpr double kDrawnPairCost = 1000.0;

// An upper bound of the pair tests a run costs: its fixed steps (frames x frame_ms / dt,
// plus one) times sub-steps times passes times the pairs of the most shapes it can have
// (those at the start and one an F or G press), and for a page that draws its pairs,
// kDrawnPairCost a pair a frame.
double pair_test_bound(const StepCost& step, const Options& options);

// What a stage's index.html registers with the browser.
class PageScripts {
public:
    virtual ~PageScripts() = default;
    virtual void onKeyDown(Key key) = 0;  // <body onkeydown="userControl(event)">
    virtual void onAnimationFrame() = 0;  // the requestAnimationFrame callback
    // For the budget: a page that says nothing counts as one pass a 1/60 s step over
    // the shapes its key presses make.
    virtual StepCost stepCost() const { return {}; }
};

// A key press reaching the page: on a stage with an overlay, kOverlayKey turns
// window.overlay on or off; every other key goes to the page's onKeyDown.
void press_key(PageScripts& scripts, Window& window, const Options& options, Key key);

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
// would go over its budget (kMaxDevicePixels, kMaxPixelsDrawn, kMaxPairTests).
// SIGINT and SIGTERM end a run after the frame they come in, with the staging folder
// and every partial file removed (interruption.h).
// With options.live.on it plays the page in a window instead (live.h), writing no
// pictures: 0 when the reader closes it, 1 with one line when no window can be opened
// or the recorded key script or screenshot cannot be written.
int run(PageScripts& scripts, Window& window, const Options& options);

}  // namespace browser
