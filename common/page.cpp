#include "page.h"

#include <algorithm>
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "text.h"

namespace browser {

namespace {

constexpr Color kFrameColor = colors::kGray;  // the thin border round the canvas
constexpr Color kTextColor = colors::kBlack;

constexpr int kLineHeight = text_line_height();  // the panel's lines are the font's
constexpr int kPanelMargin = 10;
// The live window's status line: a light gray band, so it reads as the window's and
// not the page's.
constexpr int kStatusPadding = 6;
constexpr Color kStatusBackground{224, 224, 224, 255};

// Splits one line of text into pieces at most max_width pixels wide, breaking after the
// last space that fits, or inside a word too long to fit at all. Continued pieces are
// indented two spaces deeper than the line, so they read as part of the same entry.
std::vector<std::string> wrap(std::string line, int max_width) {
    const std::size_t first_letter = line.find_first_not_of(' ');
    const std::string indent(first_letter == std::string::npos ? 0 : first_letter + 2, ' ');
    std::vector<std::string> pieces;
    while (text_width(line) > max_width) {
        const std::size_t text_start = line.find_first_not_of(' ');
        if (text_start == std::string::npos) break;
        std::size_t fits = text_start + 1;  // always take a letter, so the loop moves on
        while (fits < line.size() && text_width(line.substr(0, fits + 1)) <= max_width) ++fits;
        const std::size_t space = line.rfind(' ', fits);
        const std::size_t cut = (space != std::string::npos && space > text_start) ? space : fits;
        pieces.push_back(line.substr(0, cut));
        line = indent + line.substr(line[cut] == ' ' ? cut + 1 : cut);
    }
    pieces.push_back(line);
    return pieces;
}

// Inside the legend box: a swatch of the entry's colour, then its text.
constexpr int kSwatchSize = 12;
constexpr int kSwatchGap = 6;
constexpr Color kLegendBorder = colors::kGray;

void fill(Image& picture, int x0, int y0, int x1, int y1, Color color) {
    for (int j = y0; j < y1; ++j) {
        for (int i = x0; i < x1; ++i) picture.set(i, j, color);
    }
}

// The legend's band (Document::legend_room): entries in columns as wide as the stage's
// widest entry can be (Document::legend_text_width) with its swatch and a gap, as many
// as the page's width holds, in as many rows as the entries fill, filled top to bottom
// and then left to right, so that each layer's entries stay together. The default width
// gives columns 390 pixels apart.
constexpr int kLegendColumnGap = 6;

int legend_column_width(int widest) { return kSwatchSize + kSwatchGap + widest + kLegendColumnGap; }

int legend_columns(int page_width, int widest) {
    return std::max(1, (page_width - kPanelMargin) / legend_column_width(widest));
}

int legend_rows(std::size_t entries, int page_width, int widest) {
    const std::size_t columns = static_cast<std::size_t>(legend_columns(page_width, widest));
    return static_cast<int>(std::max<std::size_t>(1, (entries + columns - 1) / columns));
}

// The entries the band is made for: the stage's most, or the legend's own, if more.
std::size_t legend_entries(const Document& document) {
    if (!document.legend_room && document.legend.empty()) return 0;
    return std::max({document.legend_entries, document.legend.size(), std::size_t{1}});
}

int page_width(const Document& document) { return static_cast<int>(document.canvas.width()) + kPanelWidth; }

void draw_legend(Image& page, const Document& document, int top);

// The band under the page (Document::echo_notes, Document::beyond_echo): its first line
// this far below the canvas, and a half margin under its last.
constexpr int kBandGap = kPanelMargin / 2;

// An echo note's mark and text: dim, so that they read as the page's, not the book's.
constexpr Color kNoteColor = colors::kGray;

// The note on `line` of the echo, if the stage has one.
const EchoNote* note_on(const Document& document, std::string_view line) {
    const std::size_t first_letter = line.find_first_not_of(' ');
    if (first_letter == std::string_view::npos) return nullptr;
    for (const EchoNote& note : document.echo_notes) {
        if (!note.line_start.empty() && line.substr(first_letter).starts_with(note.line_start)) return &note;
    }
    return nullptr;
}

// The notes' lines on the band: each note's mark and text, wrapped to the panel's width.
std::vector<std::string> note_lines(const Document& document) {
    std::vector<std::string> lines;
    for (const EchoNote& note : document.echo_notes) {
        for (std::string& piece : wrap(font_text(note.mark + " " + note.text), kPanelWidth - 2 * kPanelMargin)) {
            lines.push_back(std::move(piece));
        }
    }
    return lines;
}

// The beyond_echo's lines, one a '\n', each wrapped to the panel's width as the echo's are.
std::vector<std::string> beyond_lines(const Document& document) {
    std::vector<std::string> lines;
    std::string_view text = document.beyond_echo;
    while (!text.empty()) {
        const std::size_t end = text.find('\n');
        for (std::string& piece : wrap(font_text(text.substr(0, end)), kPanelWidth - 2 * kPanelMargin)) {
            lines.push_back(std::move(piece));
        }
        text = end == std::string_view::npos ? std::string_view{} : text.substr(end + 1);
    }
    return lines;
}

int band_height(std::size_t lines) {
    if (lines == 0) return 0;
    return kBandGap + static_cast<int>(lines) * kLineHeight + kPanelMargin / 2;
}

}  // namespace

int legend_band_height(std::size_t entries, int page_width, int widest_text) {
    if (entries == 0) return 0;
    return legend_rows(entries, page_width, widest_text) * kLineHeight + kPanelMargin;
}

std::vector<LegendBox> legend_boxes(const Document& document) {
    const int widest = document.legend_text_width;
    const int rows = legend_rows(legend_entries(document), page_width(document), widest);
    const int top = static_cast<int>(document.canvas.height()) +
                    band_height(note_lines(document).size() + beyond_lines(document).size());
    std::vector<LegendBox> boxes;
    for (std::size_t index = 0; index < document.legend.size(); ++index) {
        const int column = static_cast<int>(index) / rows, row = static_cast<int>(index) % rows;
        const int x = kPanelMargin + column * legend_column_width(widest);
        const int y = top + kPanelMargin / 2 + row * kLineHeight;
        const int right = x + kSwatchSize + kSwatchGap + text_width(document.legend[index].text);
        boxes.push_back({x, y, right, y + kLineHeight});
    }
    return boxes;
}

Image render_page(const Document& document) {
    const Image& canvas = document.canvas.pixels();
    const int scale = document.canvas.scale();
    const std::vector<std::string> notes = note_lines(document);
    const std::vector<std::string> beyond = beyond_lines(document);
    const int band = band_height(notes.size() + beyond.size());
    const int legend_top = static_cast<int>(document.canvas.height()) + band;
    const int legend_height =
        legend_band_height(legend_entries(document), page_width(document), document.legend_text_width);
    Image page(canvas.width + kPanelWidth * scale, canvas.height + (band + legend_height) * scale, colors::kWhite);
    page.paste(canvas, 0, 0);

    // The frame lies on the canvas's outermost pixels (its outermost `scale` rows and
    // columns of device pixels), so the page keeps the canvas size.
    for (int i = 0; i < canvas.width; ++i) {
        for (int t = 0; t < scale; ++t) {
            page.set(i, t, kFrameColor);
            page.set(i, canvas.height - 1 - t, kFrameColor);
        }
    }
    for (int j = 0; j < canvas.height; ++j) {
        for (int t = 0; t < scale; ++t) {
            page.set(t, j, kFrameColor);
            page.set(canvas.width - 1 - t, j, kFrameColor);
        }
    }

    // The echo panel: one text line per '\n', wrapped to the panel, cut at its bottom:
    // a line is drawn only if its letters end above the canvas's bottom (its line, less
    // the space under the letters), so that no line is half drawn and none runs into the
    // band under the page. Laid out in page pixels, drawn in device pixels.
    const int text_left = document.canvas.width() + kPanelMargin;
    const int text_width_limit = kPanelWidth - 2 * kPanelMargin;
    const int text_bottom = document.canvas.height() + kBandGap;
    int y = kPanelMargin;
    std::string_view echo = document.ui_echo;
    while (!echo.empty() && y + kLineHeight <= text_bottom) {
        const std::size_t end = echo.find('\n');
        const EchoNote* note = note_on(document, echo.substr(0, end));
        const std::string line = font_text(echo.substr(0, end));
        echo = end == std::string_view::npos ? std::string_view{} : echo.substr(end + 1);
        const std::vector<std::string> pieces = wrap(line, text_width_limit);
        for (const std::string& piece : pieces) {
            if (y + kLineHeight > text_bottom) break;
            draw_text(page, piece, text_left * scale, y * scale, kTextColor, scale);
            // A noted line's mark, dim, a letter's gap after its last piece.
            if (note != nullptr && &piece == &pieces.back()) {
                const int after = text_left + text_width(piece) + text_width(" ") / 2;
                draw_text(page, font_text(note->mark), after * scale, y * scale, kNoteColor, scale);
            }
            y += kLineHeight;
        }
    }
    // On the band under the panel, where a reader of the panel goes on reading: the
    // notes on the echo's lines, dim, then the stage's own section.
    y = document.canvas.height() + kBandGap;
    for (const std::string& line : notes) {
        draw_text(page, line, text_left * scale, y * scale, kNoteColor, scale);
        y += kLineHeight;
    }
    for (const std::string& line : beyond) {
        draw_text(page, line, text_left * scale, y * scale, kTextColor, scale);
        y += kLineHeight;
    }
    draw_legend(page, document, legend_top);
    return page;
}

namespace {

// The legend in its band under everything else, so it never covers a line of the echo
// nor of the stage's own section: a box the page's width, a swatch and a line for each
// entry; the band has a row for every entry (legend_entries).
void draw_legend(Image& page, const Document& document, int top) {
    if (document.legend.empty()) return;  // the room kept for it stays blank
    const int k = document.canvas.scale();
    const int width = page.width / k;
    const int left = kPanelMargin / 2, right = width - kPanelMargin / 2;
    const int bottom =
        top + legend_band_height(legend_entries(document), width, document.legend_text_width) - kPanelMargin / 2;
    fill(page, left * k, top * k, right * k, bottom * k, kLegendBorder);
    fill(page, (left + 1) * k, (top + 1) * k, (right - 1) * k, (bottom - 1) * k, colors::kWhite);
    const std::vector<LegendBox> boxes = legend_boxes(document);
    for (std::size_t index = 0; index < boxes.size(); ++index) {
        const int x = boxes[index].left, y = boxes[index].top;
        const LegendEntry& entry = document.legend[index];
        const int swatch_top = y + (kLineHeight - kSwatchSize) / 2 - 2;
        fill(page, x * k, swatch_top * k, (x + kSwatchSize) * k, (swatch_top + kSwatchSize) * k, entry.color);
        draw_text(page, entry.text, (x + kSwatchSize + kSwatchGap) * k, y * k, kTextColor, k);
    }
}

}  // namespace

Image with_status_line(const Image& page, std::string_view status, int scale) {
    const int band = (kLineHeight + kStatusPadding) * scale;
    Image picture(page.width, page.height + band, kStatusBackground);
    picture.paste(page, 0, 0);
    draw_text(picture, status, kPanelMargin * scale, page.height + (kStatusPadding / 2 + 2) * scale, kTextColor, scale);
    return picture;
}

}  // namespace browser
