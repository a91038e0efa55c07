#pragma once
// The book's index.html as the browser shows it: the canvas on the left and, on its
// right, the "UI echo" text panel (selected object, its state, the key controls).

#include <cstddef>
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

// How wide a legend entry's text may be (text_width, page pixels) unless the stage says
// otherwise (Document::legend_text_width): three columns on a page 1180 pixels wide.
inline constexpr int kLegendTextWidth = 366;

// A note the page adds to a line of the echo, as a footnote: where a line of the echo
// starts with `line_start` (after its indent), a dim `mark` follows its text, and under
// the panel the same mark leads `text`, dim too. The echo itself stays as the page was
// given it, letter for letter: the note is the page's, not the echo's (a stage keeps the
// book's quirk of a line and says so beside it).
struct EchoNote {
    std::string line_start;  // what the noted line starts with, its indent left out
    std::string mark;        // e.g. "*"
    std::string text;        // what the note says, wrapped to the panel's width
};

struct Document {
    Canvas canvas;        // <canvas id="canvas">
    std::string ui_echo;  // <div id="uiEchoString">: plain text, '\n' starts a new line
    // What a stage beyond the book adds to the echo, its own settings and keys: a section
    // of its own, under the book's lines, on a band the page grows by (render_page), so
    // that the book's echo keeps every line whole. Empty in the book's projects. A stage
    // keeps its number of lines the same from frame to frame: the page's height follows it.
    std::string beyond_echo;
    // The stage's notes on lines of the echo (EchoNote): each one's text is on the band
    // under the panel, first, from the first frame to the last, whether the line it
    // notes is shown or not, so that the page keeps its height.
    std::vector<EchoNote> echo_notes;
    // What the overlay's colours mean (overlay_draw.h), boxed in a band of its own under
    // the page (render_page), where it covers none of the echo's lines; empty while the
    // overlay is off.
    std::vector<LegendEntry> legend;
    // Whether the page keeps the legend's band while the legend is empty: so that every
    // picture of a run in which the overlay can come on (--overlay, the overlay key in
    // its script, a live session) has one size, the overlay on or off. The book's runs
    // keep none, and their pictures stay the book's.
    bool legend_room = false;
    // How many entries the band is made for: the most the stage's overlay puts in its
    // legend with the layers the run can show (its own layer alone, or every layer: the
    // stage's overlay.h says how many, Window::every_layer_possible which). The band is
    // as tall as the rows those entries take in the columns the page's width holds, or
    // the rows the legend shown takes, if it has more; so a run's pictures keep one height.
    std::size_t legend_entries = 0;
    // How wide the widest entry's text can be, in page pixels (text_width): the stage
    // says, from the longest lines its legend writes, numbers included. Each column of the
    // band is that wide (and a swatch), so that every entry fits in its column and every
    // column on the page; the band's rows follow from it and legend_entries alone, never
    // from the words of one frame, so that a run's pictures keep one height.
    int legend_text_width = kLegendTextWidth;
};

// Where an entry of the legend lies on the page, in page pixels: from its swatch's left
// to the end of its text, one line of the font tall.
struct LegendBox {
    int left = 0, top = 0, right = 0, bottom = 0;
};

inline constexpr int kPanelWidth = 380;  // width of the text panel in pixels

// Composes the page: canvas with a thin frame, the echo panel beside it; then, when the
// document has echo notes or a beyond_echo, a white band under them both with the
// notes' lines and then the beyond_echo's, under the panel's; then, when it has a legend
// or keeps room for one, the legend's band (legend_band_height): entries in columns
// across the page, a swatch and a line each entry.
// Size: (canvas width + kPanelWidth) x (canvas height + the bands, if any), times the
// canvas's scale: the frame, the panel and its text are drawn that many times larger
// too, and the text is wrapped where it is wrapped at scale 1.
Image render_page(const Document& document);

// The height of the legend's band, in page pixels, on a page `page_width` page pixels
// wide (the canvas's width and kPanelWidth), for `entries` entries whose text is at most
// `widest_text` wide: a line of the font a row, as many rows as the entries fill in the
// columns that width holds (at least one), and a margin. 0 entries: no band.
int legend_band_height(std::size_t entries, int page_width, int widest_text = kLegendTextWidth);

// Where render_page draws each entry of the document's legend (LegendBox), measured with
// the font's own text_width: what a test checks lies on the page and in its column.
std::vector<LegendBox> legend_boxes(const Document& document);

// The page with one line of text under it, on a gray band the page's width: what a
// live window shows (live.h), so the page above the band is the picture a run saves.
Image with_status_line(const Image& page, std::string_view status, int scale);

}  // namespace browser
