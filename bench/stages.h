#pragma once
// Which engine makes a row: one of the stages stages.txt marks "bench" (5.1 to 5.7),
// each the engine of its own folder, or Box2D as the reference (box2d_world.h). What a
// stage can vary is what its scene files may say: the bench asks the stage for its
// world keys rather than keeping a table of its own.

#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "bench_world.h"
#include "scene_description.h"
#include "stage_engine.h"

namespace bench {

// bench_stage_list.h, made by bench/CMakeLists.txt from stages.txt, holds one line
// BENCH_STAGE(s5_1, "5.1") per stage, oldest first.
enum class Stage {
#define BENCH_STAGE(id, number) id,
#include "bench_stage_list.h"
#undef BENCH_STAGE
    box2d
};

// The stages, oldest first.
inline constexpr std::array kChapter5Stages{
#define BENCH_STAGE(id, number) Stage::id,
#include "bench_stage_list.h"
#undef BENCH_STAGE
};

// The stage's number ("5.1"), or Box2D's own name and version ("Box2D 2.4").
std::string stage_name(Stage stage);

// A chapter 5 stage's engine. Throws std::invalid_argument for Stage::box2d.
std::unique_ptr<StageEngine> stage_engine(Stage stage);

// The stage's engine with `scene` built. Throws browser::SceneError, its message
// starting with the stage's name, when the stage cannot read the scene's world.
std::unique_ptr<BenchWorld> stage_world(Stage stage, const SceneDescription& scene);

// The book's world (the book's keys, as stage 5.1 has them).
WorldDescription book_world();

// Whether the stage reads every key `world` sets (and tells events, if `world` reads them).
bool can_express(Stage stage, const WorldDescription& world);

// The oldest of `stages` that can express `world`; nothing when none can.
std::optional<Stage> oldest_expressing(const std::vector<Stage>& stages, const WorldDescription& world);

// Whether the stage runs a scene's own world as the stage before it does, bit for bit
// (its identity test), so that a "scene" row of it would repeat the one before: 5.4,
// whose solver is the book's unless a scene says otherwise, and 5.7, which keeps
// collision events only while someone reads them, and a scene alone reads none.
bool runs_scene_as_stage_before(Stage stage);

// `world` with every key the stage reads written out: a key left unset becomes the
// stage's own default, found among the values the bench knows for it. Two worlds that
// the stage reads alike are then equal. Keys the stage does not read stay unset.
WorldDescription resolved(Stage stage, const WorldDescription& world);

}  // namespace bench
