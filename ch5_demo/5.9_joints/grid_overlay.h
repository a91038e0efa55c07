#pragma once
// 5.2's part of the overlay (overlay.h): the grid broad phase at work, when the
// world uses it.
//  - The grid's cells, and the cells each shape's widened box reaches into: two shapes
//    become candidates only by sharing one of them.
//  - The candidate pairs on the list the relaxation passes walk, centre to centre. A
//    shape too large for the cells (a floor) is every shape's candidate: its pairs are
//    counted, not drawn.
//  - The count: the pair tests the book's loop makes in a step (every pair, every
//    pass) against the grid's, and how many it saved.

#include <vector>

#include "core.h"
#include "page.h"

namespace engine {

void drawGrid(browser::Canvas& canvas, const Core& core, std::vector<browser::LegendEntry>& legend);

}  // namespace engine
