#pragma once
// Charts of measurements, drawn with the project's own canvas and font and saved as PNG:
// one scatter (or line) plot per picture, with labelled axes, optionally logarithmic,
// a legend, and the Pareto front of a speed/accuracy trade-off marked.

#include <filesystem>
#include <string>
#include <vector>

namespace bench {

inline constexpr int kChartWidth = 900;   // pixels of every chart write_chart makes
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
    std::vector<Series> series;  // each gets its own colour and marker
    bool mark_pareto = false;    // outline the points no other point beats on both axes
                                 // (lower is better on both) and join them
    std::vector<std::string> notes;  // extra lines printed under the title
};

// The points on the front when lower x and lower y are both better: a point is on it
// unless another point is <= on both and < on one (so equal points are all on it).
// Returned sorted by x, then y. A point with a NaN coordinate cannot be compared with
// any other and is left out.
std::vector<ChartPoint> pareto_front(const std::vector<ChartPoint>& points);

// The exponent b of the power law y = a x^b that fits the points with x in
// [x_min, x_max] best: the least-squares line log y = log a + b log x. Points whose x
// or y is not a finite positive number have no logarithm and are left out. NaN when
// fewer than two different x remain (no line is fixed by them).
double fitted_exponent(const std::vector<ChartPoint>& points, double x_min, double x_max);

// Draws the chart (kChartWidth x kChartHeight pixels) and writes it to `png`. A point
// with a NaN or infinite coordinate, one <= 0 on a logarithmic axis, or one beyond 1e300
// on a linear axis (where the axis arithmetic would overflow) cannot be placed: it is
// left out and counted in a last note, "N points off the scale" ("1 point off the
// scale"). Throws browser::FileError when the file cannot be written.
void write_chart(const Chart& chart, const std::filesystem::path& png);

}  // namespace bench
