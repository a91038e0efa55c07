#pragma once
// One stage's engine, as the bench drives it. The stages all keep their engine in
// namespace engine under the same class names, so this interface names no engine type:
// each stage gets its own implementation, made by one adapter (stage_adapter.cpp)
// compiled once per stage (bench/CMakeLists.txt says how), and the rest of the bench
// sees only this.

#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "bench_world.h"
#include "scene_description.h"

namespace bench {

class StageEngine {
public:
    virtual ~StageEngine() = default;

    // The world keys the stage's scene files may hold: the names of its engine::worldKeys.
    virtual std::vector<std::string> world_keys() const = 0;
    // The book's world keys as the stage's engine::kBookWorld has them.
    virtual WorldDescription book_world() const = 0;
    // The stage's engine with the scene built, its world read from the scene's JSON by the
    // stage's own world keys. Throws browser::SceneError, in the words of the stage's
    // program, for a key the stage does not read or a value it refuses, and for events
    // read (WorldDescription::events) on a stage that has none.
    virtual std::unique_ptr<BenchWorld> world(const SceneDescription& scene) const = 0;
    // A scene's text read as the stage's program reads a scene file, in the bench's terms:
    // the book's world keys and the bodies. `source` stands for the file in a refusal.
    // Throws browser::SceneError.
    virtual SceneDescription read_scene(const std::string& text, std::string_view source) const = 0;
    // Whether the stage reads the two worlds as the same settings: a key left unset is the
    // same as the stage's default written out. Throws browser::SceneError as world() does.
    virtual bool same_settings(const WorldDescription& a, const WorldDescription& b) const = 0;
    // Whether the stage tells collision events that a game may read after each step
    // (WorldDescription::events): 5.7 on.
    virtual bool has_events() const = 0;
};

// One per stage of bench_stage_list.h (s5_1_engine, ...), each defined by the adapter
// compiled with that stage.
#define BENCH_STAGE(id, number) std::unique_ptr<StageEngine> id##_engine();
#include "bench_stage_list.h"
#undef BENCH_STAGE

}  // namespace bench
