#pragma once
// The core's world as the stage program sees it (common/stage_main.h): every body's
// state, for --dump and the check that every number stays finite; when a fixed step has
// been taken; and what a run may cost, for its budget. Not in the book: the book's page
// runs until the reader closes it, and ours must know before it starts that it ends.

#include "core.h"
#include "stage_main.h"

namespace engine {

// The option that writes every collision event to a CSV file (5.7), a line each:
// step,kind,id_a,id_b,x,y,nx,ny,speed. 5.9 adds the kind `limit`, a joint's limit
// reached (contact_events.h says what its columns hold).
inline constexpr std::string_view kEventsOption = "--events";

browser::PageWorld pageWorld(Core& core);

// What a run of the core's world with these key presses may cost at most, counted in
// pair tests (about 45 ns each): the shapes at the start and one for each press of the
// keys that add one (F, G), every pair of them tested in every collision pass.
browser::WorldCost worldCost(const Core& core, const browser::KeyScript& keys);

}  // namespace engine
