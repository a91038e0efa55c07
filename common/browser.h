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
};

// What a stage's index.html registers with the browser.
class PageScripts {
public:
    virtual ~PageScripts() = default;
    virtual void onKeyDown(Key key) = 0;  // <body onkeydown="userControl(event)">
    virtual void onAnimationFrame() = 0;  // the requestAnimationFrame callback
};

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
// cannot be written; 2 with gif_writer.h's one line kNoGifSupport when options.gif
// asks for a GIF that this build cannot write (nothing is written then).
// With options.live.on it plays the page in a window instead (live.h), writing no
// pictures: 0 when the reader closes it, 1 with one line when no window can be opened
// or the recorded key script or screenshot cannot be written.
int run(PageScripts& scripts, Window& window, const Options& options);

}  // namespace browser
