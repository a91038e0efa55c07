#include "chart_marks.h"

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <numbers>

#include "chart_look.h"

namespace bench::chart {
namespace {

constexpr int kMarkerCount = 8;

// The outline of a marker of size r round (cx, cy), as the current path.
void marker_path(Canvas& canvas, Marker marker, double cx, double cy, double r) {
    canvas.beginPath();
    const auto polygon = [&](std::initializer_list<Pixel> corners) {
        for (const Pixel& c : corners) canvas.lineTo(cx + c.x, cy + c.y);
        canvas.closePath();
    };
    const auto bar = [&](double dx, double dy) {
        canvas.moveTo(cx - dx, cy - dy);
        canvas.lineTo(cx + dx, cy + dy);
    };
    // Sizes balanced by eye: a square as wide as a circle looks heavier, a triangle lighter.
    const double s = 0.85 * r, t = 1.25 * r, d = 1.2 * r;
    switch (marker) {
        case Marker::circle: canvas.arc(cx, cy, r, 0.0, 2.0 * std::numbers::pi); break;
        case Marker::square: polygon({{-s, -s}, {s, -s}, {s, s}, {-s, s}}); break;
        case Marker::triangle_up: polygon({{0, -t}, {0.866 * t, 0.5 * t}, {-0.866 * t, 0.5 * t}}); break;
        case Marker::diamond: polygon({{0, -d}, {d, 0}, {0, d}, {-d, 0}}); break;
        case Marker::triangle_down: polygon({{0, t}, {-0.866 * t, -0.5 * t}, {0.866 * t, -0.5 * t}}); break;
        case Marker::cross:
            bar(s, s);
            bar(s, -s);
            break;
        case Marker::plus:
            bar(r, 0);
            bar(0, r);
            break;
        case Marker::star:
            bar(r, 0);
            bar(0.5 * r, 0.866 * r);
            bar(0.5 * r, -0.866 * r);
            break;
    }
}

bool has_inside(Marker marker) { return marker != Marker::cross && marker != Marker::plus && marker != Marker::star; }

}  // namespace

Color colour_of(std::size_t series) { return kPalette[series % kColourCount]; }
Marker marker_of(std::size_t series) { return static_cast<Marker>(series % kMarkerCount); }

void stroke_thick(Canvas& canvas, const std::vector<Pixel>& line, Color color) {
    for (const Pixel nudge : {Pixel{0.0, 0.0}, Pixel{0.5, 0.0}, Pixel{0.0, 0.5}}) {
        canvas.save();
        canvas.setStrokeStyle(color);
        canvas.translate(nudge.x, nudge.y);
        canvas.beginPath();
        for (const Pixel& p : line) canvas.lineTo(p.x, p.y);
        canvas.stroke();
        canvas.restore();
    }
}

void stroke_dashed(Canvas& canvas, const std::vector<Pixel>& line, Color color) {
    constexpr double kDash = 7.0, kGap = 5.0;
    std::vector<std::vector<Pixel>> dashes;
    double along = 0.0;  // position in the current dash-and-gap period
    bool drawing = false;
    for (std::size_t k = 1; k < line.size(); ++k) {
        const Pixel a = line[k - 1], b = line[k];
        const double length = std::hypot(b.x - a.x, b.y - a.y);
        double done = 0.0;
        while (done < length) {
            const bool in_dash = along < kDash;
            const double piece = std::min(length - done, in_dash ? kDash - along : kDash + kGap - along);
            const Pixel from{a.x + (b.x - a.x) * done / length, a.y + (b.y - a.y) * done / length};
            done += piece;
            const Pixel to{a.x + (b.x - a.x) * done / length, a.y + (b.y - a.y) * done / length};
            if (in_dash) {
                if (!drawing) dashes.push_back({from});
                dashes.back().push_back(to);
            }
            drawing = in_dash && along + piece < kDash;
            along = std::fmod(along + piece, kDash + kGap);
        }
    }
    for (const auto& dash : dashes) stroke_thick(canvas, dash, color);
}

void draw_marker(Canvas& canvas, Marker marker, double cx, double cy, Color color) {
    canvas.save();
    if (has_inside(marker)) {
        canvas.setStrokeStyle(browser::colors::kWhite);
        for (double r = kMarkerRadius - 1.0; r > 0.0; r -= 0.6) {
            marker_path(canvas, marker, cx, cy, r);
            canvas.stroke();
        }
    }
    canvas.setStrokeStyle(color);
    marker_path(canvas, marker, cx, cy, kMarkerRadius);
    canvas.stroke();
    if (has_inside(marker)) {
        marker_path(canvas, marker, cx, cy, kMarkerRadius - 0.8);
    } else {  // bars: thickened across instead of nested
        canvas.translate(0.5, 0.5);
        marker_path(canvas, marker, cx, cy, kMarkerRadius);
    }
    canvas.stroke();
    canvas.restore();
}

void draw_pareto_ring(Canvas& canvas, double cx, double cy) {
    canvas.save();
    canvas.setStrokeStyle(kParetoColor);
    for (double r : {kParetoRadius, kParetoRadius - 0.7}) {
        canvas.beginPath();
        canvas.arc(cx, cy, r, 0.0, 2.0 * std::numbers::pi);
        canvas.stroke();
    }
    canvas.restore();
}

double centred(double pixel) { return std::floor(pixel) + 0.5; }

void draw_line(Canvas& canvas, double x0, double y0, double x1, double y1, Color color) {
    canvas.save();
    canvas.setStrokeStyle(color);
    canvas.beginPath();
    canvas.moveTo(x0, y0);
    canvas.lineTo(x1, y1);
    canvas.stroke();
    canvas.restore();
}

}  // namespace bench::chart
