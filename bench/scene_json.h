#pragma once
// Scene files in and out: the JSON that the stages' scene files hold, every number printed
// in the fewest digits that read back to the same double. The same text is what the
// bench hands each stage (stage_engine.h), so a stage reads the bench's settings as it
// reads a scene file, and refuses a key it does not read in the same words.

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "scene_description.h"

namespace bench {

// One key of a scene file's world, as written: its name and its value as JSON text.
struct WorldEntry {
    std::string_view key;
    std::string value;
};
// The book's keys, then each key of a later stage that `world` sets.
std::vector<WorldEntry> world_entries(const WorldDescription& world);

std::string scene_json(const SceneDescription& scene);

// Writes to "<file>.partial" and renames it into place. Throws browser::FileError.
void write_scene(const std::filesystem::path& file, const SceneDescription& scene);

// A scene file of the book's world keys, the only ones bench/scenes/ holds, read as
// stage 5.1 reads it (a later stage's key there is refused). Throws browser::SceneError
// with one line.
SceneDescription read_scene(const std::filesystem::path& file);

}  // namespace bench
