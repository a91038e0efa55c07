#pragma once
// Scene files in, state dumps out (--scene FILE, --dump FILE): the bridge between what
// the browser reads and writes (scene_file.h, state_dump.h) and the stage's world.
// Neither is in the book: they let a reader change the scene without recompiling, and
// compare this engine's numbers, step by step, with the book's JavaScript.

#include <filesystem>
#include <vector>

#include "browser.h"
#include "core.h"
#include "scene_file.h"
#include "state_dump.h"
#include "world_settings.h"

namespace engine {

// The world keys the stage reads, bound to `world`: one for each of its settings.
std::vector<browser::WorldKey> worldKeys(WorldSettings& world);

// A scene file, read with the stage's world keys: the book's world where the file
// says nothing, and the file's bodies. Throws browser::SceneError with one line.
struct Scene {
    WorldSettings world = kBookWorld;
    std::vector<browser::BodyDescription> bodies;
};
Scene loadScene(const std::filesystem::path& file);

// Adds the bodies of a scene file, in file order (object 0 is the first body), in
// place of the book's MyGame scene. Each is built as the book builds a shape, then
// turned with rotate(angle) and set moving with its velocity and angular velocity.
void buildScene(Core& core, const std::vector<browser::BodyDescription>& bodies);

// One row per object for the core's current step (0 before any update).
void dumpState(browser::StateDump& dump, const Core& core);

// The last guard against a scene beyond what the engine can compute: throws
// browser::NonFiniteState naming the first object whose position or velocity is not a
// finite number.
void checkFinite(const Core& core);

// What one fixed step of the core's world costs at most, for the run's budget.
browser::StepCost stepCost(const Core& core);

}  // namespace engine
