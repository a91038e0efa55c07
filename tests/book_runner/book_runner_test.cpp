// tools/book_runner end to end, on standin/ (our own small project in the book's
// shape: rectangles fall by symplectic Euler, circles by explicit Euler, nothing
// collides), and first_divergence on its dump against stage 4.1's own --dump.

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

#include "near.h"
#include "random.h"
#include "scratch_folder.h"
#include "stage_program.h"

namespace fs = std::filesystem;

namespace {

constexpr double kDt = 1.0 / 60.0;
constexpr double kGravity = 30.0;  // the scene's, px/s^2

// A box falling from rest, a circle thrown sideways and spinning, a static plank: far
// apart, so that in 4.1 (detection, no response) nothing but gravity acts.
const char* kFallScene = R"({"world": {"movement": true, "gravity": [0, 30]},
 "bodies": [
  {"shape": "rectangle", "center": [100, 50], "width": 20, "height": 10},
  {"shape": "circle", "center": [300, 60], "radius": 10, "velocity": [6, 0], "angular_velocity": 0.5},
  {"shape": "rectangle", "center": [500, 300], "width": 200, "height": 20, "mass": 0, "angle": 0.25}
 ]})";

fs::path writeFile(const test::ScratchFolder& folder, const std::string& name, const std::string& text) {
    const fs::path file = folder.path / name;
    std::ofstream(file) << text;
    return file;
}

// A shell command's exit status and what it printed; its output goes to files in `folder`.
struct Run {
    int status = -1;
    std::string out, error;
};
Run runCommand(const test::ScratchFolder& folder, const std::string& command) {
    const fs::path out = folder.path / "run_stdout.txt", err = folder.path / "run_stderr.txt";
    const int raw = std::system((command + " >" + test::quoted(out) + " 2>" + test::quoted(err)).c_str());
    Run run;
    if (raw != -1 && WIFEXITED(raw)) run.status = WEXITSTATUS(raw);
    run.out = test::readText(out);
    run.error = test::readText(err);
    return run;
}

Run runBook(const test::ScratchFolder& folder, const std::string& arguments) {
    return runCommand(folder, test::quoted(BOOK_RUNNER) + " " + test::quoted(STANDIN_PROJECT) + " " + arguments);
}

std::vector<test::DumpRow> rowsOf(const std::vector<test::DumpRow>& rows, std::size_t index) {
    std::vector<test::DumpRow> picked;
    for (const test::DumpRow& row : rows) {
        if (row.index == index) picked.push_back(row);
    }
    return picked;
}

}  // namespace

TEST_CASE("the book's code runs on our scene: every step of free fall as worked out by hand", "[book_runner_test]") {
    test::ScratchFolder folder("book_runner_fall");
    const fs::path scene = writeFile(folder, "fall.json", kFallScene);
    const fs::path dump = folder.path / "book.csv";
    const Run run = runBook(folder, "--scene " + test::quoted(scene) + " --frames 60 --dump " + test::quoted(dump));
    INFO(run.error);
    REQUIRE(run.status == 0);
    const std::vector<test::DumpRow> rows = test::readDump(dump);

    // Step k of symplectic Euler from rest: v = k g dt, y = y0 + g dt^2 k (k + 1) / 2.
    const auto box = rowsOf(rows, 0);
    REQUIRE(box.size() > 50);
    for (const test::DumpRow& row : box) {
        const double k = static_cast<double>(row.step);
        CHECK_THAT(row.vy, test::near(k * kGravity * kDt, 1e-9));
        CHECK_THAT(row.cy, test::near(50 + kGravity * kDt * kDt * k * (k + 1) / 2, 1e-9));
        CHECK(row.cx == 100);
    }
    // Explicit Euler moves with the old velocity: y = y0 + g dt^2 k (k - 1) / 2; the
    // sideways speed and the spin carry it k dt along.
    for (const test::DumpRow& row : rowsOf(rows, 1)) {
        const double k = static_cast<double>(row.step);
        CHECK(row.shape == "circle");
        CHECK_THAT(row.cy, test::near(60 + kGravity * kDt * kDt * k * (k - 1) / 2, 1e-9));
        CHECK_THAT(row.cx, test::near(300 + 6 * k * kDt, 1e-9));
        CHECK_THAT(row.angle, test::near(0.5 * k * kDt, 1e-12));
    }
    // The static plank keeps its place and its turn.
    for (const test::DumpRow& row : rowsOf(rows, 2)) {
        CHECK(row.cy == 300);
        CHECK(row.angle == 0.25);
    }
}

TEST_CASE("first_divergence finds the stand-in's planted difference against stage 4.1", "[book_runner_test]") {
    test::ScratchFolder folder("book_runner_diverge");
    const fs::path scene = writeFile(folder, "fall.json", kFallScene);
    const fs::path ours = folder.path / "ours.csv", book = folder.path / "book.csv";
    const test::ProgramRun stage =
        test::runStageProgram(folder, "--scene " + test::quoted(scene) + " --keys '' --frames 60 --every 0 --out " +
                                          test::quoted(folder.path / "out") + " --dump " + test::quoted(ours));
    INFO(stage.error_text);
    REQUIRE(stage.status == 0);
    REQUIRE(runBook(folder, "--scene " + test::quoted(scene) + " --frames 60 --dump " + test::quoted(book)).status ==
            0);

    // Both loops run the same fixed updates on the same clock.
    const auto our_rows = test::readDump(ours), book_rows = test::readDump(book);
    REQUIRE(our_rows.size() == book_rows.size());
    CHECK(our_rows.back().step == book_rows.back().step);

    // The boxes agree; the circle parts at step 1, where ours has moved by g dt^2 and
    // the stand-in's explicit Euler has not moved down at all.
    const Run compare = runCommand(
        folder, test::quoted(FIRST_DIVERGENCE) + " " + test::quoted(ours) + " " + test::quoted(book) + " --stage 4.1");
    INFO(compare.out << compare.error);
    CHECK(compare.status == 1);
    CHECK_THAT(compare.out, Catch::Contains("step 1, body 1 (circle): cy is 60.008333333333333 in "));
    CHECK_THAT(compare.out, Catch::Contains(" and 60 in "));
    CHECK_THAT(compare.out, Catch::Contains("no entry of docs/errata.md explains this for 4.1"));
    // A dump compared with itself agrees.
    const Run same =
        runCommand(folder, test::quoted(FIRST_DIVERGENCE) + " " + test::quoted(book) + " " + test::quoted(book));
    CHECK(same.status == 0);
    CHECK_THAT(same.out, Catch::Contains("no divergence"));
}

TEST_CASE("Math.random is our seeded generator: F throws the shape our stages would", "[book_runner_test]") {
    test::ScratchFolder folder("book_runner_random");
    const fs::path dump = folder.path / "book.csv";
    // No scene: the stand-in's own MyGame, one static box at (100, 100); F before frame 0.
    for (const std::uint64_t seed : {2017ull, 7ull}) {
        const Run run =
            runBook(folder, "--keys f --frames 2 --seed " + std::to_string(seed) + " --dump " + test::quoted(dump));
        INFO(run.error);
        REQUIRE(run.status == 0);
        const auto made = rowsOf(test::readDump(dump), 1);
        REQUIRE_FALSE(made.empty());
        // Width and height take the first two draws, the velocity the next two.
        browser::Random random(seed);
        random.next();
        random.next();
        const double vx = random.next() * 300 - 150, vy = random.next() * 300 - 150;
        CHECK(made.front().step == 1);
        CHECK(made.front().vx == vx);
        CHECK(made.front().vy == vy);
        CHECK(made.front().cx == 100);  // movement is off in the stand-in's own world
    }
}

TEST_CASE("a page that throws in every frame stops updating, as a browser's does", "[book_runner_test]") {
    test::ScratchFolder folder("book_runner_throw");
    const fs::path scene = writeFile(folder, "fall.json", kFallScene);
    const fs::path full = folder.path / "full.csv", frozen = folder.path / "frozen.csv";
    REQUIRE(runBook(folder, "--scene " + test::quoted(scene) + " --frames 10 --dump " + test::quoted(full)).status ==
            0);
    // Select body 2, then X leaves only body 0: the echo of body 2 throws from frame 5 on.
    const Run run = runBook(
        folder, "--scene " + test::quoted(scene) + " --keys '2 x@5' --frames 10 --dump " + test::quoted(frozen));
    CHECK(run.status == 0);
    CHECK_THAT(run.error, Catch::Contains("the book's page threw 5 time(s)"));
    const auto rows = test::readDump(frozen);
    // Frames 0 to 4 ran 5 updates (1, 1, 0, 2, 1: the step is a hair longer than the
    // frame, docs/errata.md); nothing after.
    CHECK(rows.back().step == 5);
    const Run compare = runCommand(folder, test::quoted(FIRST_DIVERGENCE) + " " + test::quoted(full) + " " +
                                               test::quoted(frozen) + " --stage 5.1");
    CHECK(compare.status == 1);
    CHECK_THAT(compare.out, Catch::Contains("step 6: "));
    CHECK_THAT(compare.out, Catch::Contains("has no more steps"));
    CHECK_THAT(compare.out, Catch::Contains("the-selection-survives-the-removal-of-the-selected-shape-fixed-51"));
}

TEST_CASE("book code that never returns stops the run with one line, nothing written", "[book_runner_test]") {
    test::ScratchFolder folder("book_runner_endless");
    const fs::path dump = folder.path / "book.csv";
    // The stand-in's Z loops for ever.
    const Run run = runBook(folder, "--keys z@2 --frames 5 --script-timeout 0.5 --dump " + test::quoted(dump));
    CHECK(run.status == 3);
    CHECK(test::isOneLine(run.error));
    CHECK_THAT(run.error, Catch::Contains("ran for over 0.5 s in frame 2, key code 90 without returning"));
    CHECK_FALSE(fs::exists(dump));
}

TEST_CASE("the runner refuses what it cannot run with one line, and writes nothing", "[book_runner_test]") {
    test::ScratchFolder folder("book_runner_refuse");
    const fs::path dump = folder.path / "book.csv";
    const auto refused = [&](const std::string& arguments, const std::string& says) {
        const Run run = runBook(folder, arguments + " --dump " + test::quoted(dump));
        INFO(arguments << "\n" << run.error);
        CHECK(run.status == 2);
        CHECK(test::isOneLine(run.error));
        CHECK_THAT(run.error, Catch::StartsWith("book_runner: ") && Catch::Contains(says));
        CHECK_FALSE(fs::exists(dump));
    };
    const fs::path typo =
        writeFile(folder, "typo.json", R"({"bodies": [{"shape": "circle", "center": [1, 2], "radius": 3, "mas": 2}]})");
    refused("--scene " + test::quoted(typo) + " --frames 5", "bodies[0].mas: unknown key");
    const fs::path step = writeFile(folder, "step.json", R"({"world": {"dt": 0.01}, "bodies": []})");
    refused("--scene " + test::quoted(step) + " --frames 5",
            "world.dt: the book's code keeps this in a private variable");
    const fs::path grid = writeFile(folder, "grid.json", R"({"world": {"broad_phase": "grid"}, "bodies": []})");
    refused("--scene " + test::quoted(grid) + " --frames 5", "world.broad_phase: the book's code has no such setting");
    refused("--keys 'f*0' --frames 5", "bad key script token \"f*0\"");
    refused("--frames 0", "--frames must be a whole number");
    // The scene the run reads, and the book's own folder, are never written.
    const std::string typo_text = test::readText(typo);
    const Run over_scene =
        runBook(folder, "--scene " + test::quoted(typo) + " --frames 5 --dump " + test::quoted(typo));
    CHECK(over_scene.status == 2);
    CHECK_THAT(over_scene.error, Catch::Contains("that is the scene file the run reads"));
    CHECK(test::readText(typo) == typo_text);
    const fs::path inside = fs::path(STANDIN_PROJECT) / "public_html" / "dump.csv";
    const Run into_book = runBook(folder, "--frames 5 --dump " + test::quoted(inside));
    CHECK(into_book.status == 2);
    CHECK_THAT(into_book.error, Catch::Contains("inside the book project"));
    CHECK_FALSE(fs::exists(inside));
    // A folder that is not there: the system's refusal, status 1, as for our programs.
    const Run no_folder = runBook(folder, "--frames 5 --dump " + test::quoted(folder.path / "missing" / "book.csv"));
    CHECK(no_folder.status == 1);
    CHECK(test::isOneLine(no_folder.error));
    CHECK_THAT(no_folder.error, Catch::Contains("cannot write"));
    fs::create_directory(folder.path / "empty");
    const Run no_book = runCommand(folder, test::quoted(BOOK_RUNNER) + " " + test::quoted(folder.path / "empty") +
                                               " --frames 5 --dump " + test::quoted(dump));
    CHECK(no_book.status == 2);
    CHECK_THAT(no_book.error, Catch::Contains("no index.html to load"));
    CHECK_FALSE(fs::exists(dump));
}

TEST_CASE("first_divergence refuses a file that is not a dump, in one line naming it", "[book_runner_test]") {
    test::ScratchFolder folder("book_runner_not_a_dump");
    const fs::path scene = writeFile(folder, "fall.json", kFallScene);
    const Run run =
        runCommand(folder, test::quoted(FIRST_DIVERGENCE) + " " + test::quoted(scene) + " " + test::quoted(scene));
    CHECK(run.status == 2);
    CHECK(test::isOneLine(run.error));
    CHECK_THAT(run.error, Catch::Contains("fall.json:1: not a state dump"));
    const Run missing = runCommand(folder, test::quoted(FIRST_DIVERGENCE) + " " +
                                               test::quoted(folder.path / "none.csv") + " " + test::quoted(scene));
    CHECK(missing.status == 2);
    CHECK(test::isOneLine(missing.error));
    const Run stage = runCommand(folder, test::quoted(FIRST_DIVERGENCE) + " a.csv b.csv --stage 44");
    CHECK(stage.status == 2);
    CHECK(test::isOneLine(stage.error));
}

TEST_CASE("tools/book_runner_compare runs both and gives first_divergence's verdict", "[book_runner_test]") {
    test::ScratchFolder folder("book_runner_compare");
    const fs::path scene = writeFile(folder, "fall.json", kFallScene);
    const std::string command = test::quoted(BOOK_RUNNER_COMPARE) + " " + test::quoted(STANDIN_PROJECT);
    const std::string where = " --build " + test::quoted(BUILD_DIR) + " --out " + test::quoted(folder.path / "compare");
    const Run run = runCommand(folder, command + " 4.1 --scene " + test::quoted(scene) + " --frames 60" + where);
    INFO(run.out << run.error);
    CHECK(run.status == 1);
    CHECK_THAT(run.out, Catch::Contains("step 1, body 1 (circle): cy is 60.008333333333333 in "));
    CHECK(fs::exists(folder.path / "compare" / "ours.csv"));
    CHECK(fs::exists(folder.path / "compare" / "book.csv"));

    const Run bad = runCommand(folder, command + " 44" + where);
    CHECK(bad.status == 2);
    CHECK(test::isOneLine(bad.error));
    CHECK_THAT(bad.error, Catch::Contains("a book project is X.Y"));
}

namespace {

// A copy of the stand-in project to spoil, in `folder`/book.
fs::path standinCopy(const test::ScratchFolder& folder) {
    const fs::path book = folder.path / "book";
    fs::copy(STANDIN_PROJECT, book, fs::copy_options::recursive);
    return book;
}

Run runOn(const test::ScratchFolder& folder, const fs::path& book, const std::string& arguments,
          const std::string& before = "") {
    return runCommand(folder,
                      before + "timeout 60 " + test::quoted(BOOK_RUNNER) + " " + test::quoted(book) + " " + arguments);
}

void replaceIn(const fs::path& file, const std::string& from, const std::string& to) {
    std::string text = test::readText(file);
    text.replace(text.find(from), from.size(), to);
    std::ofstream(file) << text;
}

}  // namespace

TEST_CASE("the runner reads only regular files of the project it was given, each in one line when refused",
          "[book_runner_test]") {
    test::ScratchFolder folder("book_runner_files");
    const fs::path dump = folder.path / "book.csv";
    const std::string args = "--frames 3 --dump " + test::quoted(dump);
    const auto refused = [&](const fs::path& book, const std::string& says) {
        const Run run = runOn(folder, book, args);
        INFO(run.error);
        CHECK(run.status == 2);
        CHECK(test::isOneLine(run.error));
        CHECK_THAT(run.error, Catch::Contains(says));
        CHECK_FALSE(fs::exists(dump));
    };
    // A FIFO as index.html or as a script once waited for ever; a script linked to
    // /dev/zero grew to 13.8 GB.
    const fs::path fifo_index = standinCopy(folder);
    fs::remove(fifo_index / "public_html" / "index.html");
    REQUIRE(::mkfifo((fifo_index / "public_html" / "index.html").c_str(), 0600) == 0);
    refused(fifo_index, "index.html: it is a FIFO, not a regular file");
    fs::remove_all(fifo_index);
    const fs::path fifo_script = standinCopy(folder);
    fs::remove(fifo_script / "public_html" / "MyGame.js");
    REQUIRE(::mkfifo((fifo_script / "public_html" / "MyGame.js").c_str(), 0600) == 0);
    refused(fifo_script, "MyGame.js: it is a FIFO, not a regular file");
    fs::remove_all(fifo_script);
    const fs::path zero = standinCopy(folder);
    fs::remove(zero / "public_html" / "MyGame.js");
    fs::create_symlink("/dev/zero", zero / "public_html" / "MyGame.js");
    refused(zero, "its script MyGame.js lies outside the project folder");
    fs::remove_all(zero);
    // A script from outside the folder given, by a path or by a link, is never read.
    const fs::path climbing = standinCopy(folder);
    replaceIn(climbing / "public_html" / "index.html", "src=\"MyGame.js\"",
              "src=\"../../../../../../../etc/hostname\"");
    refused(climbing, "lies outside the project folder");
    fs::remove_all(climbing);
}

TEST_CASE("a script that allocates for ever ends the run in one line, status 3, nothing written",
          "[book_runner_test]") {
    test::ScratchFolder folder("book_runner_memory");
    const fs::path dump = folder.path / "book.csv";
    const fs::path book = standinCopy(folder);
    std::ofstream(book / "public_html" / "MyGame.js", std::ios::app)
        << "\nvar hog = []; while (true) hog.push(new Array(100000).fill(1.5));\n";
    // A small heap for the test; by default it is 2 GB.
    const Run run = runOn(folder, book, "--frames 3 --dump " + test::quoted(dump), "BOOK_RUNNER_HEAP_MB=64 ");
    INFO(run.error);
    CHECK(run.status == 3);
    CHECK(test::isOneLine(run.error));
    CHECK_THAT(run.error, Catch::Contains("the book's code ran out of memory"));
    CHECK(folder.files() == std::vector<std::string>{"book", "run_stderr.txt", "run_stdout.txt"});
}

TEST_CASE("a number beyond a double's range in a scene is named as such", "[book_runner_test]") {
    test::ScratchFolder folder("book_runner_range");
    const fs::path scene =
        writeFile(folder, "big.json", R"({"bodies": [{"shape": "circle", "center": [1e400, 2], "radius": 3}]})");
    const Run run = runBook(
        folder, "--scene " + test::quoted(scene) + " --frames 3 --dump " + test::quoted(folder.path / "book.csv"));
    CHECK(run.status == 2);
    CHECK_THAT(run.error, Catch::Contains("center[0]: must be a finite number (got a number beyond the range"));
}

TEST_CASE("SIGINT and SIGTERM end the runner by that signal, with no dump and no partial file", "[book_runner_test]") {
    for (const int signal : {SIGINT, SIGTERM}) {
        INFO("signal " << signal);
        test::ScratchFolder folder("book_runner_signal");
        const fs::path dump = folder.path / "book.csv";
        // The stand-in's Z loops for ever: the page is busy when the signal comes.
        const std::string command = "exec " + test::quoted(BOOK_RUNNER) + " " + test::quoted(STANDIN_PROJECT) +
                                    " --keys z@2 --frames 5 --dump " + test::quoted(dump) + " 2>/dev/null";
        const pid_t pid = test::startShell(command);
        const fs::path partial = dump.string() + ".partial-" + std::to_string(pid);
        for (int wait = 0; wait < 2000 && !fs::exists(partial); ++wait) {
            std::this_thread::sleep_for(std::chrono::milliseconds(10));
        }
        CHECK(fs::exists(partial));
        std::this_thread::sleep_for(std::chrono::milliseconds(200));  // into the endless key handler
        ::kill(pid, signal);
        int status = 0;
        REQUIRE(::waitpid(pid, &status, 0) == pid);
        CHECK(WIFSIGNALED(status));
        CHECK((WIFSIGNALED(status) ? WTERMSIG(status) : -1) == signal);
        CHECK(folder.files().empty());
    }
}

TEST_CASE("first_divergence: a tolerance is a plain number, a dump a regular file, memory a step of each",
          "[book_runner_test]") {
    test::ScratchFolder folder("first_divergence_hostile");
    const auto trouble = [&](const std::string& arguments, const std::string& says, const std::string& before = "") {
        const Run run = runCommand(folder, before + "timeout 60 " + test::quoted(FIRST_DIVERGENCE) + " " + arguments);
        INFO(arguments << "\n" << run.error);
        CHECK(run.status == 2);
        CHECK(test::isOneLine(run.error));
        CHECK(run.error.size() < 300);  // an out-of-range tolerance was once echoed in 300 digits
        CHECK_THAT(run.error, Catch::Contains(says));
    };
    std::string rows = "step,index,shape,cx,cy,angle,vx,vy,angular_velocity\n";
    const fs::path small = writeFile(folder, "small.csv", rows + "0,0,circle,1,2,3,4,5,6\n");
    const std::string pair = test::quoted(small) + " " + test::quoted(small);
    trouble(pair + " --absolute nan", "--absolute: must be a number from 0 to 1e+06 (got \"nan\")");
    trouble(pair + " --absolute -1e300", "must be a number from 0 to 1e+06");
    trouble(pair + " --relative 1e400", "--relative: must be a number from 0 to 1 (got \"1e400\")");
    REQUIRE(::mkfifo((folder.path / "fifo.csv").c_str(), 0600) == 0);
    trouble(test::quoted(folder.path / "fifo.csv") + " " + test::quoted(small), "fifo.csv: cannot read: it is a FIFO");
    trouble(test::quoted(folder.path) + " " + test::quoted(small), "cannot read: it is a folder");
    trouble("/dev/zero " + test::quoted(small), "/dev/zero: cannot read: it is a device");
    writeFile(folder, "long.csv", rows + std::string(10'000, '1') + "\n");
    trouble(test::quoted(folder.path / "long.csv") + " " + test::quoted(small), "a line longer than 4096 bytes");
    // 1,000,000 steps of one body (25 MB) against itself, in 100 MB of address space:
    // the whole dumps in memory took twice that.
    if (!test::underAddressSanitizer) {
        {
            std::ofstream big(folder.path / "big.csv");
            big << rows;
            for (int step = 0; step < 1'000'000; ++step) big << step << ",0,circle,1,2,3,4,5,6\n";
        }
        const fs::path big = folder.path / "big.csv";
        const Run run = runCommand(folder, "ulimit -v 100000; " + test::quoted(FIRST_DIVERGENCE) + " " +
                                               test::quoted(big) + " " + test::quoted(big));
        INFO(run.error);
        CHECK(run.status == 0);
        CHECK_THAT(run.out, Catch::Contains("agree at every step"));
    }
}
