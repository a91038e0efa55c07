#pragma once
// 5.8's part of the overlay (overlay.h): GJK (gjk.h) drawn by its own numbers, for one
// pair: the selected shape and the shape nearest to it.
//  - In an inset box in the canvas's top-right corner, the pair's Minkowski difference
//    A - B, which GJK never builds: the hull of every a - b of their corners, scaled to
//    fit. A circle is its centre and a radius, so A - B is then rounded by the radii:
//    a ring of their sum round each corner of the hull.
//  - The origin as a cross: the shapes share a point exactly when A - B holds it.
//  - GJK's last simplex (1 to 3 support points, joined), where its walk stopped.
//  - The line from the origin to the point of A - B nearest it: its length is the
//    distance between the shapes.
//  - On the canvas itself, the two closest points joined, with the distance in px.

#include <cstddef>
#include <optional>
#include <vector>

#include "core.h"
#include "gjk.h"
#include "overlay_draw.h"
#include "page.h"

namespace engine {

// What the diagram draws, worked out apart from the drawing so a test can check it.
struct GjkDiagram {
    std::size_t first = 0;   // A: the selected shape
    std::size_t second = 0;  // B: the shape nearest to it (the first of equals)
    // The corners of A - B's core, counter-clockwise: the hull of every a_i - b_j (one
    // point for two circles, two for a circle and a segment-thin hull).
    std::vector<Vec2> difference;
    double radius = 0.0;  // px: A - B is its core rounded by this (the two radii)
    DistanceResult gjk;   // GJK's answer for A and B: distance, closest points, simplex
};

// The pair and its diagram; nothing when the world holds fewer than two shapes.
std::optional<GjkDiagram> gjkDiagram(const Core& core);

void drawGjk(browser::Canvas& canvas, browser::overlay::LabelLayout& labels, const Core& core,
             std::vector<browser::LegendEntry>& legend);

}  // namespace engine
