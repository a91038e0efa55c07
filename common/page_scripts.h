#pragma once
// What a stage's page meets in the browser: the window its scripts reach (the document
// with its canvas and echo panel, and the clock behind Date.now()) and the callbacks it
// registers. Both ways of playing a page use them: browser::run saves it as pictures
// (browser.h) and run_live shows it in a window (live.h).
//
// StepCost is the one place where the page tells the browser about its world: what one
// step costs, in shapes, pairs and passes. It stays in the engine's terms on purpose.
// The budget must refuse a run that would take hours before it starts, and only the
// engine's own counts bound that; a browser-side unit ("work") would have to be
// translated from those same counts by every stage, and a reader would no longer see
// why 5,000 shapes are refused. For the same reason the budget takes F and G as the keys
// that may add a shape (browser.cpp's most_shapes): every stage binds them so, as the
// book's pages do, which makes them a convention of the pages the browser serves.

#include <cstddef>
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
    int passes = 1;           // collision passes a sub-step (0 counts as 1: the pairs are still found)
    std::size_t shapes = 0;   // at the start; each F or G press may add one more
    bool draws_pairs = true;  // every frame draws a line for every pair that collides
    // The memory a pair of shapes in contact holds during a step (the collision found,
    // a solver's contact and what it keeps for the next step), in bytes: at worst every
    // pair is in contact, as when all the shapes lie on one point.
    // 100 bytes: the colliding pairs a pass keeps, measured in 4.1 (docs/scene_format.md).
    double bytes_a_contact = 100.0;
};

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

}  // namespace browser
