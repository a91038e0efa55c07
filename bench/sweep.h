#pragma once
// The settings a scene is run with: its own world first, then the knobs changed one
// at a time from it, each over its range:
//   relaxation_iterations {1, 2, 4, 8, 15, 30}   dt {1/30, 1/60, 1/120, 1/240}
//   substeps {1, 2, 4, 8}   each broad phase, integrator and friction model
//   rotation off, friction off
// One at a time, so each row says what that one knob does; a setting equal to one
// already listed (the scene's own value of a knob) is not run twice.

#include <string>
#include <vector>

#include "scene_file.h"

namespace bench {

enum class Knob { relaxation_iterations, dt, substeps, broad_phase, integrator, friction_model, rotation, friction };

// How many of a knob's values to try: all of them, or only the first that differs from
// the scene's (passes 1, dt 1/30, substeps 2, ...), where a scene is too big to try all.
enum class Range { all, one };
struct Sweep {
    Knob knob;
    Range range = Range::all;
};

struct Setting {
    std::string varied;  // the knob's name as in scene files, "" for the scene's own world
    std::string label;   // for tables and charts: "passes 8", "dt 1/120", "grid", "scene"
    browser::WorldSettings world;
};

// With `quick`, every knob takes one value besides the scene's.
std::vector<Setting> one_at_a_time(const browser::WorldSettings& base, const std::vector<Sweep>& sweeps, bool quick);

// "dt 1/120" for 1/120 s: steps are best read as steps per second.
std::string dt_label(double dt);

}  // namespace bench
