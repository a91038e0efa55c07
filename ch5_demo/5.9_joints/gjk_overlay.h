#pragma once
// 5.8's part of the overlay (overlay.h): GJK (gjk.h) drawn by its own numbers, for one
// pair: the selected shape and the shape nearest to it. The diagram is a row of small
// panels in a corner of the canvas, the one the scene leaves emptiest (the top right
// first), every one the same picture of the pair's Minkowski difference A - B at the
// same scale, so that the walk can be followed from panel to panel:
//  - A - B, which GJK never builds: the hull of every a - b of their corners. A circle is
//    its centre and a radius, so A - B is then rounded by the radii: a ring of their sum
//    round each corner of the hull. The origin is the black cross: the shapes share a
//    point exactly when A - B holds it.
//  - One panel a pass of GJK's loop (gjk.h's GjkStep, recorded by the very call the
//    engine makes, never worked out again here), numbered from 1: the simplex as that
//    pass solved it (cut to the feature nearest the origin), the search direction as an
//    arrow from the simplex's point nearest the origin, and the support point that
//    direction found, ringed. The next panel shows it joined, or the label says the walk
//    ended there: "no nearer" (the point brought the simplex no nearer the origin, so
//    the simplex is the answer) or "inside" (the simplex holds the origin).
//  - A last panel with the answer: apart, the line from the origin to the point of A - B
//    nearest it, whose length is the distance; overlapping, the polygon EPA (epa.h) grew
//    inside A - B, its normal, and the depth.
//  - On the canvas itself, the two closest points joined, with the distance in px.

#include <cstddef>
#include <optional>
#include <vector>

#include "core.h"
#include "epa.h"
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
    double radius = 0.0;         // px: A - B is its core rounded by this (the two radii)
    DistanceResult gjk;          // GJK's answer for A and B: distance, closest points, simplex
    std::vector<GjkStep> steps;  // that call's passes, one panel each
    // When the cores overlap: EPA's answer and the polygon it ended on (points of A - B).
    std::optional<EpaPenetration> epa;
    std::vector<Vec2> epa_polygon;
    // px: how deep the shapes overlap: EPA's depth of the cores and the radii, or for
    // rounded shapes whose cores are apart, the radii less the cores' distance. 0 when
    // they are apart.
    double depth = 0.0;
};

// The pair and its diagram; nothing when the world holds fewer than two shapes.
std::optional<GjkDiagram> gjkDiagram(const Core& core);

// Where the diagram's panels go on a canvas `canvas_width` px wide: their top-left
// corners, one a pass and the answer's last, in a row right-aligned along the top edge
// and wrapped to another row below when they do not fit.
std::vector<Vec2> gjkPanelCorners(std::size_t panels, double canvas_width);

// A box on the canvas, px: what the scene draws somewhere (a shape and its joints' anchors).
struct CanvasBox {
    Vec2 low, high;
};

// Every shape's box: its corners (a circle's centre) and radius, as GJK sees it.
std::vector<CanvasBox> shapeBoxes(const Core& core);

// The same block of panels in whichever corner of a canvas `canvas_width` x
// `canvas_height` px it covers the least of `occupied` in (the area of the boxes under
// it): the top right, the top left, the bottom right or the bottom left, the first of
// them on a tie. Panels over the
// scene would hide what its layers draw there (a pendulum's pin, its limit event); a
// corner keeps them together where the eye finds them, and where the scene is emptiest.
std::vector<Vec2> gjkPanelCorners(std::size_t panels, double canvas_width, double canvas_height,
                                  const std::vector<CanvasBox>& occupied);
// Each panel this large: wide enough for a label of 14 letters ("123.45 px deep"), and
// short enough that a row of them leaves the top end of the demo's long slide uncovered.
inline constexpr double kGjkPanelWidth = 136.0;   // px
inline constexpr double kGjkPanelHeight = 108.0;  // px
inline constexpr double kGjkPanelMargin = 8.0;    // px from the canvas's edges
inline constexpr double kGjkPanelGap = 6.0;       // px between two panels, and between two rows

void drawGjk(browser::Canvas& canvas, browser::overlay::LabelLayout& labels, const Core& core,
             std::vector<browser::LegendEntry>& legend);

}  // namespace engine
