#pragma once
// The legend of a chart: a box right of the plot, its top level with the plot's, with a
// sample (marker, line) and the name of each named series, and one for the Pareto front.

#include <string>
#include <vector>

#include "canvas.h"
#include "chart_look.h"
#include "chart_marks.h"
#include "charts.h"

namespace bench::chart {

struct LegendEntry {
    std::vector<std::string> lines;
    Color colour;
    Marker marker;
    bool joined;
    bool pareto;  // the Pareto front's entry: ring and dashes
    int top = 0;  // of its first line
};

// The box right of the plot, its top level with the plot's: for each entry a sample (marker,
// line) and the name beside it.
struct Legend {
    std::vector<LegendEntry> entries;
    int left = 0, top = 0, width = 0, height = 0;
    int sample_left() const { return left + kLegendPadding; }
    int text_left() const { return sample_left() + kLegendSample + 8; }
};

// Entries for the named series and for the Pareto front, stacked; the box is placed later,
// once the plot's right edge is known.
Legend list_legend(const Chart& chart, bool has_front);
// Puts the box's top-left corner at (left, top).
void place_legend(Legend& legend, int left, int top);

// The samples and the box, drawn on the canvas; then the names, laid on the picture.
void draw_legend_box(Canvas& canvas, const Legend& legend);
void draw_legend_names(browser::Image& picture, const Legend& legend);

}  // namespace bench::chart
