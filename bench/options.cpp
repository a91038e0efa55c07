#include "options.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <charconv>
#include <iostream>
#include <stdexcept>

#include "strict_parse.h"

namespace bench {
namespace {

using browser::in_quotes;
using browser::UsageError;

int repeats_option(const std::string& text) {
    int value = 0;
    const char* end = text.data() + text.size();
    const auto [stop, error] = std::from_chars(text.data(), end, value);
    if (text.empty() || error != std::errc{} || stop != end || value < 1 || value > kMaxRepeats) {
        throw UsageError("--repeats: must be a whole number from 1 to " + std::to_string(kMaxRepeats) + " (got " +
                         in_quotes(text) + ")");
    }
    return value;
}

std::string joined(const std::vector<std::string>& words) {
    std::string text;
    for (const std::string& word : words) text += (text.empty() ? "" : ", ") + word;
    return text;
}

void check_studies(const std::vector<std::string>& only, const std::vector<std::string>& studies) {
    for (const std::string& name : only) {
        if (std::find(studies.begin(), studies.end(), name) == studies.end()) {
            throw UsageError("--only: no study named " + in_quotes(name) + " (there are " + joined(studies) + ")");
        }
    }
}

}  // namespace

ParsedBenchCommandLine parse_bench_command_line(int argc, const char* const* argv,
                                                const std::filesystem::path& default_out,
                                                const std::vector<std::string>& studies) {
    std::string out_text = default_out.string();
    std::string repeats_text;
    std::string scenes_text;
    bool quick = false;
    std::vector<std::string> only;

    CLI::App app("bench: what each chapter 5 stage's engine and knobs cost and buy", "bench");
    app.allow_extras();  // unknown words stay in app.remaining(), so we can name them
    app.add_option("--out", out_text, "folder for results.csv, results.md and the charts (replaced by each run)")
        ->type_name("DIR")
        ->capture_default_str();
    app.add_flag("--quick", quick, "a run of seconds: fewer settings, shorter runs, one timed run each");
    app.add_option("--repeats", repeats_text, "timed runs per setting; the cost is their median")
        ->type_name("N")
        ->default_str(std::to_string(kDefaultRepeats) + " (" + std::to_string(kQuickRepeats) + " with --quick)");
    app.add_option("--only", only, "run only these studies: " + joined(studies))->type_name("NAME");
    app.add_option("--write-scenes", scenes_text,
                   "write the shipped scene files (bench/scenes/) into DIR, and do nothing else")
        ->type_name("DIR");

    try {
        std::vector<std::string> arguments;  // CLI11 takes them last-first, without the program
        for (int i = argc - 1; i >= 1; --i) arguments.emplace_back(argv[i]);
        if (!browser::parse_strictly(app, arguments)) return {std::nullopt, 0};

        BenchOptions options;
        if (app.count("--write-scenes") > 0) {
            if (scenes_text.empty()) throw UsageError("--write-scenes: must name a folder (got \"\")");
            for (const char* other : {"--out", "--quick", "--repeats", "--only"}) {
                if (app.count(other) > 0) {
                    throw UsageError(std::string("--write-scenes: writes the scene files only, so ") + other +
                                     " has nothing to do");
                }
            }
            options.write_scenes = scenes_text;
            return {std::move(options), 0};
        }
        if (out_text.empty()) throw UsageError("--out: must name a folder (got \"\")");
        options.out_dir = out_text;
        options.quick = quick;
        options.repeats =
            app.count("--repeats") > 0 ? repeats_option(repeats_text) : (quick ? kQuickRepeats : kDefaultRepeats);
        check_studies(only, studies);
        options.only = only;
        return {std::move(options), 0};
    } catch (const UsageError& error) {
        std::cerr << "bench: " << error.what() << '\n';
        return {std::nullopt, 2};
    }
}

}  // namespace bench
