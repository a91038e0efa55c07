#pragma once
// The bench from its options: run the chosen studies and write results.csv,
// results.md and the charts into a folder that is replaced only when all of it has
// been written; or only write the scene files.

#include <iosfwd>

#include "options.h"

namespace bench {

// The file every results folder has: a folder without it was not written by the bench,
// and is not replaced.
inline constexpr const char* kResultsCsv = "results.csv";

// Returns the exit status: 0, or 1 after one line on `err`. Progress goes to `out`,
// one line per study.
int run_bench(const BenchOptions& options, std::ostream& out, std::ostream& err);

// Writes every shipped scene (scene_maker.h) as DIR/<name>.json. Returns 0, or 1 after
// one line on `err`.
int write_scene_files(const std::filesystem::path& dir, std::ostream& out, std::ostream& err);

}  // namespace bench
