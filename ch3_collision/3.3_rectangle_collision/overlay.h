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

#include <cstddef>

#include "browser.h"
#include "core.h"

namespace engine {

// The most entries the overlay's legend holds, with the stage's own layer alone and with
// every layer on: the page keeps a band for that many under it (page.h's
// Document::legend_entries), the second in a run where every layer can come on, so that
// every picture of a run has one height, whichever layers are on.
inline constexpr std::size_t kOwnLegendEntries = 4;
inline constexpr std::size_t kLegendEntries = 5;

// While window.overlay is on, draws the overlay onto the canvas and sets the legend;
// while it is off, takes the legend away. Called last in a frame, over everything.
void drawOverlay(browser::Window& window, const Core& core);

}  // namespace engine
