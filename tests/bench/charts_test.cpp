// The charts of bench/ and the statistics drawn on them: the Pareto front and the
// fitted growth exponent, worked out by hand on small sets, and chart pictures that are
// written, read back, and skip the points they cannot place.
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

#include "charts.h"
#include "near.h"
#include "statistics.h"
#include "image.h"
#include "png_io.h"
#include "scratch_folder.h"

using bench::Chart;
using bench::ChartPoint;
using bench::Series;

namespace {

std::vector<std::pair<double, double>> coordinates(const std::vector<ChartPoint>& points) {
    std::vector<std::pair<double, double>> xy;
    for (const ChartPoint& p : points) xy.emplace_back(p.x, p.y);
    return xy;
}

using XY = std::vector<std::pair<double, double>>;

int count_pixels(const browser::Image& image, bool (*wanted)(browser::Color)) {
    int count = 0;
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) count += wanted(image.at(x, y)) ? 1 : 0;
    }
    return count;
}

// A bool, not a comparison of the pixel vectors: Catch would print millions of bytes.
bool same_pixels(const browser::Image& a, const browser::Image& b) {
    return a.width == b.width && a.height == b.height && a.rgba == b.rgba;
}

bool not_white(browser::Color c) { return c.r != 255 || c.g != 255 || c.b != 255; }
// The first series' colour is a blue; nothing else on a chart (black text, grey grid) is.
bool bluish(browser::Color c) { return c.b > c.r + 80 && c.b > c.g + 30; }

Chart sample_chart() {
    Chart chart;
    chart.title = "cost and error";
    chart.x_label = "cost (us per step)";
    chart.y_label = "error (m)";
    chart.log_x = true;
    chart.log_y = true;
    chart.series = {{"fast", {{10, 1.0, "a"}, {20, 0.5, ""}, {40, 0.3, ""}}, true},
                    {"slow", {{30, 0.05, ""}, {100, 0.01, "b"}}, false}};
    return chart;
}

browser::Image chart_picture(const Chart& chart, const test::ScratchFolder& folder, const std::string& name) {
    const std::filesystem::path file = folder.path / name;
    bench::write_chart(chart, file);
    return browser::read_png(file);
}

}  // namespace

TEST_CASE("pareto_front: small sets worked out by hand") {
    SECTION("nothing in, nothing out") { CHECK(bench::pareto_front({}).empty()); }

    SECTION("a single point is its own front") {
        const auto front = bench::pareto_front({{3.0, 4.0, "only"}});
        REQUIRE(front.size() == 1);
        CHECK(front[0].x == 3.0);
        CHECK(front[0].y == 4.0);
        CHECK(front[0].label == "only");
    }

    SECTION("beaten points drop out; the front comes sorted by x") {
        // (3,4) is beaten by (2,3); (2,6) by (1,5); the other three beat each other on
        // one axis and lose on the other.
        const std::vector<ChartPoint> points{{4, 1, ""}, {3, 4, ""}, {2, 6, ""}, {2, 3, ""}, {1, 5, ""}};
        CHECK(coordinates(bench::pareto_front(points)) == XY{{1, 5}, {2, 3}, {4, 1}});
    }

    SECTION("a tie on one axis: the point worse on the other is beaten") {
        CHECK(coordinates(bench::pareto_front({{1, 3, ""}, {1, 2, ""}, {2, 1, ""}})) == XY{{1, 2}, {2, 1}});
        CHECK(coordinates(bench::pareto_front({{2, 1, ""}, {1, 1, ""}})) == XY{{1, 1}});
    }

    SECTION("equal points do not beat each other: both stay, with their labels") {
        const auto front = bench::pareto_front({{1, 1, "first"}, {2, 0.5, ""}, {1, 1, "second"}, {1, 2, ""}});
        REQUIRE(coordinates(front) == XY{{1, 1}, {1, 1}, {2, 0.5}});
        CHECK(front[0].label == "first");
        CHECK(front[1].label == "second");
    }

    SECTION("a point with a NaN coordinate cannot be compared and is left out") {
        const double nan = std::numeric_limits<double>::quiet_NaN();
        CHECK(coordinates(bench::pareto_front({{nan, 0, ""}, {1, 1, ""}, {0.5, nan, ""}})) == XY{{1, 1}});
    }
}

// The fits below work through logarithms of a handful of points: 1e-12 is their rounding.
TEST_CASE("fitted_exponent: recovers the exponent of a power law") {
    SECTION("y = 3 x^1.5") {
        const std::vector<ChartPoint> points{{1, 3, ""}, {2, 3 * std::pow(2.0, 1.5), ""}, {4, 24, ""}, {9, 81, ""}};
        CHECK_THAT(bench::fitted_exponent(points, 1, 9), test::near(1.5, 1e-12));
    }
    SECTION("y = 2 x^2, x below 1 included") {
        const std::vector<ChartPoint> points{{0.5, 0.5, ""}, {1, 2, ""}, {3, 18, ""}, {10, 200, ""}};
        CHECK_THAT(bench::fitted_exponent(points, 0.1, 100), test::near(2.0, 1e-12));
    }
    SECTION("points outside [x_min, x_max] are ignored; the ends belong to the range") {
        // On y = 3 x^1.5 from x = 2 to 8, with two far-off points outside: taken in, they
        // would pull the slope far from 1.5. Were the ends left out, only x = 4 would
        // remain and there would be no slope at all.
        const std::vector<ChartPoint> points{
            {1, 100, ""}, {2, 3 * std::pow(2.0, 1.5), ""}, {4, 24, ""}, {8, 3 * std::pow(8.0, 1.5), ""}, {16, 0.1, ""}};
        CHECK_THAT(bench::fitted_exponent(points, 2, 8), test::near(1.5, 1e-12));
    }
    SECTION("scattered points: the least-squares slope") {
        // log10 x = 0, 1, 2 and log10 y = 0, 1, 3. Means 1 and 4/3; slope =
        // [(-1)(-4/3) + 0 + (1)(5/3)] / [1 + 0 + 1] = 3 / 2.
        const std::vector<ChartPoint> points{{1, 1, ""}, {10, 10, ""}, {100, 1000, ""}};
        CHECK_THAT(bench::fitted_exponent(points, 1, 100), test::near(1.5, 1e-12));
    }
    SECTION("no slope from fewer than two different x") {
        CHECK(std::isnan(bench::fitted_exponent({{2, 5, ""}, {2, 7, ""}}, 0, 10)));
        CHECK(std::isnan(bench::fitted_exponent({{2, 5, ""}, {20, 7, ""}}, 3, 10)));
        CHECK(std::isnan(bench::fitted_exponent({}, 0, 10)));
    }
}

TEST_CASE("write_chart: a PNG of the chart's size that reads back and shows something") {
    test::ScratchFolder folder("charts");
    Chart chart = sample_chart();
    chart.mark_pareto = true;
    chart.notes = {"fitted exponent 1.07"};
    const browser::Image picture = chart_picture(chart, folder, "chart.png");
    CHECK(picture.width == bench::kChartWidth);
    CHECK(picture.height == bench::kChartHeight);
    CHECK(count_pixels(picture, not_white) > 5000);  // frame, axes, grid, text
    CHECK(count_pixels(picture, bluish) > 50);       // the first series' markers and line

    chart.mark_pareto = false;
    CHECK_FALSE(same_pixels(chart_picture(chart, folder, "no_front.png"), picture));
}

TEST_CASE("write_chart: points it cannot place are skipped and counted in a note") {
    test::ScratchFolder folder("charts_skip");
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();

    SECTION("NaN, infinity and values <= 0 on a log axis") {
        Chart messy = sample_chart();
        messy.series[0].points.push_back({nan, 1.0, "lost"});
        messy.series[0].points.push_back({50, inf, ""});
        messy.series[1].points.push_back({-5, 0.1, ""});   // log x
        messy.series[1].points.push_back({200, 0.0, ""});  // log y
        Chart clean = sample_chart();
        clean.notes = {"4 points off the scale"};
        const browser::Image messy_picture = chart_picture(messy, folder, "messy.png");
        CHECK(same_pixels(messy_picture, chart_picture(clean, folder, "clean.png")));
        CHECK(count_pixels(messy_picture, bluish) > 50);
    }

    SECTION("on linear axes, negative values are fine and one bad point is counted singly") {
        Chart messy;
        messy.series = {{"s", {{-2, -1, ""}, {3, 4, ""}, {-inf, 0, ""}}, true}};
        Chart clean;
        clean.series = {{"s", {{-2, -1, ""}, {3, 4, ""}}, true}};
        clean.notes = {"1 point off the scale"};
        CHECK(same_pixels(chart_picture(messy, folder, "messy.png"), chart_picture(clean, folder, "clean.png")));
    }

    SECTION("nothing left to place still makes a chart") {
        Chart empty;
        empty.log_x = true;
        empty.series = {{"s", {{0, 1, ""}, {nan, nan, ""}}, true}};
        empty.mark_pareto = true;
        const browser::Image picture = chart_picture(empty, folder, "empty.png");
        CHECK(picture.width == bench::kChartWidth);
        CHECK(count_pixels(picture, not_white) > 1000);
    }
}

TEST_CASE("write_chart: a folder that does not exist is a FileError") {
    test::ScratchFolder folder("charts_missing");
    CHECK_THROWS_AS(bench::write_chart(sample_chart(), folder.path / "no_such_folder" / "chart.png"),
                    browser::FileError);
    CHECK(folder.files().empty());
}
