#pragma once
// Scene files out: the JSON that browser::load_scene reads back to the same
// SceneDescription, every number printed in the fewest digits that read back to the
// same double. The world is written whole, knobs included, so a file runs the same
// whatever the reading stage's defaults are (docs/scene_format.md).

#include <filesystem>
#include <string>

#include "scene_file.h"

namespace bench {

std::string scene_json(const browser::SceneDescription& scene);

// Writes to "<file>.partial" and renames it into place. Throws browser::FileError.
void write_scene(const std::filesystem::path& file, const browser::SceneDescription& scene);

}  // namespace bench
