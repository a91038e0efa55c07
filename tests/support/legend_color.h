#pragma once
// The overlay tests find what they look for by the colour the page's legend gives it, so
// a test never repeats a colour the overlay chose.

#include <catch2/catch.hpp>

#include <string>

#include "page.h"
#include "color_text.h"

namespace test {

// The colour of the legend line that starts with `prefix`; the test fails if none does.
inline browser::Color legendColor(const browser::Document& document, const std::string& prefix) {
    for (const browser::LegendEntry& entry : document.legend) {
        if (entry.text.rfind(prefix, 0) == 0) return entry.color;
    }
    FAIL("no legend line starts with \"" << prefix << "\"");
    return {};
}

}  // namespace test
