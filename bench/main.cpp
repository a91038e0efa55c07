// bench: what each chapter 5 stage's engine and knobs cost and buy (README.md).

#include <iostream>

#include "bench_run.h"
#include "options.h"
#include "study.h"

int main(int argc, char** argv) {
    std::vector<std::string> names;
    for (const bench::Study& study : bench::all_studies()) names.push_back(study.name);
    const bench::ParsedBenchCommandLine parsed = bench::parse_bench_command_line(argc, argv, BENCH_RESULTS_DIR, names);
    if (!parsed.options) return parsed.exit_status;
    if (!parsed.options->write_scenes.empty()) {
        return bench::write_scene_files(parsed.options->write_scenes, std::cout, std::cerr);
    }
    return bench::run_bench(*parsed.options, std::cout, std::cerr);
}
