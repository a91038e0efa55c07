#pragma once
// Where everything on a chart goes, worked out before anything is drawn: the title and
// notes, the plot's box, both axes with their ticks and labels, and the legend.

#include <string>
#include <vector>

#include "chart_axes.h"
#include "chart_legend.h"
#include "chart_marks.h"
#include "charts.h"
#include "image.h"

namespace bench::chart {

using browser::Image;

struct Layout {
    std::vector<std::string> title_lines, note_lines;
    double plot_left = 0, plot_top = 0, plot_right = 0, plot_bottom = 0;
    Axis x, y;
    AxisMarks x_marks, y_marks;
    std::vector<Image> x_label_inks, y_label_inks;
    std::vector<bool> x_shown, y_shown;
    Legend legend;
};

// `notes`: the chart's notes and any the drawing adds; `placed`: the points that can be
// placed (on_scale), which the axes must show; `has_front`: the legend lists the front.
Layout lay_out(const Chart& chart, const std::vector<std::string>& notes, const std::vector<ChartPoint>& placed,
               bool has_front);

// Whether the point can be placed on the chart's axes.
bool on_scale(const ChartPoint& point, const Chart& chart);

// Where a point lands on the picture.
Pixel pixel_of(const ChartPoint& point, const Layout& layout);

}  // namespace bench::chart
