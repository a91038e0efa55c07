#pragma once
// The book's index.html as the browser shows it: the canvas on the left and, on its
// right, the "UI echo" text panel (selected object, its state, the key controls).

#include <string>
#include <string_view>
#include <vector>

#include "canvas.h"
#include "image.h"

namespace browser {

// A line of an overlay's legend: the colour it draws something in, and what that is.
struct LegendEntry {
    Color color;
    std::string text;
};

struct Document {
    Canvas canvas;        // <canvas id="canvas">
    std::string ui_echo;  // <div id="uiEchoString">: plain text, '\n' starts a new line
    // What a stage beyond the book adds to the echo, its own settings and keys: a section
    // of its own, under the book's lines, on a band the page grows by (render_page), so
    // that the book's echo keeps every line whole. Empty in the book's projects. A stage
    // keeps its number of lines the same from frame to frame: the page's height follows it.
    std::string beyond_echo;
    // What the overlay's colours mean (overlay_draw.h), boxed in a band of its own under
    // the page (render_page), where it covers none of the echo's lines; empty while the
    // overlay is off.
    std::vector<LegendEntry> legend;
    // Whether the page keeps the legend's band while the legend is empty: so that every
    // picture of a run in which the overlay can come on (--overlay, the overlay key in
    // its script, a live session) has one size, the overlay on or off. The book's runs
    // keep none, and their pictures stay the book's.
    bool legend_room = false;
};

inline constexpr int kPanelWidth = 380;  // width of the text panel in pixels

// Composes the page: canvas with a thin frame, the echo panel beside it; then, when the
// document has a beyond_echo, a white band under them both with its lines, under the
// panel's; then, when it has a legend or keeps room for one, the legend's band: seven
// lines in columns across the page, a swatch and a line each entry.
// Size: (canvas width + kPanelWidth) x (canvas height + the bands, if any), times the
// canvas's scale: the frame, the panel and its text are drawn that many times larger
// too, and the text is wrapped where it is wrapped at scale 1.
Image render_page(const Document& document);

// The page with one line of text under it, on a gray band the page's width: what a
// live window shows (live.h), so the page above the band is the picture a run saves.
Image with_status_line(const Image& page, std::string_view status, int scale);

}  // namespace browser
