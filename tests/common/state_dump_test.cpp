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

#include "state_dump.h"
#include "scratch_folder.h"

namespace fs = std::filesystem;
using browser::FileError;
using browser::StateDump;
using browser::Vec2;

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
    CHECK(folder.files() == std::vector<std::string>{"dump.csv.partial"});
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

TEST_CASE("state_dump: a shape name other than rectangle or circle is refused") {
    ScratchFolder folder("shape");
    StateDump dump(folder.path / "dump.csv");
    CHECK_THROWS_AS(dump.row(0, 0, "triangle", {0, 0}, 0, {0, 0}, 0), std::invalid_argument);
    CHECK_THROWS_AS(dump.row(0, 0, "circle,1", {0, 0}, 0, {0, 0}, 0), std::invalid_argument);
}
