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

// Where the legend's box starts (page pixels): above the panel's bottom by its entries.
int legend_top(const Document& document) {
    const int entries = static_cast<int>(document.legend.size());
    const int bottom = document.canvas.height() - kPanelMargin / 2;
    return std::max(0, bottom - entries * kLineHeight - kPanelMargin);
}

void draw_legend(Image& page, const Document& document);

// The band under the page (Document::beyond_echo): its first line this far below the
// canvas, and a half margin under its last.
constexpr int kBandGap = kPanelMargin / 2;

// The band's lines, one a '\n', each wrapped to the panel's width as the echo's are.
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

int band_height(const std::vector<std::string>& lines) {
    if (lines.empty()) return 0;
    return kBandGap + static_cast<int>(lines.size()) * kLineHeight + kPanelMargin / 2;
}

}  // namespace

Image render_page(const Document& document) {
    const Image& canvas = document.canvas.pixels();
    const int scale = document.canvas.scale();
    const std::vector<std::string> beyond = beyond_lines(document);
    Image page(canvas.width + kPanelWidth * scale, canvas.height + band_height(beyond) * scale, colors::kWhite);
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

    // The echo panel: one text line per '\n', wrapped to the panel, cut at its bottom.
    // Laid out in page pixels, drawn in device pixels.
    const int text_left = document.canvas.width() + kPanelMargin;
    const int text_width_limit = kPanelWidth - 2 * kPanelMargin;
    // Under a legend the echo stops a whole line short of its box, so no half-hidden
    // line shows beneath it.
    const int text_bottom = document.legend.empty() ? document.canvas.height() + kLineHeight : legend_top(document);
    int y = kPanelMargin;
    std::string_view echo = document.ui_echo;
    while (!echo.empty() && y + kLineHeight <= text_bottom) {
        const std::size_t end = echo.find('\n');
        const std::string line = font_text(echo.substr(0, end));
        echo = end == std::string_view::npos ? std::string_view{} : echo.substr(end + 1);
        for (const std::string& piece : wrap(line, text_width_limit)) {
            draw_text(page, piece, text_left * scale, y * scale, kTextColor, scale);
            y += kLineHeight;
        }
    }
    draw_legend(page, document);
    // The stage's own section, on the band: under the panel's lines, where a reader of
    // the panel goes on reading.
    y = document.canvas.height() + kBandGap;
    for (const std::string& line : beyond) {
        draw_text(page, line, text_left * scale, y * scale, kTextColor, scale);
        y += kLineHeight;
    }
    return page;
}

namespace {

// The legend covers the bottom of the echo panel (in chapter 4 the echo fills the panel,
// and the canvas is the scene's): the key list hidden under it is still in --help, and
// the overlay key brings it back.
void draw_legend(Image& page, const Document& document) {
    if (document.legend.empty()) return;
    const int k = document.canvas.scale();
    const int left = document.canvas.width() + kPanelMargin / 2;
    const int right = document.canvas.width() + kPanelWidth - kPanelMargin / 2;
    const int bottom = document.canvas.height() - kPanelMargin / 2;
    const int top = legend_top(document);
    fill(page, left * k, top * k, right * k, bottom * k, kLegendBorder);
    fill(page, (left + 1) * k, (top + 1) * k, (right - 1) * k, (bottom - 1) * k, colors::kWhite);
    int y = top + kPanelMargin / 2;
    for (const LegendEntry& entry : document.legend) {
        const int swatch_top = y + (kLineHeight - kSwatchSize) / 2 - 2;
        fill(page, (left + kPanelMargin / 2) * k, swatch_top * k, (left + kPanelMargin / 2 + kSwatchSize) * k,
             (swatch_top + kSwatchSize) * k, entry.color);
        const int text_left = left + kPanelMargin / 2 + kSwatchSize + kSwatchGap;
        draw_text(page, entry.text, text_left * k, y * k, kTextColor, k);
        y += kLineHeight;
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
