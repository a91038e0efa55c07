#pragma once
// Which engine makes a row: one of the chapter 5 stages, each the engine of its own
// folder, or Box2D as the reference (box2d_world.h).
//   5.1  ch5_demo/5.1_cool_demo            the book's engine: passes, dt, correction
//   5.2  ch5_demo/5.2_spatial_partitioning + broad_phase (its default: the grid)
//   5.3  ch5_demo/5.3_speed_vs_accuracy    + substeps, integrator, friction_model,
//                                            rotation, friction
//   5.4  ch5_demo/5.4_contact_solver       + solver and its knobs
//   5.5  ch5_demo/5.5_sleeping             + sleep (its default: on)
//   5.6  ch5_demo/5.6_continuous_collision + continuous (its default: on)
// What a stage can vary is what its scene files may say: the bench asks the stage for
// its world keys rather than keeping a table of its own.

#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "bench_world.h"
#include "scene_description.h"
#include "stage_engine.h"

namespace bench {

enum class Stage { s5_1, s5_2, s5_3, s5_4, s5_5, s5_6, box2d };

// Oldest first.
inline constexpr std::array kChapter5Stages{Stage::s5_1, Stage::s5_2, Stage::s5_3,
                                            Stage::s5_4, Stage::s5_5, Stage::s5_6};

// "5.1" to "5.6", or Box2D's own name and version ("Box2D 2.4").
std::string stage_name(Stage stage);

// A chapter 5 stage's engine. Throws std::invalid_argument for Stage::box2d.
std::unique_ptr<StageEngine> stage_engine(Stage stage);

// The stage's engine with `scene` built. Throws browser::SceneError, its message
// starting with the stage's name, when the stage cannot read the scene's world.
std::unique_ptr<BenchWorld> stage_world(Stage stage, const SceneDescription& scene);

// The book's world (the book's keys, as stage 5.1 has them).
WorldDescription book_world();

// Whether the stage reads every key `world` sets.
bool can_express(Stage stage, const WorldDescription& world);

// The oldest of `stages` that can express `world`; nothing when none can.
std::optional<Stage> oldest_expressing(const std::vector<Stage>& stages, const WorldDescription& world);

// `world` with every key the stage reads written out: a key left unset becomes the
// stage's own default, found among the values the bench knows for it. Two worlds that
// the stage reads alike are then equal. Keys the stage does not read stay unset.
WorldDescription resolved(Stage stage, const WorldDescription& world);

}  // namespace bench
