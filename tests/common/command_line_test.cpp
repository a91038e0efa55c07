// The command line every stage's program shares.
#include <catch2/catch.hpp>

#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "captured_output.h"
#include "command_line.h"
#include "gif_writer.h"
#include "live_window.h"
#include "random.h"

using browser::Key;
using browser::ParsedCommandLine;

namespace {

const browser::StageDefaults kDefaults{
    .id = "s9_9",
    .title = "9.9 A Test Stage",
    .keys = "f@2 g",
    .frames = 30,
    .every = 10,
    .extra_options =
        {{.name = "--scene", .value_name = "FILE", .help = "scene to load", .default_value = "default.txt"},
         {.name = "--dump", .value_name = "FILE", .help = "state dump", .default_value = ""}},
};

using test::CapturedOutput;

struct Outcome {
    ParsedCommandLine parsed;
    std::string out, err;
};

// Runs the parser as the program "/usr/bin/s9_9_test" would with these arguments.
Outcome parse(std::vector<std::string> arguments, const browser::StageDefaults& defaults = kDefaults) {
    arguments.insert(arguments.begin(), "/usr/bin/s9_9_test");
    std::vector<const char*> argv;
    for (const std::string& argument : arguments) argv.push_back(argument.c_str());
    argv.push_back(nullptr);  // as the real argv ends
    Outcome outcome;
    CapturedOutput captured;
    outcome.parsed = browser::parse_command_line(static_cast<int>(arguments.size()), argv.data(), defaults);
    outcome.out = captured.out();
    outcome.err = captured.err();
    return outcome;
}

// A bad command line stops with status 2 and exactly one line on stderr that starts
// with the program's name and mentions `must_mention` (usually the option).
void check_rejected(const std::vector<std::string>& arguments, const std::string& must_mention,
                    const browser::StageDefaults& defaults = kDefaults) {
    const Outcome outcome = parse(arguments, defaults);
    std::string shown;
    for (const std::string& argument : arguments) shown += " [" + argument + "]";
    INFO("arguments:" << shown << "\nstderr: " << outcome.err);
    CHECK(outcome.parsed.exit_status == 2);
    CHECK_FALSE(outcome.parsed.options.has_value());
    REQUIRE_FALSE(outcome.err.empty());
    CHECK(outcome.err.back() == '\n');
    CHECK(outcome.err.find('\n') == outcome.err.size() - 1);
    CHECK(outcome.err.rfind("s9_9_test: ", 0) == 0);
    CHECK_THAT(outcome.err, Catch::Contains(must_mention));
    CHECK(outcome.out.empty());
}

}  // namespace

TEST_CASE("command_line: no arguments give the stage's defaults") {
    const Outcome outcome = parse({});
    REQUIRE(outcome.parsed.exit_status == 0);
    REQUIRE(outcome.parsed.options.has_value());
    const browser::Options& options = *outcome.parsed.options;
    CHECK(options.out_dir == std::filesystem::path("out") / "s9_9");
    CHECK(options.frames == 30);
    CHECK(options.every == 10);
    CHECK(options.seed == browser::Random::kDefaultSeed);
    CHECK(options.keys_text == "f@2 g");
    CHECK(options.keys.pressesAt(2) == std::vector<Key>{Key::F, Key::G});
    CHECK(options.frame_ms == 1000.0 / 60.0);
    CHECK(options.extra.at("--scene") == "default.txt");
    CHECK(options.extra.at("--dump").empty());
    CHECK(options.extra.size() == 2);
    CHECK(outcome.out.empty());
    CHECK(outcome.err.empty());
}

TEST_CASE("command_line: each option is read") {
    const Outcome outcome =
        parse({"--out", "pictures/run 1", "--frames", "120", "--every=7", "--seed", "18446744073709551615", "--keys",
               "UP*2@100 comma", "--frame-ms", "2.5", "--dump", "state.txt", "--scene=box.txt", "--"});
    REQUIRE(outcome.parsed.exit_status == 0);
    REQUIRE(outcome.parsed.options.has_value());
    const browser::Options& options = *outcome.parsed.options;
    CHECK(options.out_dir == "pictures/run 1");
    CHECK(options.frames == 120);
    CHECK(options.every == 7);
    CHECK(options.seed == 18446744073709551615ULL);
    CHECK(options.keys_text == "UP*2@100 comma");
    CHECK(options.keys.pressesAt(100) == std::vector<Key>{Key::Up, Key::Up, Key::Comma});
    CHECK(options.keys.pressesAt(2).empty());
    CHECK(options.frame_ms == 2.5);
    CHECK(options.extra.at("--scene") == "box.txt");
    CHECK(options.extra.at("--dump") == "state.txt");
    CHECK(outcome.err.empty());
}

TEST_CASE("command_line: edge values that are allowed") {
    const Outcome outcome =
        parse({"--frames", "1", "--every", "0", "--seed", "0", "--keys", "", "--frame-ms", "10000"});
    REQUIRE(outcome.parsed.options.has_value());
    CHECK(outcome.parsed.options->frames == 1);
    CHECK(outcome.parsed.options->every == 0);
    CHECK(outcome.parsed.options->seed == 0);
    CHECK(outcome.parsed.options->keys.empty());
    CHECK(outcome.parsed.options->frame_ms == 10000.0);
}

TEST_CASE("command_line: --help prints the usage and stops with status 0") {
    for (const char* help : {"--help", "-h"}) {
        const Outcome outcome = parse({help});
        CHECK(outcome.parsed.exit_status == 0);
        CHECK_FALSE(outcome.parsed.options.has_value());
        CHECK(outcome.err.empty());
        CHECK_THAT(outcome.out, Catch::Contains("9.9 A Test Stage"));
        for (const char* option : {"--out", "--frames", "--from", "--every", "--gif", "--no-gif", "--gif-every",
                                   "--seed", "--keys", "--frame-ms", "--scene", "--dump"}) {
            CHECK_THAT(outcome.out, Catch::Contains(option));
        }
    }
}

TEST_CASE("command_line: bad numbers are rejected in one line naming the option") {
    check_rejected({"--frames", "abc"}, "--frames: must be a whole number from 1 to 10000000 (got \"abc\")");
    check_rejected({"--frames", "0"}, "--frames");
    check_rejected({"--frames", "-3"}, "--frames");
    check_rejected({"--frames=-3"}, "--frames");
    check_rejected({"--frames", "2.5"}, "--frames");
    check_rejected({"--frames", "10000001"}, "--frames");
    check_rejected({"--frames", "99999999999999999999"}, "--frames");
    check_rejected({"--frames", ""}, "--frames");
    check_rejected({"--frames", " 5"}, "--frames");
    check_rejected({"--every", "-1"}, "--every");
    check_rejected({"--every", "x"}, "--every");
    check_rejected({"--seed", "-1"}, "--seed");
    check_rejected({"--seed", "18446744073709551616"}, "--seed");
    check_rejected({"--seed", "12abc"}, "--seed");
    check_rejected({"--frame-ms", "nan"}, "--frame-ms");
    check_rejected({"--frame-ms", "inf"}, "--frame-ms");
    check_rejected({"--frame-ms", "-inf"}, "--frame-ms");
    check_rejected({"--frame-ms", "0"}, "--frame-ms");
    check_rejected({"--frame-ms", "-16"}, "--frame-ms");
    check_rejected({"--frame-ms", "10000.5"}, "--frame-ms");
    check_rejected({"--frame-ms", "16ms"}, "--frame-ms");
    check_rejected({"--frame-ms", ""}, "--frame-ms");
}

TEST_CASE("command_line: bad key scripts are usage errors") {
    check_rejected({"--keys", "q*x"}, "--keys: bad key script token \"q*x\"");
    check_rejected({"--keys", "f@-1"}, "a-z, 0-9, comma, up, down");
    check_rejected({"--keys", "left"}, "\"left\"");
}

TEST_CASE("command_line: the reader's keys after the last frame are a usage error") {
    check_rejected({"--keys", "f@30"}, "--keys");  // the default run has frames 0..29
    check_rejected({"--keys", "f@5", "--frames", "5"}, "--keys");
}

TEST_CASE("command_line: a shorter run simply stops before the rest of the default script") {
    const Outcome shorter = parse({"--frames", "2"});  // the default script presses at frame 2
    REQUIRE(shorter.parsed.options);
    CHECK(shorter.parsed.options->frames == 2);
    CHECK_FALSE(shorter.parsed.options->keys_given);
    const Outcome own = parse({"--keys", "f"});
    REQUIRE(own.parsed.options);
    CHECK(own.parsed.options->keys_given);
}

TEST_CASE("command_line: unknown options, stray words and missing values") {
    check_rejected({"--bogus"}, "\"--bogus\"");
    check_rejected({"--bogus=3"}, "--bogus");
    check_rejected({"-x"}, "\"-x\"");
    check_rejected({"picture.png"}, "\"picture.png\"");
    check_rejected({"--frames", "5", "extra"}, "\"extra\"");
    check_rejected({"--", "extra"}, "\"extra\"");
    check_rejected({"--frames"}, "--frames");
    check_rejected({"--frames", "--every", "3"}, "--frames: needs a value");
    check_rejected({"--out", "--frames", "5"}, "--out: needs a value");
    check_rejected({"--keys", "--frames", "5"}, "--keys: needs a value");
    check_rejected({"--scene", "--every", "5"}, "--scene: needs a value");
    check_rejected({"--out"}, "--out");
    check_rejected({"--out", ""}, "--out");
    check_rejected({"--frames", "5", "--frames", "6"}, "--frames");
}

TEST_CASE("command_line: whatever the reader typed, a refusal is one line, the text escaped and shortened") {
    // A line break, a terminal's escape sequence, bytes that are not UTF-8, a long value.
    check_rejected({"--frames", "1\n2"}, R"(--frames: must be a whole number from 1 to 10000000 (got "1\n2"))");
    check_rejected({"--seed", "7\r\n"}, R"((got "7\r\n"))");
    check_rejected({"--frame-ms", "16\x1b[2J"}, R"((got "16\x1b[2J"))");
    check_rejected({"--bo\ngus"}, R"(unknown option "--bo\ngus")");
    check_rejected({"stray\xff\xfe"}, R"(unexpected argument "stray\xff\xfe")");
    const Outcome long_value = parse({"--frames", std::string(100'000, '9')});
    CHECK(long_value.parsed.exit_status == 2);
    CHECK(long_value.err.size() < 300);
    CHECK_THAT(long_value.err, Catch::Contains("999...999"));
}

TEST_CASE("command_line: an empty file name is refused for every option that takes one") {
    check_rejected({"--scene", ""}, R"(--scene: must name a file (got ""))");
    check_rejected({"--dump", ""}, R"(--dump: must name a file (got ""))");
    check_rejected({"--out", ""}, R"(--out: must name a folder (got ""))");
}

TEST_CASE("command_line: more pictures than a run may write are refused") {
    // 1,000 pictures are allowed: frames 0, 10, ..., 9990.
    CHECK(parse({"--frames", "10000", "--every", "10"}).parsed.exit_status == 0);
    check_rejected({"--frames", "10001", "--every", "10"},
                   "--every: 10001 frames would save 1001 pictures, more than the 1000 a run may");
    check_rejected({"--frames", "10000000", "--every", "1"}, "--every: 10000000 frames would save 10000000 pictures");
    if (browser::gif_supported()) {
        CHECK(parse({"--frames", "2000", "--gif", "--every", "0"}).parsed.exit_status == 0);
        check_rejected({"--frames", "2001", "--gif", "--every", "0"},
                       "--gif-every: 2001 frames would make a GIF of 1001 pictures, more than the 1000 a run may");
    }
}

TEST_CASE("command_line: --from starts the pictures at a frame the run reaches") {
    const Outcome outcome = parse({"--frames", "100", "--from", "99", "--every", "10"});
    REQUIRE(outcome.parsed.options.has_value());
    CHECK(outcome.parsed.options->from == 99);
    CHECK(parse({}).parsed.options->from == 0);
    check_rejected({"--frames", "100", "--from", "100"},
                   "--from: frame 100 is not run: --frames 100 runs frames 0 to 99");
    check_rejected({"--from", "-1"}, "--from: must be a whole number from 0");
    // Only the frames from F on count towards the most pictures a run may save.
    CHECK(parse({"--frames", "10100", "--from", "100", "--every", "10"}).parsed.exit_status == 0);
    check_rejected({"--frames", "10101", "--from", "100", "--every", "10"},
                   "--every: 10001 frames would save 1001 pictures");
    check_rejected({"--live", "--from", "5"}, "--from: a --live session writes no pictures");
}

TEST_CASE("command_line: the program name is argv[0]'s file name, or the stage id without one") {
    const char* const argv[] = {nullptr};
    CapturedOutput captured;
    const ParsedCommandLine parsed = browser::parse_command_line(0, argv, kDefaults);
    CHECK(parsed.exit_status == 0);
    const char* const bad[] = {"", "--bogus", nullptr};
    CHECK(browser::parse_command_line(2, bad, kDefaults).exit_status == 2);
    CHECK(captured.err().rfind("s9_9: ", 0) == 0);
}

TEST_CASE("command_line: a stage's own option that clashes is a programming error") {
    browser::StageDefaults clash = kDefaults;
    clash.extra_options.push_back({.name = "--frames", .value_name = "N", .help = "again", .default_value = ""});
    const char* const argv[] = {"prog", nullptr};
    CHECK_THROWS_AS(browser::parse_command_line(1, argv, clash), std::logic_error);
}

TEST_CASE("command_line: --gif and --gif-every") {
    const Outcome plain = parse({});
    REQUIRE(plain.parsed.options.has_value());
    CHECK_FALSE(plain.parsed.options->gif);
    CHECK(plain.parsed.options->gif_every == 2);
    if (browser::gif_supported()) {
        const Outcome gif = parse({"--gif", "--gif-every", "5"});
        REQUIRE(gif.parsed.options.has_value());
        CHECK(gif.parsed.options->gif);
        CHECK(gif.parsed.options->gif_every == 5);
        CHECK(gif.err.empty());
        CHECK(parse({"--gif", "--gif-every=1"}).parsed.options->gif_every == 1);
        check_rejected({"--gif", "--gif-every", "0"},
                       "--gif-every: must be a whole number from 1 to 10000000 (got \"0\")");
        check_rejected({"--gif", "--gif-every", "2x"}, "--gif-every");
    } else {
        check_rejected({"--gif"}, std::string(browser::kNoGifSupport));
    }
    CHECK_FALSE(parse({"--no-gif"}).parsed.options->gif);
    check_rejected({"--gif-every", "3"}, "--gif-every: there is no GIF to space out");
    check_rejected({"--gif", "--no-gif"}, "--gif, --no-gif: give one or the other");
    check_rejected({"--gif=false"}, "--gif: takes no value (got \"--gif=false\")");
    check_rejected({"--no-gif=1"}, "--no-gif: takes no value");
    check_rejected({"--gif", "yes"}, "unexpected argument \"yes\"");
}

TEST_CASE("command_line: a stage can write a GIF by default") {
    browser::StageDefaults stage = kDefaults;
    stage.gif = true;
    stage.gif_every = 3;
    const Outcome outcome = parse({}, stage);
    REQUIRE(outcome.parsed.options.has_value());
    CHECK(outcome.parsed.options->gif_every == 3);
    if (browser::gif_supported()) {
        CHECK(outcome.parsed.options->gif);
        CHECK(outcome.err.empty());
        CHECK(parse({"--gif-every", "4"}, stage).parsed.options->gif_every == 4);  // no --gif needed
    } else {
        // Without giflib the stage's default run still works, and says what it skips.
        CHECK_FALSE(outcome.parsed.options->gif);
        CHECK_THAT(outcome.err, Catch::StartsWith("s9_9_test: note: no animation.gif"));
        CHECK(outcome.err.find('\n') == outcome.err.size() - 1);
    }
    const Outcome off = parse({"--no-gif"}, stage);
    REQUIRE(off.parsed.options.has_value());
    CHECK_FALSE(off.parsed.options->gif);
    CHECK(off.err.empty());
    check_rejected({"--no-gif", "--gif-every", "4"}, "--gif-every", stage);
}

namespace {

// A stage that declares its keys.
browser::StageDefaults with_keys() {
    browser::StageDefaults stage = kDefaults;
    stage.key_help = {{"0-9 up down", "select"}, {"f g", "a new shape"}};
    return stage;
}

}  // namespace

TEST_CASE("command_line: a key script may press only the stage's keys") {
    const browser::StageDefaults stage = with_keys();
    const Outcome fine = parse({"--keys", "f 7@3 up@4 G"}, stage);
    REQUIRE(fine.parsed.options.has_value());
    CHECK(fine.parsed.options->stage_keys.text() == "f, g, 0-9, up, down");
    check_rejected({"--keys", "f g@2 h@3"}, "--keys: \"h\" is not a key of this stage (its keys: f, g, 0-9, up, down)",
                   stage);
    check_rejected({"--keys", "comma"}, "\"comma\" is not a key of this stage", stage);
    // A stage that declares no keys takes any.
    CHECK(parse({"--keys", "h comma"}).parsed.options.has_value());
}

TEST_CASE("command_line: --help lists the stage's keys and what they do") {
    const Outcome outcome = parse({"--help"}, with_keys());
    CHECK(outcome.parsed.exit_status == 0);
    CHECK_THAT(outcome.out, Catch::Contains("The keys of this stage, in a --keys script or live with --live:\n"
                                            "  0-9 up down  select\n"
                                            "  f g          a new shape\n"));
    CHECK_THAT(outcome.out, Catch::Contains("Space pauses"));
    CHECK_THAT(outcome.out, Catch::Contains("--live"));
    CHECK_THAT(outcome.out, Catch::Contains("--record FILE"));
    CHECK_THAT(outcome.out, Catch::Contains("--scale K=1"));
    // The test hooks stay out of a reader's sight.
    CHECK_THAT(outcome.out, !Catch::Contains("--live-events"));
    CHECK_THAT(outcome.out, !Catch::Contains("--live-screenshot"));
}

TEST_CASE("command_line: a stage's key list with a bad name is a programming error") {
    browser::StageDefaults stage = kDefaults;
    stage.key_help = {{"f left", "?"}};
    const char* const argv[] = {"prog", nullptr};
    CHECK_THROWS_AS(browser::parse_command_line(1, argv, stage), std::logic_error);
}

TEST_CASE("command_line: --scale") {
    CHECK(parse({}).parsed.options->scale == 1);
    CHECK(parse({"--scale", "4"}).parsed.options->scale == 4);
    check_rejected({"--scale", "0"}, "--scale: must be a whole number from 1 to 4 (got \"0\")");
    check_rejected({"--scale", "5"}, "--scale: must be a whole number from 1 to 4 (got \"5\")");
    check_rejected({"--scale", "1.5"}, "--scale");
}

TEST_CASE("command_line: --live, --record and what goes with them") {
    check_rejected({"--record", "session.keys"}, "--record: only with --live");
    check_rejected({"--live-events", "events.txt"}, "--live-events: only with --live");
    check_rejected({"--live-screenshot", "shot.png"}, "--live-screenshot: only with --live");
    if (!browser::live_window_supported()) {
        check_rejected({"--live"}, std::string(browser::kNoLiveSupport));
        return;
    }
    const browser::StageDefaults stage = with_keys();
    const Outcome outcome =
        parse({"--live", "--record", "my session.keys", "--seed", "7", "--scene", "box.txt", "--scale", "2"}, stage);
    REQUIRE(outcome.parsed.options.has_value());
    const browser::Options& options = *outcome.parsed.options;
    CHECK(options.live.on);
    CHECK(options.live.record == "my session.keys");
    CHECK(options.live.title == "9.9 A Test Stage (s9_9)");
    CHECK(options.live.stage_id == "s9_9");
    // The stage's default script is not played: the reader plays.
    CHECK(options.keys.empty());
    CHECK_FALSE(options.gif);
    // The replay runs the same world: the program as called, with what shapes the run.
    CHECK(options.live.replay_command ==
          std::vector<std::string>{"/usr/bin/s9_9_test", "--seed", "7", "--scale", "2", "--scene", "box.txt"});
    CHECK(options.live.replay_every == 10);
    CHECK(options.live.replay_gif == browser::gif_supported());
    CHECK(outcome.err.empty());

    // The reader's own script plays in a live session too, whatever its last frame.
    const Outcome scripted = parse({"--live", "--keys", "f@500"}, stage);
    REQUIRE(scripted.parsed.options.has_value());
    CHECK(scripted.parsed.options->keys.pressesAt(500) == std::vector<Key>{Key::F});
    check_rejected({"--live", "--keys", "h"}, "\"h\" is not a key of this stage", stage);

    // A live session writes no pictures and runs until the reader ends it.
    for (const std::vector<std::string>& arguments : {std::vector<std::string>{"--live", "--every", "5"},
                                                      {"--live", "--out", "x"},
                                                      {"--live", "--gif"},
                                                      {"--live", "--gif-every", "3"}}) {
        check_rejected(arguments, "a --live session writes no pictures; record it with --record FILE");
    }
    check_rejected({"--live", "--frames", "100"}, "--frames: a --live session runs until Escape");
    check_rejected({"--live", "--record", ""}, "--record: must name a file");
    check_rejected({"--live=1"}, "--live: takes no value");
}
