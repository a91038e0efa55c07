#pragma once
// Charts of measurements, drawn with the project's own canvas and font and saved as PNG:
// one scatter (or line) plot per picture, with labelled axes, optionally logarithmic,
// a legend, and the Pareto front of a speed/accuracy trade-off marked. The parts that
// draw it are the chart_*.h files (the look, text, axes, marks, legend, layout); the
// numbers worked out from points, such as the front itself, are statistics.h's.

#include <filesystem>
#include <string>
#include <vector>

namespace bench {

inline constexpr int kChartWidth = 900;  // pixels of every chart write_chart makes
inline constexpr int kChartHeight = 560;

struct ChartPoint {
    double x;
    double y;
    std::string label;  // may be "": drawn small beside the point
};

struct Series {
    std::string name;  // shown in the legend ("" leaves the series out of it)
    std::vector<ChartPoint> points;
    bool joined = false;  // draw a line through the points in the order given
};

struct Chart {
    std::string title;
    std::string x_label;  // with units, e.g. "cost (us per step)"
    std::string y_label;
    bool log_x = false;
    bool log_y = false;
    std::vector<Series> series;      // each gets its own colour and marker
    bool mark_pareto = false;        // outline the points no other point beats on both axes
                                     // (lower is better on both) and join them
    std::vector<std::string> notes;  // extra lines printed under the title
};

// Draws the chart (kChartWidth x kChartHeight pixels) and writes it to `png`. A point
// with a NaN or infinite coordinate, one <= 0 on a logarithmic axis, or one beyond 1e300
// on a linear axis (where the axis arithmetic would overflow) cannot be placed: it is
// left out and counted in a last note, "N points off the scale" ("1 point off the
// scale"). Throws browser::FileError when the file cannot be written.
void write_chart(const Chart& chart, const std::filesystem::path& png);

}  // namespace bench
