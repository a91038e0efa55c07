#pragma once
// The overlay tests find what they look for by the colour the page's legend gives it, so
// a test never repeats a colour the overlay chose.

#include <catch2/catch.hpp>

#include <source_location>
#include <string>

#include "checked_at.h"
#include "color_text.h"
#include "page.h"

namespace test {

// The colour of the legend line that starts with `prefix`; the test fails if none does,
// at the test's line, listing the lines the legend has.
inline browser::Color legendColor(const browser::Document& document, const std::string& prefix,
                                  std::source_location where = std::source_location::current()) {
    for (const browser::LegendEntry& entry : document.legend) {
        if (entry.text.rfind(prefix, 0) == 0) return entry.color;
    }
    std::string text = "no line starts with \"" + prefix + "\": this stage's overlay does not draw it yet. Its lines:";
    for (const browser::LegendEntry& entry : document.legend) text += "\n  " + entry.text;
    if (document.legend.empty()) text += " none";
    checkedAt(where, "a line of the overlay's legend, naming a colour the overlay draws", false, text, true);
    return {};
}

}  // namespace test
