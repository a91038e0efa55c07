#pragma once
// A world read from a scene file's "world" object through the stage's own scene_io, the
// way the program reads a reader's file: tests of a setting then test the key that sets
// it as well, so a key read into the wrong setting (or not read) shows.

#include <string>

#include "scene_io.h"
#include "scratch_folder.h"

namespace test {

// `world_object` is the JSON of the "world" object, e.g. R"({"correction_rate": 0.5})".
inline engine::WorldSettings worldFromScene(const std::string& world_object) {
    const ScratchFolder folder("world-from-scene");
    return engine::loadScene(folder.write("scene.json", R"({"world": )" + world_object + "}")).world;
}

}  // namespace test
