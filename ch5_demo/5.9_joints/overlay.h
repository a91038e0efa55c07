#pragma once
// The stage's overlay (--overlay, or the key t live and in key scripts): what the
// engine computed this frame, drawn over the book's picture, with a legend in a band
// under the page that names each colour. The book's pictures stay the book's: with the
// overlay off nothing here draws.
//
// It comes in layers: by default the stage's own technique (with what a reader needs to
// read it); the key t pressed again, or --overlay-all, adds the layers of the stages
// before (drawOverlay says which). Its numbers are fixed decimals with their unit, and
// its labels never cover each other.
//
// From 3.2 on the pass finds the collision info of each colliding pair (Figure
// 3-6), and the overlay shows it all: the start and the end of the overlap, the normal
// (drawn 20 px long, so its direction shows even where the overlap is a hair deep) and
// the depth in numbers, where the book shows only the line from start to end.
//
// Chapter 4 sets the shapes moving: each moving shape gets its velocity as an arrow
// from its centre to where that velocity takes it in half a second, and its angular
// velocity as a curved arrow round its centre, turning the way the shape turns, as far
// as it turns in half a second.
//
// Positional correction moves overlapping shapes apart, a little each relaxation pass:
// an arrow from each corrected shape's centre shows how far the passes of the last step
// moved it in all, ten times larger so that fractions of a pixel show (and cut at 60 px,
// where shapes made inside each other are pushed out by tens of pixels in one step).
//
// From 4.3 the book no longer draws the collision info; the overlay still does. Each
// resolved pair gets the impulses of the last step at its contact: the normal
// impulse (the bounce) and the tangent impulse (friction), as the second shape received
// them (the first got the same, turned round), with their sizes in numbers.
//
// From 4.4 the impulses act at a contact point and turn the shapes: they are drawn
// there, with the lever arms from both centres to it, and each shape of the pair gets
// a second curved arrow, outside its spin, for the change of spin the impulses gave it
// (as far as that change turns the shape in half a second).
//
// 5.2's grid broad phase adds its own (grid_overlay.h): the grid's cells, the candidate
// pairs on its list, and the pair tests a pass saves.
//
// 5.4's contact solver adds its contacts (contact_overlay.h): reference and incident
// faces, the clipped points, and the totals each point ended the step with.
//
// 5.5's sleeping adds its islands (islands_overlay.h): each island in its own colour,
// each shape's rest timer as a ring that fills, the sleeping shapes; and the grid's
// layer leaves out the pairs the broad phase passes over asleep.
//
// 5.6's continuous collision adds the sweeps (continuous.h): each fast shape's
// path in the last step, and where the sweep stopped it.
//
// 5.7's collision events add their own (events_overlay.h): each begin, end and hit
// where it happened, for half a second, and their counts.
//
// 5.8's GJK adds its diagram (gjk_overlay.h): for the selected shape and the one
// nearest it, their Minkowski difference in a row of panels, one a pass of GJK's walk,
// then the distance or EPA's depth; and on the canvas the two closest points.
//
// 5.9's joints add theirs (joints_overlay.h): anchors, links, limits and each joint's
// error in px, and the legend names the page's kinematic bodies and mouse line; its
// limit events join 5.7's (events_overlay.h).

#include <cstddef>

#include "browser.h"
#include "core.h"

namespace engine {

// The most entries the overlay's legend holds, with the stage's own layer alone and with
// every layer on: the page keeps a band for that many under it (page.h's
// Document::legend_entries), the second in a run where every layer can come on, so that
// every picture of a run has one height, whichever layers are on.
inline constexpr std::size_t kOwnLegendEntries = 7;
inline constexpr std::size_t kLegendEntries = 43;
// The widest an entry's text can be, px (page.h's Document::legend_text_width): the
// events' counts ("in 0.5 s: begins 10, ends 10, hits 10; touching 10" is 440 px) are
// wider than the 366 px of the stages before; the band's columns are made this wide, two
// on a page 980 px wide or more, so that no entry runs into the next column or off the
// page. The drawing test measures every entry against it.
inline constexpr int kLegendTextWidth = 460;

// While window.overlay is on, draws the overlay onto the canvas and sets the legend;
// while it is off, takes the legend away. Called last in a frame, over everything.
void drawOverlay(browser::Window& window, const Core& core);

}  // namespace engine
