#include "stages.h"

#include <algorithm>
#include <initializer_list>
#include <stdexcept>
#include <string_view>

#include "box2d_world.h"
#include "scene_file.h"  // SceneError
#include "scene_json.h"

namespace bench {
namespace {

bool contains(const std::vector<std::string>& names, std::string_view name) {
    return std::find(names.begin(), names.end(), name) != names.end();
}

// Whether the stage reads every key `world` sets, and tells events if they are to be read.
bool reads_all(const StageEngine& stage, const WorldDescription& world) {
    if (world.events && !stage.has_events()) return false;
    const std::vector<std::string> keys = stage.world_keys();
    const std::vector<WorldEntry> entries = world_entries(world);
    return std::all_of(entries.begin(), entries.end(),
                       [&](const WorldEntry& entry) { return contains(keys, entry.key); });
}

// Writes out one key that `world` leaves unset, if the stage reads it: the first
// candidate the stage reads as the same settings as leaving the key out.
template <class Value>
void write_default(const StageEngine& stage, std::optional<Value> WorldDescription::*key,
                   std::initializer_list<Value> candidates, WorldDescription& world) {
    if ((world.*key).has_value()) return;
    for (const Value& candidate : candidates) {
        WorldDescription written = world;
        written.*key = candidate;
        if (!reads_all(stage, written)) return;
        if (stage.same_settings(world, written)) {
            world = written;
            return;
        }
    }
}

}  // namespace

std::string stage_name(Stage stage) {
    switch (stage) {
#define BENCH_STAGE(id, number) \
    case Stage::id:             \
        return number;
#include "bench_stage_list.h"
#undef BENCH_STAGE
        case Stage::box2d: return box2d_version();
    }
    return "";
}

std::unique_ptr<StageEngine> stage_engine(Stage stage) {
    switch (stage) {
#define BENCH_STAGE(id, number) \
    case Stage::id:             \
        return id##_engine();
#include "bench_stage_list.h"
#undef BENCH_STAGE
        case Stage::box2d: break;
    }
    throw std::invalid_argument("stage_engine: Box2D is not a stage of this book");
}

std::unique_ptr<BenchWorld> stage_world(Stage stage, const SceneDescription& scene) {
    try {
        return stage_engine(stage)->world(scene);
    } catch (const browser::SceneError& error) {
        throw browser::SceneError("stage " + stage_name(stage) + ": " + error.what());
    }
}

WorldDescription book_world() { return stage_engine(Stage::s5_1)->book_world(); }

bool can_express(Stage stage, const WorldDescription& world) { return reads_all(*stage_engine(stage), world); }

std::optional<Stage> oldest_expressing(const std::vector<Stage>& stages, const WorldDescription& world) {
    for (Stage stage : stages) {
        if (stage != Stage::box2d && can_express(stage, world)) return stage;
    }
    return std::nullopt;
}

bool runs_scene_as_stage_before(Stage stage) { return stage == Stage::s5_4 || stage == Stage::s5_7; }

WorldDescription resolved(Stage stage, const WorldDescription& world) {
    if (stage == Stage::box2d) return world;
    const std::unique_ptr<StageEngine> adapter = stage_engine(stage);
    WorldDescription written = world;
    using W = WorldDescription;
    write_default(*adapter, &W::broad_phase, {BroadPhase::bounding_circle, BroadPhase::all_pairs, BroadPhase::grid},
                  written);
    write_default(*adapter, &W::substeps, {1, 2, 4, 8}, written);
    write_default(*adapter, &W::integrator, {Integrator::symplectic, Integrator::explicit_euler}, written);
    write_default(*adapter, &W::friction_model, {FrictionModel::book, FrictionModel::coulomb}, written);
    write_default(*adapter, &W::rotation, {true, false}, written);
    write_default(*adapter, &W::friction, {true, false}, written);
    write_default(*adapter, &W::solver, {Solver::book, Solver::sequential_impulse}, written);
    write_default(*adapter, &W::velocity_iterations, {1, 2, 4, 8, 16, 32}, written);
    write_default(*adapter, &W::warm_starting, {true, false}, written);
    write_default(*adapter, &W::position_method,
                  {PositionMethod::split_impulse, PositionMethod::baumgarte, PositionMethod::relax}, written);
    write_default(*adapter, &W::restitution_threshold, {30.0, 0.0}, written);
    write_default(*adapter, &W::sleep, {true, false}, written);
    write_default(*adapter, &W::continuous, {true, false}, written);
    write_default(*adapter, &W::events, {false, true}, written);
    return written;
}

}  // namespace bench
