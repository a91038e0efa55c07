#include "chart_text.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "contact_sheet.h"  // shrink
#include "text.h"           // draw_text

namespace bench::chart {
namespace {

constexpr int kWidestLetter = 20;  // more than any letter's advance in that font (16 for @)

}  // namespace

Image ink_of(std::string_view text) {
    const auto tabs = std::count(text.begin(), text.end(), '\t');  // a tab is four spaces
    const int room = kWidestLetter * static_cast<int>(text.size() + 3 * static_cast<std::size_t>(tabs) + 1);
    Image scratch(room, kInkHeight, browser::colors::kWhite);
    browser::draw_text(scratch, text, 0, 0, browser::colors::kBlack);
    int width = 1;
    for (int x = 0; x < scratch.width; ++x) {
        for (int y = 0; y < scratch.height; ++y) {
            if (scratch.at(x, y).r != 255) width = x + 1;
        }
    }
    Image trimmed(width, kInkHeight, browser::colors::kWhite);
    trimmed.paste(scratch, 0, 0);
    return trimmed;
}

int text_width(std::string_view text) { return ink_of(text).width; }

Image small_ink_of(std::string_view text) { return browser::shrink(ink_of(text), 2); }

Image turned_up(const Image& ink) {
    Image turned(ink.height, ink.width);
    for (int y = 0; y < ink.height; ++y) {
        for (int x = 0; x < ink.width; ++x) turned.set(y, ink.width - 1 - x, ink.at(x, y));
    }
    return turned;
}

void stamp(Image& picture, const Image& ink, int x, int y, Color color) {
    const auto mix = [](std::uint8_t under, std::uint8_t over, double cover) {
        return static_cast<std::uint8_t>(under + (over - under) * cover + 0.5);
    };
    for (int j = 0; j < ink.height; ++j) {
        for (int i = 0; i < ink.width; ++i) {
            const double cover = 1.0 - ink.at(i, j).r / 255.0;
            if (cover <= 0.0 || !picture.contains(x + i, y + j)) continue;
            const Color under = picture.at(x + i, y + j);
            picture.set(
                x + i, y + j,
                {mix(under.r, color.r, cover), mix(under.g, color.g, cover), mix(under.b, color.b, cover), 255});
        }
    }
}

std::vector<std::string> wrapped(std::string_view text, int max_width) {
    std::vector<std::string> lines;
    std::string line;
    const auto fits = [&](const std::string& candidate) { return text_width(candidate) <= max_width; };
    std::size_t start = 0;
    while (start <= text.size()) {
        const std::size_t end = std::min(text.find(' ', start), text.size());
        std::string word(text.substr(start, end - start));
        start = end + 1;
        if (word.empty()) continue;
        if (!line.empty() && fits(line + " " + word)) {
            line += " " + word;
            continue;
        }
        if (!line.empty()) lines.push_back(line);
        line.clear();
        while (!fits(word)) {  // a word wider than a line: as many letters as fit, at least one
            std::size_t keep = 1;
            while (keep + 1 < word.size() && fits(word.substr(0, keep + 1))) ++keep;
            lines.push_back(word.substr(0, keep));
            word.erase(0, keep);
        }
        line = word;
    }
    if (!line.empty() || lines.empty()) lines.push_back(line);
    return lines;
}

int whole(double pixel) { return static_cast<int>(std::lround(std::clamp(pixel, -1e6, 1e6))); }

}  // namespace bench::chart
