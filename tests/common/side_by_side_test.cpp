// compare_runs' pictures (side_by_side.h): the canvas cut out of a saved page.
#include <catch2/catch.hpp>

#include <string>

#include "page.h"
#include "side_by_side.h"

namespace side_by_side_test {

TEST_CASE("side by side: the canvas of a page is its framed canvas, without a stage's band under the page") {
    for (const int scale : {1, 3}) {
        browser::Document document{browser::Canvas(200, 120, scale), "Selected Object:"};
        document.canvas.beginPath();
        document.canvas.moveTo(20.5, 60.5);
        document.canvas.lineTo(180.5, 60.5);
        document.canvas.stroke();
        const browser::Image book = browser::render_page(document);
        document.beyond_echo = "Beyond the book:\n  Sleeping: true";
        const browser::Image banded = browser::render_page(document);
        REQUIRE(banded.height > book.height);
        const browser::Image canvas = browser::canvas_of(book, scale);
        CHECK(canvas.width == 200 * scale);
        CHECK(canvas.height == 120 * scale);
        CHECK(canvas.at(0, canvas.height - 1) == browser::colors::kGray);                  // the frame's corner
        CHECK(canvas.at(100 * scale, 60 * scale + scale / 2) != browser::colors::kWhite);  // the line
        CHECK(browser::canvas_of(banded, scale).rgba == canvas.rgba);
    }
}

}  // namespace side_by_side_test
