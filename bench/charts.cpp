#include "charts.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "chart_layout.h"
#include "chart_look.h"
#include "chart_text.h"
#include "png_io.h"
#include "statistics.h"

namespace bench {
namespace {

using namespace chart;

void draw_grid_and_axes(Canvas& canvas, const Layout& layout) {
    const double left = centred(layout.plot_left), right = centred(layout.plot_right);
    const double top = centred(layout.plot_top), bottom = centred(layout.plot_bottom);
    for (double u : layout.x_marks.minor_units) {
        const double x = centred(layout.x.pixel_of_units(u));
        draw_line(canvas, x, top, x, bottom, kMinorGridColor);
    }
    for (double u : layout.y_marks.minor_units) {
        const double y = centred(layout.y.pixel_of_units(u));
        draw_line(canvas, left, y, right, y, kMinorGridColor);
    }
    for (const Tick& tick : layout.x_marks.ticks) {
        const double x = centred(layout.x.pixel_of_units(tick.units));
        draw_line(canvas, x, top, x, bottom, kGridColor);
        draw_line(canvas, x, bottom, x, bottom + kTickLength, kAxisColor);
    }
    for (const Tick& tick : layout.y_marks.ticks) {
        const double y = centred(layout.y.pixel_of_units(tick.units));
        draw_line(canvas, left, y, right, y, kGridColor);
        draw_line(canvas, left - kTickLength, y, left, y, kAxisColor);
    }
    canvas.save();
    canvas.setStrokeStyle(kAxisColor);
    canvas.strokeRect(left, top, right - left, bottom - top);
    canvas.restore();
}

// Dashes from ring to ring, which leave the markers on the front clear.
void draw_front_line(Canvas& canvas, const std::vector<Pixel>& front) {
    for (std::size_t k = 1; k < front.size(); ++k) {
        const Pixel a = front[k - 1], b = front[k];
        const double length = std::hypot(b.x - a.x, b.y - a.y);
        if (length <= 2.0 * kParetoRadius) continue;  // rings touching: no room for a line
        const double ux = (b.x - a.x) / length * kParetoRadius, uy = (b.y - a.y) / length * kParetoRadius;
        stroke_dashed(canvas, {{a.x + ux, a.y + uy}, {b.x - ux, b.y - uy}}, kParetoColor);
    }
}

// The lines of the joined series first, then all markers, so no line crosses a marker.
void draw_series(Canvas& canvas, const Chart& chart, const Layout& layout) {
    for (std::size_t s = 0; s < chart.series.size(); ++s) {
        if (!chart.series[s].joined) continue;
        std::vector<Pixel> run;  // a point off the scale breaks the line: nothing is known there
        const auto end_run = [&] {
            stroke_thick(canvas, run, colour_of(s));
            run.clear();
        };
        for (const ChartPoint& point : chart.series[s].points) {
            if (on_scale(point, chart)) run.push_back(pixel_of(point, layout));
            else end_run();
        }
        end_run();
    }
    for (std::size_t s = 0; s < chart.series.size(); ++s) {
        for (const ChartPoint& point : chart.series[s].points) {
            if (!on_scale(point, chart)) continue;
            const Pixel p = pixel_of(point, layout);
            draw_marker(canvas, marker_of(s), p.x, p.y, colour_of(s));
        }
    }
}

void draw_texts(Image& picture, const Chart& chart, const Layout& layout) {
    int y = kMargin;
    for (const std::string& text : layout.title_lines) {  // bold: the letters twice, a pixel apart
        const Image ink = ink_of(text);
        stamp(picture, ink, kMargin, y, kTextInk);
        stamp(picture, ink, kMargin + 1, y, kTextInk);
        y += kLineStep;
    }
    for (const std::string& text : layout.note_lines) {
        stamp(picture, ink_of(text), kMargin, y, kNoteInk);
        y += kLineStep;
    }

    const int below_ticks = whole(layout.plot_bottom) + kTickLength + kLabelGap;
    for (std::size_t i = 0; i < layout.x_marks.ticks.size(); ++i) {
        if (!layout.x_shown[i]) continue;
        const Image& ink = layout.x_label_inks[i];
        const int centre = whole(layout.x.pixel_of_units(layout.x_marks.ticks[i].units));
        stamp(picture, ink, centre - ink.width / 2, below_ticks, kTextInk);
    }
    for (std::size_t i = 0; i < layout.y_marks.ticks.size(); ++i) {
        if (!layout.y_shown[i]) continue;
        const Image& ink = layout.y_label_inks[i];
        const int centre = whole(layout.y.pixel_of_units(layout.y_marks.ticks[i].units));
        stamp(picture, ink, whole(layout.plot_left) - kTickLength - kLabelGap - ink.width, centre - kCapHeight / 2,
              kTextInk);
    }

    const int plot_middle_x = whole(0.5 * (layout.plot_left + layout.plot_right));
    const int plot_middle_y = whole(0.5 * (layout.plot_top + layout.plot_bottom));
    if (!chart.x_label.empty()) {
        const Image ink = ink_of(chart.x_label);
        const int x =
            std::clamp(plot_middle_x - ink.width / 2, kMargin, std::max(kMargin, kChartWidth - kMargin - ink.width));
        stamp(picture, ink, x, below_ticks + kLineStep + 4, kTextInk);
    }
    if (!chart.y_label.empty()) {
        const Image ink = turned_up(ink_of(chart.y_label));
        const int top = std::max(whole(layout.plot_top) - 8, plot_middle_y - ink.height / 2);
        stamp(picture, ink, kMargin, top, kTextInk);
    }
}

// Point labels in the small font, in a darker shade of the series' colour (light colours
// make faint letters), right of the marker, or left of it near the right edge, and clear
// of the ring round a point on the Pareto front.
void draw_point_labels(Image& picture, const Chart& chart, const Layout& layout, const std::vector<ChartPoint>& front) {
    const auto darker = [](std::uint8_t channel) { return static_cast<std::uint8_t>(channel * 7 / 10); };
    for (std::size_t s = 0; s < chart.series.size(); ++s) {
        const Color colour = colour_of(s);
        const Color ink_colour{darker(colour.r), darker(colour.g), darker(colour.b), 255};
        for (const ChartPoint& point : chart.series[s].points) {
            if (point.label.empty() || !on_scale(point, chart)) continue;
            const bool ringed = std::any_of(front.begin(), front.end(),
                                            [&](const ChartPoint& f) { return f.x == point.x && f.y == point.y; });
            const Image ink = small_ink_of(point.label);
            const int x = whole(layout.x.pixel(point.x)), y = whole(layout.y.pixel(point.y));
            const int room = static_cast<int>(ringed ? kParetoRadius : kMarkerRadius) + 4;
            const int left = x + room + ink.width <= whole(layout.plot_right) - 2 ? x + room : x - room - ink.width;
            stamp(picture, ink, left, y - kCapHeight / 4, ink_colour);
        }
    }
}

}  // namespace

void write_chart(const Chart& chart, const std::filesystem::path& png) {
    std::vector<ChartPoint> placed;
    int off_scale = 0;
    for (const Series& series : chart.series) {
        for (const ChartPoint& point : series.points) {
            if (on_scale(point, chart)) placed.push_back(point);
            else ++off_scale;
        }
    }
    std::vector<std::string> notes = chart.notes;
    if (off_scale > 0)
        notes.push_back(std::to_string(off_scale) + (off_scale == 1 ? " point" : " points") + " off the scale");
    const std::vector<ChartPoint> front = chart.mark_pareto ? pareto_front(placed) : std::vector<ChartPoint>{};
    const Layout layout = lay_out(chart, notes, placed, !front.empty());

    Canvas canvas(kChartWidth, kChartHeight);
    draw_grid_and_axes(canvas, layout);
    std::vector<Pixel> front_pixels;
    for (const ChartPoint& p : front) front_pixels.push_back(pixel_of(p, layout));
    draw_front_line(canvas, front_pixels);
    draw_series(canvas, chart, layout);
    for (const Pixel& p : front_pixels) draw_pareto_ring(canvas, p.x, p.y);
    draw_legend_box(canvas, layout.legend);
    canvas.save();
    canvas.setStrokeStyle(kBoxColor);
    canvas.strokeRect(0.5, 0.5, kChartWidth - 1.0, kChartHeight - 1.0);
    canvas.restore();

    Image picture = canvas.pixels();
    draw_texts(picture, chart, layout);
    draw_legend_names(picture, layout.legend);
    draw_point_labels(picture, chart, layout, front);
    browser::write_png(png, picture);
}

}  // namespace bench
