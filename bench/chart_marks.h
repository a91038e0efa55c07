#pragma once
// The strokes of a chart: thick and dashed lines, the markers that tell the series
// apart, and the ring round a point on the Pareto front.

#include <cstddef>
#include <vector>

#include "canvas.h"

namespace bench::chart {

using browser::Canvas;
using browser::Color;

struct Pixel {
    double x, y;
};

// Markers are told apart by shape as well as colour, so the chart reads in grey too.
enum class Marker { circle, square, triangle_up, diamond, triangle_down, cross, plus, star };

// Each series' colour and marker, by its place in the chart.
Color colour_of(std::size_t series);
Marker marker_of(std::size_t series);

// Data lines a little over 1.5 px wide: the 1 px pen drawn three times, nudged half a pixel
// across and down.
void stroke_thick(Canvas& canvas, const std::vector<Pixel>& line, Color color);
// A dashed line through the pixels: dashes and gaps measured along the whole line, so the
// pattern runs on round its corners.
void stroke_dashed(Canvas& canvas, const std::vector<Pixel>& line, Color color);

// A hollow marker with a white face, so lines under it do not show through; its rim is
// two outlines a pixel apart, to stand out from the 1 px grid.
void draw_marker(Canvas& canvas, Marker marker, double cx, double cy, Color color);
void draw_pareto_ring(Canvas& canvas, double cx, double cy);

// A horizontal or vertical 1 px line lands on one row or column of pixels when it runs
// through pixel centres.
double centred(double pixel);
void draw_line(Canvas& canvas, double x0, double y0, double x1, double y1, Color color);

}  // namespace bench::chart
