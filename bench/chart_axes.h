#pragma once
// The axes of a chart: how values map to pixels, linearly or by their logarithm, where
// the ticks go and what they say, and which tick labels have room to be printed.

#include <cmath>
#include <string>
#include <utility>
#include <vector>

namespace bench::chart {

// Linear axes stop at 1e300 so that spans and paddings of the values stay finite.
constexpr double kLargestLinear = 1e300;

// One axis maps data values to pixels. On a logarithmic axis positions follow log10 of the
// value, so equal ratios take equal lengths; "units" below are the values on a linear
// axis and their logarithms on a logarithmic one.
struct Axis {
    bool log = false;
    double low = 0.0, high = 1.0;              // the ends, in units
    double pixel_low = 0.0, pixel_high = 1.0;  // where they lie on the picture

    double units(double value) const { return log ? std::log10(value) : value; }
    double pixel_of_units(double u) const { return pixel_low + (u - low) / (high - low) * (pixel_high - pixel_low); }
    double pixel(double value) const { return pixel_of_units(units(value)); }
    double length() const { return std::abs(pixel_high - pixel_low); }
};

// Whether a value can be placed on an axis: finite, and > 0 on a logarithmic one.
bool on_scale(double value, bool log);

// The ends of an axis showing the given units: the data's span with a twentieth of it to
// spare at each end, so no marker sits on the frame. A single value gets room around it
// (half a decade either side on a logarithmic axis); no values at all, a unit span.
std::pair<double, double> axis_ends(const std::vector<double>& units, bool log);

struct Tick {
    double units;
    std::string label;
    int priority;  // labels of priority 0 are placed first, then 1, ...
    double place;  // a whole number counting the ticks of priority 0 from a round value (0 or 1)
};

struct AxisMarks {
    std::vector<Tick> ticks;          // with a grid line and a label (if it fits)
    std::vector<double> minor_units;  // a faint grid line only
};

// Ticks with round values and the faint lines between them. `spacing`: the pixels wanted
// between ticks of a linear axis.
AxisMarks axis_marks(const Axis& axis, double spacing);

// Which tick labels to print, so that none comes within `gap` pixels of another
// (`extent`: a label's size along the axis). The main ticks are labelled every n-th,
// n as small as leaves room, counted from a round value so the labels stay regular;
// then each tick of priority 1, then 2, that finds room among those placed.
std::vector<bool> labels_that_fit(const std::vector<Tick>& ticks, const Axis& axis, const std::vector<int>& extent,
                                  double gap);

}  // namespace bench::chart
