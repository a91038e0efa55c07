// State dumps: the numbers read back as the very doubles written, and only a finished
// dump ever appears under its own name.

#include <catch2/catch.hpp>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <unistd.h>
#include <vector>

#include <sys/stat.h>
#include <sys/sysmacros.h>

#include "state_dump.h"
#include "scratch_folder.h"

namespace fs = std::filesystem;
using browser::FileError;
using browser::StateDump;
using lib::Vec2;

namespace {

using test::ScratchFolder;

constexpr const char* kHeader = "step,index,shape,cx,cy,angle,vx,vy,angular_velocity";

std::vector<std::string> lines_of(const fs::path& file) {
    std::ifstream in(file);
    std::vector<std::string> lines;
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    return lines;
}

std::vector<std::string> fields_of(const std::string& line) {
    std::vector<std::string> fields;
    std::istringstream in(line);
    for (std::string field; std::getline(in, field, ',');) fields.push_back(field);
    return fields;
}

// The whole field must be the number: strtod stopping early would hide a bad format.
double read_back(const std::string& field) {
    char* end = nullptr;
    const double value = std::strtod(field.c_str(), &end);
    CHECK(*end == '\0');
    return value;
}

struct Row {
    long step;
    std::size_t index;
    std::string shape;
    std::vector<double> numbers;  // cx, cy, angle, vx, vy, angular_velocity
};

}  // namespace

TEST_CASE("state_dump: rows read back with strtod as the very doubles written") {
    ScratchFolder folder("roundtrip");
    const fs::path file = folder.path / "dump.csv";
    const std::vector<Row> rows{
        {0, 0, "rectangle", {0.1, 1.0 / 3.0, -1e-300, 123456789.123456789, 2.8, 0.0}},
        {0, 1, "circle", {-0.0, 5e-324, 1.7976931348623157e308, -2.0 / 3.0, 1e22, 0.30000000000000004}},
        {12345678901, 7, "circle", {HUGE_VAL, -HUGE_VAL, 1.0 / 60.0, 450.0, -7.25, 3.141592653589793}},
    };
    {
        StateDump dump(file);
        for (const Row& r : rows) {
            dump.row(r.step, r.index, r.shape, {r.numbers[0], r.numbers[1]}, r.numbers[2], {r.numbers[3], r.numbers[4]},
                     r.numbers[5]);
        }
        dump.finish();
    }

    const std::vector<std::string> lines = lines_of(file);
    REQUIRE(lines.size() == rows.size() + 1);
    CHECK(lines[0] == kHeader);
    for (std::size_t i = 0; i < rows.size(); ++i) {
        INFO(lines[i + 1]);
        const std::vector<std::string> fields = fields_of(lines[i + 1]);
        REQUIRE(fields.size() == 9);
        CHECK(fields[0] == std::to_string(rows[i].step));
        CHECK(fields[1] == std::to_string(rows[i].index));
        CHECK(fields[2] == rows[i].shape);
        for (std::size_t k = 0; k < 6; ++k) {
            const double back = read_back(fields[3 + k]);
            CHECK(back == rows[i].numbers[k]);
            CHECK(std::signbit(back) == std::signbit(rows[i].numbers[k]));  // -0 stays -0
        }
    }
}

TEST_CASE("state_dump: numbers have 17 significant digits and no locale's decimal comma") {
    ScratchFolder folder("digits");
    const fs::path file = folder.path / "dump.csv";
    StateDump dump(file);
    dump.row(3, 0, "circle", {0.1, 500}, 2.8, {-1e-300, 0}, 1.0 / 3.0);
    dump.finish();
    CHECK(lines_of(file).at(1) ==
          "3,0,circle,0.10000000000000001,500,2.7999999999999998,-1e-300,0,0.33333333333333331");
}

TEST_CASE("state_dump: a NaN from a simulation that blew up is written as nan") {
    ScratchFolder folder("nan");
    const fs::path file = folder.path / "dump.csv";
    StateDump dump(file);
    dump.row(1, 0, "rectangle", {std::nan(""), 0}, 0, {0, 0}, 0);
    dump.finish();
    const std::vector<std::string> fields = fields_of(lines_of(file).at(1));
    CHECK(std::isnan(read_back(fields.at(3))));
}

TEST_CASE("state_dump: the rows go to a partial file, renamed only by finish()") {
    ScratchFolder folder("finish");
    const fs::path file = folder.path / "dump.csv";
    StateDump dump(file);
    dump.row(0, 0, "circle", {1, 2}, 0, {0, 0}, 0);
    CHECK(folder.files() == std::vector<std::string>{"dump.csv.partial-" + std::to_string(::getpid())});
    dump.finish();
    CHECK(folder.files() == std::vector<std::string>{"dump.csv"});
    CHECK(lines_of(file).size() == 2);
    CHECK_THROWS_AS(dump.row(1, 0, "circle", {1, 2}, 0, {0, 0}, 0), std::logic_error);
}

TEST_CASE("state_dump: a dump never finished leaves nothing, and an older dump stays") {
    ScratchFolder folder("unfinished");
    const fs::path file = folder.path / "dump.csv";
    std::ofstream(file) << "an older run's dump\n";
    {
        StateDump dump(file);
        dump.row(0, 0, "rectangle", {1, 2}, 0, {0, 0}, 0);
    }  // as when the run stops with an error before finish()
    CHECK(folder.files() == std::vector<std::string>{"dump.csv"});
    CHECK(lines_of(file) == std::vector<std::string>{"an older run's dump"});
}

TEST_CASE("state_dump: a dump with no rows is just the header") {
    ScratchFolder folder("empty");
    const fs::path file = folder.path / "dump.csv";
    StateDump dump(file);
    dump.finish();
    CHECK(lines_of(file) == std::vector<std::string>{kHeader});
}

TEST_CASE("state_dump: rows with ids get the id column beside the index, and the dump keeps to one kind") {
    ScratchFolder folder("ids");
    const fs::path file = folder.path / "dump.csv";
    StateDump dump(file);
    dump.row(0, 0, 1, "rectangle", {1, 2}, 0, {0, 0}, 0);
    dump.row(0, 1, 7, "circle", {3, 4}, 0.5, {0, 0}, 0);
    // A row without an id in a dump with ids would shift every column after it.
    CHECK_THROWS_AS(dump.row(1, 0, "rectangle", {1, 2}, 0, {0, 0}, 0), std::logic_error);
    dump.finish();
    CHECK(lines_of(file) == std::vector<std::string>{"step,index,id,shape,cx,cy,angle,vx,vy,angular_velocity",
                                                     "0,0,1,rectangle,1,2,0,0,0,0", "0,1,7,circle,3,4,0.5,0,0,0"});

    const fs::path plain = folder.path / "plain.csv";
    StateDump without(plain);
    without.row(0, 0, "circle", {3, 4}, 0, {0, 0}, 0);
    CHECK_THROWS_AS(without.row(0, 1, 2, "circle", {3, 4}, 0, {0, 0}, 0), std::logic_error);
    without.finish();
    CHECK(lines_of(plain) == std::vector<std::string>{kHeader, "0,0,circle,3,4,0,0,0,0"});
}

TEST_CASE("state_dump: a file that cannot be created throws a one-line FileError naming it") {
    ScratchFolder folder("cannot_open");
    for (const fs::path& file : {folder.path / "no_such_folder" / "dump.csv", folder.path}) {
        INFO(file);
        try {
            StateDump dump(file);
            FAIL("StateDump did not throw");
        } catch (const FileError& error) {
            const std::string message = error.what();
            CHECK(message.find(file.string()) != std::string::npos);
            CHECK(message.find('\n') == std::string::npos);
        }
    }
    CHECK(folder.files().empty());
}

TEST_CASE("state_dump: a kind that is not a plain word is refused") {
    ScratchFolder folder("shape");
    StateDump dump(folder.path / "dump.csv");
    CHECK_NOTHROW(dump.row(0, 0, "triangle", {0, 0}, 0, {0, 0}, 0));  // the stage's words are the stage's
    CHECK_THROWS_AS(dump.row(0, 0, "Triangle", {0, 0}, 0, {0, 0}, 0), std::invalid_argument);
    CHECK_THROWS_AS(dump.row(0, 0, "", {0, 0}, 0, {0, 0}, 0), std::invalid_argument);
    CHECK_THROWS_AS(dump.row(0, 0, "circle,1", {0, 0}, 0, {0, 0}, 0), std::invalid_argument);
}

namespace {

// The one-line OutputRefused a StateDump to `file` gives ("" when it is made).
std::string refusal_of(const fs::path& file, const fs::path& out = {}) {
    try {
        StateDump dump(file, out);
    } catch (const browser::OutputRefused& error) {
        return error.what();
    }
    return "";
}

}  // namespace

TEST_CASE("state_dump: only a regular file is replaced; a link, a FIFO, a device or a folder is refused") {
    ScratchFolder folder("not_regular");
    // A symbolic link, even to a regular file: the file it points to stays as it is.
    const fs::path target = folder.path / "target.csv";
    std::ofstream(target) << "someone's data\n";
    fs::create_symlink(target, folder.path / "link.csv");
    CHECK(refusal_of(folder.path / "link.csv") ==
          "cannot write state dump " + (folder.path / "link.csv").string() + ": it is a symbolic link");
    CHECK(lines_of(target) == std::vector<std::string>{"someone's data"});
    // A FIFO (a reader waiting at the other end would get a dump it never asked for).
    const fs::path fifo = folder.path / "fifo";
    REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
    CHECK(refusal_of(fifo) == "cannot write state dump " + fifo.string() + ": it is a FIFO");
    // A device: only ever named here, never one a failing test could replace.
    CHECK(refusal_of("/dev/null") == "cannot write state dump /dev/null: it is a device");
    CHECK(fs::is_character_file("/dev/null"));
    // A device node of our own, where the system lets us make one.
    const fs::path node = folder.path / "null";
    if (::mknod(node.c_str(), S_IFCHR | 0600, makedev(1, 3)) == 0) {
        CHECK(refusal_of(node) == "cannot write state dump " + node.string() + ": it is a device");
        CHECK(fs::is_character_file(node));
    }
    CHECK(refusal_of(folder.path) == "cannot write state dump " + folder.path.string() + ": it is a folder");
    std::vector<std::string> expected{"fifo", "link.csv", "target.csv"};
    if (fs::exists(fs::symlink_status(node))) expected.insert(expected.begin() + 2, "null");
    CHECK(folder.files() == expected);  // no partial file of any of them
}

TEST_CASE("state_dump: a dump inside the --out folder waits beside it and moves in after the run") {
    ScratchFolder folder("inside_out");
    const fs::path out = folder.path / "out";
    fs::create_directories(out);
    std::ofstream(out / "final.png") << "an older run's picture";
    StateDump dump(out / "dump.csv", out);
    dump.row(0, 0, "circle", {1, 2}, 0, {0, 0}, 0);
    // The run replaces the folder as a whole: the dump must not be inside the old one.
    CHECK(folder.files() == std::vector<std::string>{"out", "out.dump.csv-partial-" + std::to_string(::getpid())});
    fs::remove_all(out);
    fs::create_directories(out);  // the run's new folder
    dump.finish();
    CHECK(folder.files() == std::vector<std::string>{"out"});
    CHECK(lines_of(out / "dump.csv").size() == 2);
    // The folder itself is no file for a dump.
    CHECK(refusal_of(out, out) == "cannot write state dump " + out.string() + ": it is the --out folder or holds it");
}

TEST_CASE("state_dump: partial files of dumps whose process is gone are removed; others stay") {
    ScratchFolder folder("stale");
    const std::string gone = "4194305";  // one past the largest process id the kernel hands out
    std::ofstream(folder.path / ("dump.csv.partial-" + gone)) << "x";
    std::ofstream(folder.path / "dump.csv.partial-1") << "x";  // init's: alive
    std::ofstream(folder.path / "other.csv.partial-4194305") << "x";
    StateDump dump(folder.path / "dump.csv");
    dump.finish();
    CHECK(folder.files() == std::vector<std::string>{"dump.csv", "dump.csv.partial-1", "other.csv.partial-4194305"});
}

TEST_CASE("state_dump: a non-finite state names the step, the body and its shape in one line") {
    const browser::NonFiniteState error(12, 3, "circle");
    CHECK(std::string(error.what()) ==
          "step 12: body 3 (circle) has a position or velocity that is not a finite number; the scene is beyond what "
          "this engine can compute, and nothing was written");
}
