#include "chart_layout.h"

#include <algorithm>

#include "chart_look.h"
#include "chart_text.h"

namespace bench::chart {
namespace {

std::vector<Image> label_inks(const std::vector<Tick>& ticks) {
    std::vector<Image> inks;
    for (const Tick& tick : ticks) inks.push_back(ink_of(tick.label));
    return inks;
}

}  // namespace

Layout lay_out(const Chart& chart, const std::vector<std::string>& notes, const std::vector<ChartPoint>& placed,
               bool has_front) {
    Layout layout;
    const int text_room = kChartWidth - 2 * kMargin;
    layout.title_lines = wrapped(chart.title, text_room);
    if (chart.title.empty()) layout.title_lines.clear();
    for (const std::string& note : notes) {
        for (std::string& piece : wrapped(note, text_room)) layout.note_lines.push_back(std::move(piece));
    }
    const auto header_lines = static_cast<int>(layout.title_lines.size() + layout.note_lines.size());

    // Top to bottom: header, plot, x tick labels, x axis label.
    layout.plot_top = kMargin + header_lines * kLineStep + 12;  // the top y label reaches 7 px above
    layout.plot_bottom =
        kChartHeight - kMargin - (chart.x_label.empty() ? 0 : kLineStep + 4) - kInkHeight - kLabelGap - kTickLength;

    std::vector<double> xs, ys;
    for (const ChartPoint& p : placed) {
        xs.push_back(chart.log_x ? std::log10(p.x) : p.x);
        ys.push_back(chart.log_y ? std::log10(p.y) : p.y);
    }
    const auto [y_low, y_high] = axis_ends(ys, chart.log_y);
    layout.y = {chart.log_y, y_low, y_high, centred(layout.plot_bottom), centred(layout.plot_top)};
    layout.y_marks = axis_marks(layout.y, 55.0);
    layout.y_label_inks = label_inks(layout.y_marks.ticks);
    layout.y_shown =
        labels_that_fit(layout.y_marks.ticks, layout.y, std::vector<int>(layout.y_marks.ticks.size(), kCapHeight), 6.0);
    int widest_y_label = 0;
    for (std::size_t i = 0; i < layout.y_label_inks.size(); ++i) {
        if (layout.y_shown[i]) widest_y_label = std::max(widest_y_label, layout.y_label_inks[i].width);
    }

    // Left to right: y axis label (turned), y tick labels, plot, legend.
    layout.plot_left =
        kMargin + (chart.y_label.empty() ? 0 : kInkHeight + 12) + widest_y_label + kLabelGap + kTickLength;
    layout.legend = list_legend(chart, has_front);
    const bool has_legend = !layout.legend.entries.empty();
    layout.plot_right = kChartWidth - kMargin - (has_legend ? layout.legend.width + kLegendGap : 16);
    place_legend(layout.legend, static_cast<int>(layout.plot_right) + kLegendGap, static_cast<int>(layout.plot_top));

    const auto [x_low, x_high] = axis_ends(xs, chart.log_x);
    layout.x = {chart.log_x, x_low, x_high, centred(layout.plot_left), centred(layout.plot_right)};
    layout.x_marks = axis_marks(layout.x, 90.0);
    layout.x_label_inks = label_inks(layout.x_marks.ticks);
    std::vector<int> widths;
    for (const Image& ink : layout.x_label_inks) widths.push_back(ink.width);
    layout.x_shown = labels_that_fit(layout.x_marks.ticks, layout.x, widths, 12.0);
    return layout;
}

bool on_scale(const ChartPoint& point, const Chart& chart) {
    return on_scale(point.x, chart.log_x) && on_scale(point.y, chart.log_y);
}

Pixel pixel_of(const ChartPoint& point, const Layout& layout) {
    return {layout.x.pixel(point.x), layout.y.pixel(point.y)};
}

}  // namespace bench::chart
