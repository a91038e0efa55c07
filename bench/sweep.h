#pragma once
// The settings a scene is run with: its own world on each stage of the study, then the
// knobs changed one at a time from it, each over its range:
//   relaxation_iterations {1, 2, 4, 8, 15, 30}   correction_rate {0.2, 0.4, 0.6, 0.8, 1}
//   dt {1/30, 1/60, 1/120, 1/240}   broad_phase: each   substeps {1, 2, 4, 8}
//   integrator: each   friction_model: each   rotation off   friction off
//   solver sequential_impulse, and with it: velocity_iterations {2, 4, 8, 12, 16},
//   warm_starting off, position_method: each   sleep off, and on with sequential_impulse
// One at a time, so each row says what that one knob does. Each setting runs on the
// oldest stage of the study that can express it (stages.h): passes, correction and dt
// on the book's 5.1, the broad phase on 5.2, the rest on 5.3, the solver on 5.4 and
// sleep on 5.5 (5.6 and 5.7 add no knob of their own here); a setting no stage of the
// study can express is not run. A setting its stage reads as one already listed for
// that stage (the stage's own default, say) is not run twice.

#include <string>
#include <vector>

#include "scene_description.h"
#include "stages.h"

namespace bench {

enum class Knob {
    relaxation_iterations,
    correction_rate,
    dt,
    broad_phase,
    substeps,
    integrator,
    friction_model,
    rotation,
    friction,
    solver,               // 5.4: the sequential impulse solver with its defaults
    velocity_iterations,  // ... with 2, 4, 8, 12, 16 velocity iterations
    warm_starting,        // ... without warm starting
    position_method,      // ... with each way of removing overlap
    sleep                 // 5.5: sleep off, and sleep on with the sequential impulse solver
};

// How many of a knob's values to try: all of them, or only the first that makes a new
// setting (passes 1, dt 1/30, substeps 2, ...), where a scene is too big to try all.
enum class Range { all, one };
struct Sweep {
    Knob knob;
    Range range = Range::all;
};

struct Setting {
    Stage stage = Stage::s5_1;
    std::string varied;      // the knob's key in scene files, "" for the scene's own world
    std::string label;       // for tables and charts: "passes 8", "dt 1/120", "grid", "scene"
    WorldDescription world;  // as handed to the stage: keys it leaves unset are the stage's default
};

// The scene's own world on each stage first, then the knobs' settings, stage by stage.
// With `quick`, every knob takes one value besides the scene's. `stages` oldest first.
std::vector<Setting> one_at_a_time(const WorldDescription& base, const std::vector<Stage>& stages,
                                   const std::vector<Sweep>& sweeps, bool quick);

// "dt 1/120" for 1/120 s: steps are best read as steps per second.
std::string dt_label(double dt);

// A knob's key as a legend says it: "passes" for relaxation_iterations, "broad phase".
std::string knob_title(const std::string& key);

}  // namespace bench
