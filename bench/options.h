#pragma once
// The bench's command line (CLI11, kept inside options.cpp):
//   bench [--out DIR] [--quick] [--repeats N] [--only NAME...]
//   bench --write-scenes DIR
// Bad input gets one line on stderr, "bench: <problem>", exit status 2, and nothing
// is run or written.

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace bench {

inline constexpr int kDefaultRepeats = 3;
inline constexpr int kQuickRepeats = 1;
inline constexpr int kMaxRepeats = 100;

struct BenchOptions {
    std::filesystem::path out_dir;
    bool quick = false;
    int repeats = kDefaultRepeats;       // kQuickRepeats with --quick, unless --repeats says
    std::vector<std::string> only;       // study names; empty: every study
    std::filesystem::path write_scenes;  // not empty: write the scene files there, and nothing else
};

struct ParsedBenchCommandLine {
    std::optional<BenchOptions> options;
    int exit_status = 0;  // when there are no options: 0 after --help, 2 after bad input
};

// `studies` are the names --only accepts.
ParsedBenchCommandLine parse_bench_command_line(int argc, const char* const* argv,
                                                const std::filesystem::path& default_out,
                                                const std::vector<std::string>& studies);

}  // namespace bench
