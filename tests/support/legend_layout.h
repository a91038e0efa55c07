#pragma once
// Where the page's legend puts its entries (page.h's legend_boxes), judged as a reader
// would: each entry inside the legend's frame, and none running into the entry to its
// right. Shared by the collision overlay's feature test and 5.9's drawing tests.

#include <optional>
#include <string>
#include <vector>

#include "page.h"

namespace test {

// The text of the first entry that leaves the legend's frame (5 px in from each side
// of a page `page_width` wide) or runs into an entry to its right on the same row;
// nullopt when every entry lies on the page in its own column.
inline std::optional<std::string> entryOffThePage(const browser::Document& document, int page_width) {
    const std::vector<browser::LegendBox> boxes = browser::legend_boxes(document);
    for (std::size_t i = 0; i < boxes.size(); ++i) {
        const browser::LegendBox& box = boxes[i];
        if (box.left < 5 || box.right > page_width - 5) return document.legend[i].text;
        for (const browser::LegendBox& other : boxes) {
            if (other.top == box.top && other.left > box.left && box.right > other.left) {
                return document.legend[i].text;
            }
        }
    }
    return std::nullopt;
}

}  // namespace test
