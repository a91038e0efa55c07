#pragma once
// What a stage's page meets in the browser: the window its scripts reach (the document
// with its canvas and echo panel, and the clock behind Date.now()) and the callbacks it
// registers. Both ways of playing a page use them: browser::run saves it as pictures
// (browser.h) and run_live shows it in a window (live.h).

#include <utility>

#include "clock.h"
#include "command_line.h"
#include "keys.h"
#include "page.h"
#include "pointer.h"

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
    // Which layers it draws: false, the stage's own technique (and what a reader needs to
    // read it); true, the layers of every stage before it too (--overlay-all, or
    // kOverlayKey pressed while the stage's own layer shows).
    bool overlay_all = false;
    // Whether every layer can come on in this run (--overlay-all, enough presses of
    // kOverlayKey in the key script, a live session): the page then keeps room for the
    // legend of every layer, and otherwise for that of the stage's own layer (page.h's
    // Document::legend_entries, which the stage's overlay sets from it).
    bool every_layer_possible = false;
};

// What a stage's index.html registers with the browser.
class PageScripts {
public:
    virtual ~PageScripts() = default;
    virtual void onKeyDown(Key key) = 0;  // <body onkeydown="userControl(event)">
    virtual void onAnimationFrame() = 0;  // the requestAnimationFrame callback
    // The pointer pressed, moved or let go on the canvas (pointer.h): onmousedown,
    // onmousemove, onmouseup. The book's pages take no pointer, and ignore it.
    virtual void onPointer(const PointerEvent& event) { static_cast<void>(event); }
};

// A key press reaching the page: on a stage with an overlay, kOverlayKey takes the
// overlay one step round off -> the stage's own layer -> every layer -> off; every
// other key goes to the page's onKeyDown.
void press_key(PageScripts& scripts, Window& window, const Options& options, Key key);

}  // namespace browser
