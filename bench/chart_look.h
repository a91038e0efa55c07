#pragma once
// The look of the bench's charts (charts.h): colours, sizes and gaps, in pixels. One
// place for them, so the parts that draw a chart agree.

#include <iterator>

#include "image.h"

namespace bench::chart {

using browser::Color;

constexpr Color kTextInk{25, 25, 25, 255};
constexpr Color kNoteInk{80, 80, 80, 255};
constexpr Color kAxisColor{60, 60, 60, 255};
constexpr Color kGridColor{220, 220, 220, 255};
constexpr Color kMinorGridColor{240, 240, 240, 255};
constexpr Color kBoxColor{170, 170, 170, 255};  // the picture's frame and the legend's box
constexpr Color kParetoColor{20, 20, 20, 255};

// Ten colours that stay apart from one another and from the grey of the grid.
constexpr Color kPalette[] = {
    {31, 119, 180, 255}, {255, 127, 14, 255},  {44, 160, 44, 255},   {214, 39, 40, 255},  {148, 103, 189, 255},
    {140, 86, 75, 255},  {227, 119, 194, 255}, {127, 127, 127, 255}, {188, 189, 34, 255}, {23, 190, 207, 255},
};
constexpr int kColourCount = static_cast<int>(std::size(kPalette));

constexpr double kMarkerRadius = 5.0;  // a series' marker
constexpr double kParetoRadius = 9.0;  // the ring round a point on the Pareto front

constexpr int kMargin = 14;  // between the picture's edge and anything on it
constexpr int kTickLength = 5;
constexpr int kLabelGap = 6;    // between a tick and its label
constexpr int kLegendGap = 18;  // between the plot and the legend
constexpr int kLegendPadding = 8;
constexpr int kLegendSample = 34;     // room for a marker with a bit of line either side
constexpr int kLegendMostText = 210;  // a series' name wraps beyond this width

}  // namespace bench::chart
