#pragma once
// The core's world as the stage program sees it (common/stage_main.h): what a run
// may cost, for its budget. Not in the book: the book's page runs until the reader
// closes it, and ours must know before it starts that it ends.

#include "core.h"
#include "stage_main.h"

namespace engine {

browser::PageWorld pageWorld(Core& core);

// What a run of the core's world with these key presses may cost at most, in units of
// about 45 ns: the shapes at the start and one for each press of the keys that add one
// (F, G), each drawn every frame.
browser::WorldCost worldCost(const Core& core, const browser::KeyScript& keys);

}  // namespace engine
