#pragma once
// 5.7's part of the overlay (overlay.h): the collision events (contact_events.h) where
// they happened, each shown for kShownSteps steps (half a second) and shrinking as it
// ages, so that a reader sees what the game's logic hears.
//  - A begin: a ring at the middle of the overlap where the pair was first found.
//  - An end: a cross where the pair last touched.
//  - A hit: a larger ring round its begin, and the speed the surfaces met at.
//  - A limit (5.9): a diamond at the joint's anchor where its limit began to hold, and
//    the speed it closed at (rad/s for an angle, px/s for a slider's or a rope's).
//  - A sensor (rigid_shape.h): its outline is the page's (green); the overlay names it.
//  - The legend counts the events of the last half second, kind by kind, and the pairs
//    touching now.

#include <vector>

#include "core.h"
#include "overlay_draw.h"
#include "page.h"

namespace engine {

void drawEvents(browser::Canvas& canvas, browser::overlay::LabelLayout& labels, const Core& core,
                std::vector<browser::LegendEntry>& legend);

}  // namespace engine
