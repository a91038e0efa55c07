#include "chart_legend.h"

#include <algorithm>

#include "chart_text.h"

namespace bench::chart {

Legend list_legend(const Chart& chart, bool has_front) {
    Legend legend;
    for (std::size_t s = 0; s < chart.series.size(); ++s) {
        const Series& series = chart.series[s];
        if (series.name.empty()) continue;
        legend.entries.push_back(
            {wrapped(series.name, kLegendMostText), colour_of(s), marker_of(s), series.joined, false});
    }
    if (has_front) legend.entries.push_back({{"Pareto front"}, kParetoColor, Marker::circle, true, true});
    if (legend.entries.empty()) return legend;
    int text_width_most = 0, y = kLegendPadding;
    for (LegendEntry& entry : legend.entries) {
        for (const std::string& text : entry.lines) text_width_most = std::max(text_width_most, text_width(text));
        entry.top = y;
        y += static_cast<int>(entry.lines.size()) * kLineStep + 4;
    }
    legend.width = 2 * kLegendPadding + kLegendSample + 8 + text_width_most;
    legend.height = y - 4 + kLegendPadding;
    return legend;
}

void place_legend(Legend& legend, int left, int top) {
    legend.left = left;
    legend.top = top;
    for (LegendEntry& entry : legend.entries) entry.top += top;
}

void draw_legend_box(Canvas& canvas, const Legend& legend) {
    if (legend.entries.empty()) return;
    for (const LegendEntry& entry : legend.entries) {
        const double mid_y = entry.top + kCapHeight / 2.0;
        const double sample_left = legend.sample_left(), sample_right = sample_left + kLegendSample;
        const double mid_x = 0.5 * (sample_left + sample_right);
        const std::vector<Pixel> sample{{sample_left, mid_y}, {sample_right, mid_y}};
        if (entry.pareto) {
            stroke_dashed(canvas, sample, entry.colour);
            draw_pareto_ring(canvas, mid_x, mid_y);
        } else {
            if (entry.joined) stroke_thick(canvas, sample, entry.colour);
            draw_marker(canvas, entry.marker, mid_x, mid_y, entry.colour);
        }
    }
    canvas.save();
    canvas.setStrokeStyle(kBoxColor);
    canvas.strokeRect(legend.left + 0.5, legend.top + 0.5, legend.width, legend.height);
    canvas.restore();
}

void draw_legend_names(browser::Image& picture, const Legend& legend) {
    for (const LegendEntry& entry : legend.entries) {
        int line_y = entry.top;
        for (const std::string& text : entry.lines) {
            stamp(picture, ink_of(text), legend.text_left(), line_y, kTextInk);
            line_y += kLineStep;
        }
    }
}

}  // namespace bench::chart
