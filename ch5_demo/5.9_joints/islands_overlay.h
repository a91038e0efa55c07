#pragma once
// Sleeping's part of the overlay (overlay.h): the islands and the sleep rule, drawn by
// the numbers islands.cpp keeps.
//  - Each island in its own colour: every shape of it outlined again in that colour.
//    Shapes that touch are one island; a static shape joins none and keeps the page's.
//  - Each moving shape's rest timer, as a ring round it that fills clockwise from the
//    top as the shape rests: empty when its rest starts again, full after
//    time_to_sleep. An island falls asleep in the step its last ring fills.
//  - A sleeping shape: its ring full, in the gray the page draws it in.
//  - A label over each island of two shapes or more: how many shapes, and whether the
//    island sleeps or how long its least rested shape has rested, in s.
// With sleep off it draws nothing: no shape rests, and the islands are not looked for.

#include <vector>

#include "core.h"
#include "overlay_draw.h"
#include "page.h"

namespace engine {

// How far out of a shape's bounding circle its rest timer's ring runs.
inline constexpr double kRestRingGap = 3.0;  // px

void drawIslands(browser::Canvas& canvas, browser::overlay::LabelLayout& labels, const Core& core,
                 std::vector<browser::LegendEntry>& legend);

}  // namespace engine
