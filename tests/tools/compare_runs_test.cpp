// compare_runs as a reader runs it, on the newest stage's program, against hostile
// input (issue 36): it reruns into its own folder, refuses what it cannot read or use
// in one line with nothing written, keeps its memory bounded whatever the setting, and
// ends by SIGINT or SIGTERM with the runs stopped and nothing half-written.
#include <catch2/catch.hpp>

#include <chrono>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include "scratch_folder.h"
#include "stage_program.h"

namespace compare_runs_test {

namespace fs = std::filesystem;
using test::quoted;

namespace {

const fs::path kScene = fs::path(SCENE_LIBRARY_DIR) / "billiards.json";

// compare_runs PROGRAM SCENE LEFT RIGHT `rest`, from inside `folder`; stopped after 60 s
// should it wait for ever (status 124).
test::ProgramRun compareRuns(const test::ScratchFolder& folder, const std::string& scene, const std::string& rest,
                             const std::string& before = "") {
    const fs::path err = folder.path.string() + ".err";
    const std::string line = "cd " + quoted(folder.path) + " && " + before + "timeout 60 " + quoted(COMPARE_RUNS) +
                             " " + quoted(STAGE_PROGRAM) + " " + scene + " " + rest + " >/dev/null 2>" + quoted(err);
    const int raw = std::system(line.c_str());
    test::ProgramRun run;
    if (raw != -1 && WIFEXITED(raw)) run.status = WEXITSTATUS(raw);
    run.error_text = test::readText(err);
    fs::remove(err);
    return run;
}

const std::string kShort = "--out out -- --frames 3 --every 0 --no-gif";

// Refused: status 2, one line saying `says`, and nothing new in the folder.
void expectRefused(const test::ScratchFolder& folder, const std::string& scene, const std::string& rest,
                   const std::string& says, const std::string& before = "") {
    const std::vector<std::string> files = folder.files();
    const test::ProgramRun run = compareRuns(folder, scene, rest, before);
    INFO(scene << " " << rest << "\n" << run.error_text);
    CHECK(run.status == 2);
    CHECK(test::isOneLine(run.error_text));
    CHECK_THAT(run.error_text, Catch::Contains(says));
    CHECK(folder.files() == files);
}

}  // namespace

TEST_CASE("compare_runs runs again into its own folder, and keeps a reader's file put in it") {
    const test::ScratchFolder folder("compare_runs_again");
    for (int run = 1; run <= 2; ++run) {
        const test::ProgramRun again = compareRuns(folder, quoted(kScene), "'{}' '{\"solver\": \"book\"}' " + kShort);
        INFO("run " << run << ": " << again.error_text);
        REQUIRE(again.status == 0);
    }
    CHECK(fs::is_regular_file(folder.path / "out" / "left" / "final.png"));
    // Its left/ and right/ are the runs' folders; a file of the reader's in one of them
    // is no run's, and stops the next run before it starts.
    std::ofstream(folder.path / "out" / "left" / "notes.txt") << "mine\n";
    expectRefused(folder, quoted(kScene), "'{}' '{}' " + kShort, "it holds \"left/notes.txt\", which no run wrote");
    CHECK(test::readText(folder.path / "out" / "left" / "notes.txt") == "mine\n");
}

TEST_CASE("compare_runs refuses a scene it cannot read, in one line, before anything is written") {
    const test::ScratchFolder folder("compare_runs_scene");
    REQUIRE(::mkfifo((folder.path / "fifo.json").c_str(), 0600) == 0);  // no writer: reading it would wait
    expectRefused(folder, "fifo.json", "'{}' '{}' " + kShort, "fifo.json: cannot read: it is a FIFO");
    fs::create_directory(folder.path / "scenes");
    expectRefused(folder, "scenes", "'{}' '{}' " + kShort, "scenes: cannot read: it is a folder");
    expectRefused(folder, "/dev/zero", "'{}' '{}' " + kShort, "/dev/zero: cannot read: it is a device");
    // 2 MB of nesting once segfaulted: a scene goes five levels deep, no deeper.
    const std::string deep = "{\"bodies\": " + std::string(1'000'000, '[') + std::string(1'000'000, ']') + "}";
    folder.write("deep.json", deep);
    expectRefused(folder, "deep.json", "'{}' '{}' " + kShort, "is nested deeper than a scene can be (5 levels)");
    folder.write("big.json", std::string(3 << 20, ' '));
    expectRefused(folder, "big.json", "'{}' '{}' " + kShort, "longer than 2097152 bytes");
    folder.write("list.json", "[1, 2]");
    expectRefused(folder, "list.json", "'{}' '{}' " + kShort, "is not a JSON object");
    fs::remove(folder.path / "deep.json");
    fs::remove(folder.path / "big.json");
}

TEST_CASE("compare_runs refuses a deeply nested setting in little memory, naming the setting") {
    const test::ScratchFolder folder("compare_runs_setting");
    // 130 KB of nesting once took 16 GB and blamed a scene file the reader never wrote.
    const std::string deep = "{\"gravity\": " + std::string(65'000, '[') + std::string(65'000, ']') + "}";
    folder.write("setting.txt", deep);
    // In 1 GB of address space (AddressSanitizer's shadow memory alone needs more).
    const std::string bounded = test::underAddressSanitizer ? "" : "ulimit -v 1000000; ";
    expectRefused(folder, quoted(kScene), "\"$(cat setting.txt)\" '{}' " + kShort,
                  "the left setting \"{\\\"gravity\\\": [[[", bounded);
    expectRefused(folder, quoted(kScene), "'{}' \"$(cat setting.txt)\" " + kShort,
                  "is nested deeper than world keys go", bounded);
}

TEST_CASE("compare_runs checks --crop: four whole numbers, not empty, on the canvas; in any order of options") {
    const test::ScratchFolder folder("compare_runs_crop");
    expectRefused(folder, quoted(kScene), "'{}' '{}' --crop 0,0,2000000000,2000000000 " + kShort,
                  "four whole numbers of canvas pixels");
    expectRefused(folder, quoted(kScene), "'{}' '{}' --crop 0,0,0,10 " + kShort, "at least 1 px");
    expectRefused(folder, quoted(kScene), "'{}' '{}' --crop 790,0,20,10 " + kShort,
                  "must lie within the canvas, 800 x 450 px");
    expectRefused(folder, quoted(kScene), "'{}' '{}' --crop 1,2,3 " + kShort, "give X,Y,W,H");
    // --out before --crop, and --crop last before "--", as well as the README's order.
    for (const char* order : {"--out out --crop 10,10,100,50 --", "--crop 10,10,100,50 --out out --"}) {
        const test::ProgramRun run =
            compareRuns(folder, quoted(kScene), std::string("'{}' '{}' ") + order + " --frames 2 --every 0 --no-gif");
        INFO(order << "\n" << run.error_text);
        CHECK(run.status == 0);
    }
}

namespace {

// compare_runs started in the background, in a process group of its own (so that a
// test can send a signal to the group, as Ctrl-C does); its process id.
pid_t startCompareRuns(const test::ScratchFolder& folder, const std::string& arguments) {
    const std::string command = "cd " + quoted(folder.path) + " && exec " + quoted(COMPARE_RUNS) + " " +
                                quoted(STAGE_PROGRAM) + " " + arguments + " >/dev/null 2>err.txt";
    return test::startShell(command, /*own_group=*/true);
}

}  // namespace

TEST_CASE("compare_runs ends by SIGINT or SIGTERM, to it or to its group, its runs stopped, the old folder kept") {
    const test::ScratchFolder folder("compare_runs_signal");
    REQUIRE(compareRuns(folder, quoted(kScene), "'{}' '{}' " + kShort).status == 0);
    const std::string before = test::readText(folder.path / "out" / ".manifest");
    struct Case {
        int signal;
        bool to_group;
    };
    for (const Case c : {Case{SIGTERM, false}, Case{SIGINT, false}, Case{SIGINT, true}}) {
        INFO("signal " << c.signal << (c.to_group ? " to the group" : " to compare_runs"));
        // A long run (minutes): stopped once its first run has started.
        const pid_t pid =
            startCompareRuns(folder, quoted(kScene) + " '{}' '{}' --out out -- --frames 100000 --every 0 --no-gif");
        REQUIRE(pid > 0);
        const fs::path staging = folder.path / ("out.partial-" + std::to_string(pid));
        // The left run's output file shows once it has started.
        for (int wait = 0; wait < 2000 && !fs::exists(staging / "left.stderr"); ++wait) {
            std::this_thread::sleep_for(std::chrono::milliseconds(10));
        }
        CHECK(fs::exists(staging / "left.stderr"));
        ::kill(c.to_group ? -pid : pid, c.signal);
        int status = 0;
        REQUIRE(::waitpid(pid, &status, 0) == pid);
        CHECK(WIFSIGNALED(status));
        CHECK((WIFSIGNALED(status) ? WTERMSIG(status) : -1) == c.signal);
        CHECK(folder.files() == std::vector<std::string>{"err.txt", "out"});
        CHECK(test::readText(folder.path / "out" / ".manifest") == before);
        // No run of the stage is left behind ("[-]" keeps pgrep's own shell from matching).
        CHECK(std::system(("pgrep -f -- '[-]-out " + staging.string() + "/left' >/dev/null").c_str()) != 0);
        CHECK(test::readText(folder.path / "err.txt").empty());
    }
}

}  // namespace compare_runs_test
