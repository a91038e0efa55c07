#pragma once
// The error measures, worked out on a Snapshot with nothing taken from the engine
// being measured.

#include <cstddef>

#include "bench_world.h"

namespace bench {

// How deep the shapes overlap: a resting pile should not overlap at all, so every
// pixel of overlap is error. Pairs of two static bodies are left out: nothing moves
// them, and a box's walls may overlap at its corners by design.
struct Penetration {
    double max = 0.0;       // px, the deepest pair (0 when none overlap)
    double mean = 0.0;      // px, over the overlapping pairs (0 when none overlap)
    std::size_t pairs = 0;  // how many pairs overlap
};
Penetration penetration(const Snapshot& bodies);

// Sum of 1/2 m v^2 + 1/2 I w^2 over the moving bodies: mass px^2/s^2.
double kinetic_energy(const Snapshot& bodies);

// The moving body highest on the screen (smallest y; +y is down): the top of a pile.
std::size_t top_body(const Snapshot& bodies);

}  // namespace bench
