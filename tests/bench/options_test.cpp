// The bench's command line: what it accepts, and that bad input stops it at once with
// one line, writing nothing.
#include <catch2/catch.hpp>

#include <algorithm>
#include <iostream>
#include <sstream>

#include "captured_output.h"
#include "options.h"
#include "stage_program.h"  // runs STAGE_PROGRAM, here the bench

namespace {

const std::vector<std::string> kStudies{"pyramid_10", "gas", "scale"};

struct Parsed {
    bench::ParsedBenchCommandLine result;
    std::string err;
};

Parsed parse(std::vector<const char*> words) {
    words.insert(words.begin(), "bench");
    const test::CapturedOutput captured;
    Parsed parsed{bench::parse_bench_command_line(static_cast<int>(words.size()), words.data(), "results", kStudies),
                  ""};
    parsed.err = captured.err();
    return parsed;
}

bool one_line(const std::string& text) {
    return !text.empty() && text.back() == '\n' && std::count(text.begin(), text.end(), '\n') == 1;
}

}  // namespace

TEST_CASE("bench options: the defaults, and --quick times each setting once") {
    const Parsed plain = parse({});
    REQUIRE(plain.result.options);
    CHECK(plain.result.options->out_dir == "results");
    CHECK_FALSE(plain.result.options->quick);
    CHECK(plain.result.options->repeats == bench::kDefaultRepeats);
    CHECK(plain.result.options->only.empty());
    CHECK(plain.result.options->write_scenes.empty());

    const Parsed quick = parse({"--quick", "--out", "elsewhere"});
    REQUIRE(quick.result.options);
    CHECK(quick.result.options->quick);
    CHECK(quick.result.options->repeats == 1);
    CHECK(quick.result.options->out_dir == "elsewhere");

    const Parsed both = parse({"--quick", "--repeats", "5", "--only", "gas", "scale"});
    REQUIRE(both.result.options);
    CHECK(both.result.options->repeats == 5);
    CHECK(both.result.options->only == std::vector<std::string>{"gas", "scale"});
}

TEST_CASE("bench options: bad input gives one line and exit status 2") {
    for (const std::vector<const char*>& words : std::vector<std::vector<const char*>>{
             {"--repeats", "0"},
             {"--repeats", "101"},
             {"--repeats", "two"},
             {"--repeats", "3x"},
             {"--only", "pyramid"},
             {"--only", "gas", "nothing"},
             {"--out", ""},
             {"--out", "--quick"},
             {"--fast"},
             {"extra"},
             {"--write-scenes", "dir", "--quick"},
         }) {
        const Parsed parsed = parse(words);
        INFO(words.front());
        CHECK_FALSE(parsed.result.options);
        CHECK(parsed.result.exit_status == 2);
        CHECK(one_line(parsed.err));
        CHECK_THAT(parsed.err, Catch::StartsWith("bench: "));
    }
}

TEST_CASE("bench options: --only names the studies there are") {
    const Parsed parsed = parse({"--only", "pyramid"});
    CHECK_THAT(parsed.err, Catch::Contains("\"pyramid\"") && Catch::Contains("pyramid_10, gas, scale"));
}

TEST_CASE("bench: bad input stops the program before anything is written") {
    test::ScratchFolder folder("bench_cli");
    const std::filesystem::path out = folder.path / "results";
    for (const std::string arguments : {"--repeats 0", "--only nothing", "--quick --bogus", "--out"}) {
        INFO(arguments);
        const test::ProgramRun run = test::runStageProgram(folder, arguments + " --out " + test::quoted(out));
        CHECK(run.status == 2);
        CHECK(one_line(run.error_text));
        CHECK_FALSE(std::filesystem::exists(out));
    }
    CHECK(folder.files() == std::vector<std::string>{"stderr.txt", "stdout.txt"});
}

TEST_CASE("bench: a folder the bench did not write is left alone") {
    test::ScratchFolder folder("bench_cli_foreign");
    const std::filesystem::path mine = folder.write("notes.txt", "keep me");
    const test::ProgramRun run =
        test::runStageProgram(folder, "--quick --only projectile --out " + test::quoted(folder.path));
    CHECK(run.status == 1);
    CHECK(one_line(run.error_text));
    CHECK_THAT(run.error_text, Catch::Contains("it holds \"notes.txt\", which no run wrote"));
    CHECK(test::readText(mine) == "keep me");
    CHECK(folder.files() == std::vector<std::string>{"notes.txt", "stderr.txt", "stdout.txt"});
}
