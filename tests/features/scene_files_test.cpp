// Scene files and state dumps (every stage from 4.1 on): how the stage uses them, end
// to end through its program as a reader runs it. What load_scene accepts and refuses
// is tested once, in tests/common/scene_file_test.cpp.
#include <catch2/catch.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <csignal>
#include <fstream>
#include <limits>
#include <thread>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "near.h"
#include "png_io.h"
#include "rectangle.h"
#include "scene_file.h"
#include "page_world.h"
#include "scene_io.h"
#include "stage_program.h"
#include "world_fixture.h"
#include "book_scene.h"
#include "circle.h"

#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <sys/wait.h>

namespace scene_files_test {

namespace fs = std::filesystem;
using engine::Vec2;

namespace {

// Numbers chosen to be awkward in binary (0.1, 2.8, 1e-3) and of every kind a body has.
constexpr const char* kScene = R"({
  "bodies": [
    {"shape": "rectangle", "center": [500.25, 200.1], "width": 400, "height": 20,
     "mass": 0, "friction": 0.3, "restitution": 0, "angle": 2.8},
    {"shape": "circle", "center": [100.5, 50.75], "radius": 20, "mass": 5, "friction": 0.5,
     "restitution": 0.4, "velocity": [10.5, -3.25], "angular_velocity": -0.7},
    {"shape": "rectangle", "center": [0.001, 449.999], "width": 12.5, "height": 7,
     "angle": -0.1, "velocity": [1e-3, 0]}
  ]
})";

// A run that writes its pictures and dump into `folder`. No keys are pressed: a stage's
// default script may press keys later than the few frames these runs take.
std::string arguments(const test::ScratchFolder& folder, const std::string& scene, const std::string& more) {
    std::string text = more;
    text.append(" --keys ''");
    if (!scene.empty()) text.append(" --scene ").append(test::quoted(folder.path / scene));
    text.append(" --dump ").append(test::quoted(folder.path / "dump.csv"));
    text.append(" --out ").append(test::quoted(folder.path / "out"));
    return text;
}

std::vector<test::DumpRow> rowsOfStep(const std::vector<test::DumpRow>& rows, long step) {
    std::vector<test::DumpRow> found;
    for (const test::DumpRow& row : rows) {
        if (row.step == step) found.push_back(row);
    }
    return found;
}

// docs/scene_format.md, whose tables give every key of every stage: its values, its
// default and the stages that read it. Each stage holds them against its own keys.
const fs::path kSceneFormat = fs::path(SCENE_LIBRARY_DIR) / ".." / ".." / "docs" / "scene_format.md";

struct Table {
    std::vector<std::string> header;
    std::vector<std::vector<std::string>> rows;
};

std::vector<std::string> cellsOf(const std::string& line) {
    std::vector<std::string> cells;
    std::size_t start = 1;
    for (std::size_t bar = line.find('|', start); bar != std::string::npos; bar = line.find('|', start)) {
        std::string cell = line.substr(start, bar - start);
        cell.erase(0, cell.find_first_not_of(' '));
        cell.erase(cell.find_last_not_of(' ') + 1);
        cells.push_back(cell);
        start = bar + 1;
    }
    return cells;
}

// The first table after the line `heading`.
Table tableAfter(const std::string& heading) {
    std::ifstream in(kSceneFormat);
    std::string line;
    while (std::getline(in, line) && line != heading) {}
    while (std::getline(in, line) && !line.starts_with("|")) {}
    Table table{.header = cellsOf(line)};
    std::getline(in, line);  // |---|---|
    while (std::getline(in, line) && line.starts_with("|")) table.rows.push_back(cellsOf(line));
    return table;
}

// "4.3" for s4_3, and stage numbers as numbers: 4.3 is 43.
int stageNumber(std::string_view id) { return (id[1] - '0') * 10 + (id[3] - '0'); }
int stageNumber() { return stageNumber(STAGE_ID); }

// Whether a column "5.2" or "4.2-4.4" holds this stage.
bool columnHolds(const std::string& column) {
    const auto number = [](std::string_view text) { return (text[0] - '0') * 10 + (text[2] - '0'); };
    if (column.size() == 3) return number(column) == stageNumber();
    return column.size() == 7 && number(column) <= stageNumber() && stageNumber() <= number(column.substr(4));
}

// The key a row names: "`dt`" is dt.
std::string keyOf(const std::vector<std::string>& row) { return row.at(0).substr(1, row.at(0).size() - 2); }

// A default cell for this stage: "`[0, 10]`; `[0, 20]` from 5.1" is [0, 20] from 5.1 on.
std::string defaultHere(const std::string& cell) {
    std::string value;
    std::size_t start = 0;
    while (start < cell.size()) {
        const std::size_t open = cell.find('`', start), close = cell.find('`', open + 1);
        const std::size_t end = std::min(cell.find("; ", close), cell.size());
        const std::string rest = cell.substr(close + 1, end - close - 1);
        const bool applies =
            rest.empty() || (rest.starts_with(" from ") && (rest[6] - '0') * 10 + (rest[8] - '0') <= stageNumber());
        if (applies) value = cell.substr(open + 1, close - open - 1);
        start = end + 2;
    }
    return value;
}

// The world keys docs/scene_format.md gives this stage, in the table's order.
std::vector<std::string> documentedWorldKeys() {
    const Table table = tableAfter("## Which stage reads which world key");
    std::vector<std::string> keys;
    for (const std::vector<std::string>& row : table.rows) {
        for (std::size_t column = 0; column < table.header.size(); ++column) {
            if (columnHolds(table.header[column]) && row.at(column) == "x") keys.push_back(keyOf(row));
        }
    }
    return keys;
}

std::string commaList(const std::vector<std::string>& words) {
    std::string list;
    for (const std::string& word : words) list.append(list.empty() ? "" : ", ").append(word);
    return list;
}

std::vector<std::string> keysThisStageReads() {
    engine::WorldSettings world;
    std::vector<std::string> names;
    for (const browser::SceneKey& key : engine::worldKeys(world)) names.emplace_back(key.name());
    return names;
}

}  // namespace

TEST_CASE("scene files: the stage reads exactly the world keys docs/scene_format.md gives it") {
    CHECK(keysThisStageReads() == documentedWorldKeys());
}

TEST_CASE("scene files: the world keys' values and defaults are as docs/scene_format.md gives them") {
    engine::WorldSettings world = engine::kBookWorld;
    const Table table = tableAfter("## Which stage reads which world key");
    REQUIRE(table.header.size() > 3);
    REQUIRE(table.header[1] == "values");
    REQUIRE(table.header[2] == "default");
    for (const browser::SceneKey& key : engine::worldKeys(world)) {
        const browser::KeyDescription described = browser::describe(key);
        INFO(described.name);
        const auto row = std::find_if(table.rows.begin(), table.rows.end(),
                                      [&](const auto& cells) { return keyOf(cells) == described.name; });
        REQUIRE(row != table.rows.end());
        CHECK((*row)[1] == described.values);
        CHECK(defaultHere((*row)[2]) == described.value_now);
    }
}

TEST_CASE("scene files: the body keys of each shape are as docs/scene_format.md gives them") {
    const Table table = tableAfter("## Body keys");
    REQUIRE(table.header.size() >= 5);
    std::vector<engine::BodyDescription> bodies;
    const browser::SceneList list = engine::bodyList(bodies);
    // The kind key's row: every body needs it, with one of the list's words: the first
    // stage's, then '; "polygon" from 5.8' for each kind a later stage adds.
    REQUIRE_FALSE(table.rows.empty());
    CHECK(keyOf(table.rows[0]) == list.kind_key);
    std::string cell = table.rows[0][2];
    std::vector<std::string> documented_kinds;
    for (std::size_t end = cell.find("; "); !cell.empty(); end = cell.find("; ")) {
        std::string part = cell.substr(0, end);
        cell = end == std::string::npos ? "" : cell.substr(end + 2);
        if (const std::size_t from = part.find(" from "); from != std::string::npos) {
            const std::string since = part.substr(from + 6);
            part = part.substr(0, from);
            if (stageNumber() < stageNumber("s" + since.substr(0, 1) + "_" + since.substr(2, 1))) continue;
        }
        for (std::size_t quote = part.find('"'); quote != std::string::npos; quote = part.find('"', quote)) {
            const std::size_t close = part.find('"', quote + 1);
            documented_kinds.push_back(part.substr(quote + 1, close - quote - 1));
            quote = close + 1;
        }
    }
    CHECK(documented_kinds == std::vector<std::string>(list.kinds.begin(), list.kinds.end()));
    for (std::size_t kind = 0; kind < list.kinds.size(); ++kind) {
        const std::string shape(list.kinds[kind]);
        INFO(shape);
        std::vector<std::string> documented;
        for (const std::vector<std::string>& row : table.rows) {
            const bool of_shape = row[1] == "every body" || row[1] == shape;
            if (row != table.rows[0] && of_shape &&
                stageNumber() >= stageNumber("s" + row[4].substr(0, 1) + "_" + row[4].substr(2, 1))) {
                documented.push_back(keyOf(row));
            }
        }
        std::vector<std::string> declared;
        for (const browser::SceneKey& key : list.add(kind)) {
            const browser::KeyDescription described = browser::describe(key);
            INFO(described.name);
            declared.push_back(described.name);
            const auto row = std::find_if(table.rows.begin(), table.rows.end(),
                                          [&](const auto& cells) { return keyOf(cells) == described.name; });
            REQUIRE(row != table.rows.end());
            CHECK((*row)[2] == described.values);
            CHECK((*row)[3] == (described.required ? "required" : "`" + described.value_now + "`"));
        }
        CHECK(declared == documented);
    }
}

TEST_CASE("scene files: a body's \"bullet\" is read from 5.6 on and refused before, as any unknown key") {
    const test::ScratchFolder folder("scene-bullet");
    folder.write("scene.json",
                 R"({"bodies": [{"shape": "circle", "center": [100, 100], "radius": 5, "bullet": true}]})");
    const test::ProgramRun run = test::runStageProgram(folder, arguments(folder, "scene.json", "--frames 1"));
#if __has_include("continuous.h")
    CHECK(run.status == 0);
#else
    CHECK(run.status == 2);
    CHECK(run.error_text.find("bodies[0].bullet") != std::string::npos);
#endif
}

TEST_CASE("scene files: the program takes each world key the stage reads and refuses every other one") {
    const std::vector<std::string> read = keysThisStageReads();
    // Every key of every stage, each with a value the stages that read it accept: its
    // first default in docs/scene_format.md.
    std::map<std::string, std::string> every_key;
    for (const std::vector<std::string>& row : tableAfter("## Which stage reads which world key").rows) {
        every_key[keyOf(row)] = row.at(2).substr(1, row.at(2).find('`', 1) - 1);
    }
    for (const std::string& name : read) CHECK(every_key.contains(name));
    for (const auto& [name, value] : every_key) {
        const bool reads = std::find(read.begin(), read.end(), name) != read.end();
        INFO(name << (reads ? " (read)" : " (not read)"));
        const test::ScratchFolder folder("scene-key");
        folder.write("scene.json", R"({"world": {")" + name + "\": " + value + "}}");
        const test::ProgramRun run = test::runStageProgram(folder, arguments(folder, "scene.json", "--frames 1"));
        if (reads) {
            CHECK(run.status == 0);
            continue;
        }
        CHECK(run.status == 2);
        CHECK(run.error_text == (folder.path / "scene.json").string() + ": world." + name +
                                    ": unknown key; this stage's world takes " + commaList(read) + "\n");
        CHECK_FALSE(fs::exists(folder.path / "out"));
        CHECK_FALSE(fs::exists(folder.path / "dump.csv"));
    }
}

TEST_CASE("scene files: bodies come in file order, turned, moving, with their attributes") {
    const test::ScratchFolder folder("scene-build");
    const engine::Scene scene = engine::loadScene(folder.write("scene.json", kScene));
    test::WorldFixture page(scene.world);
    engine::buildScene(page.core, scene.bodies);
    REQUIRE(page.core.objectCount() == 3);

    const engine::RigidShape& platform = page.core.object(0);
    CHECK(platform.type() == engine::ShapeType::Rectangle);
    CHECK(platform.isStatic());
    CHECK(platform.friction() == 0.3);
    CHECK(platform.restitution() == 0);
    CHECK(platform.center() == Vec2{500.25, 200.1});
    CHECK(platform.angle() == 2.8);
    // Turned as the book does, with rotate() after construction: the corners too.
    const Vec2 corner = static_cast<const engine::Rectangle&>(platform).vertices()[0];
    const Vec2 unturned{500.25 - 200, 200.1 - 10};
    // 1e-12 px: one turn of coordinates near 500 px rounds by about 1e-13 px.
    CHECK_THAT(corner, test::near(unturned.rotate(platform.center(), 2.8), 1e-12));

    const engine::RigidShape& ball = page.core.object(1);
    CHECK(ball.type() == engine::ShapeType::Circle);
    CHECK(ball.invMass() == 0.2);
    CHECK_THAT(ball.invInertia(), test::near(2.0 / (5 * 20 * 20), 1e-16));  // rounding of a value of 0.001
    CHECK(ball.velocity() == Vec2{10.5, -3.25});
    CHECK(ball.angularVelocity() == -0.7);

    const engine::RigidShape& box = page.core.object(2);
    CHECK(box.mass() == 1);  // the body defaults: mass 1, friction 0.8, restitution 0.2
    CHECK(box.friction() == 0.8);
    CHECK(box.restitution() == 0.2);
}

TEST_CASE("scene files: step 0 of the dump gives back every number of the scene file") {
    const test::ScratchFolder folder("scene-round-trip");
    folder.write("scene.json", kScene);
    const test::ProgramRun run = test::runStageProgram(folder, arguments(folder, "scene.json", "--frames 1 --every 0"));
    INFO(run.error_text);
    REQUIRE(run.status == 0);
    const auto rows = rowsOfStep(test::readDump(folder.path / "dump.csv"), 0);
    REQUIRE(rows.size() == 3);
    struct Expected {
        const char* shape;
        double cx, cy, angle, vx, vy, w;
    };
    const Expected expected[] = {
        {"rectangle", 500.25, 200.1, 2.8, 0, 0, 0},
        {"circle", 100.5, 50.75, 0, 10.5, -3.25, -0.7},
        {"rectangle", 0.001, 449.999, -0.1, 1e-3, 0, 0},
    };
    for (std::size_t i = 0; i < 3; ++i) {
        INFO("body " << i);
        CHECK(rows[i].index == i);
        CHECK(rows[i].shape == expected[i].shape);
        // 17 significant digits read back to the very double the file gave.
        CHECK(rows[i].cx == expected[i].cx);
        CHECK(rows[i].cy == expected[i].cy);
        CHECK(rows[i].angle == expected[i].angle);
        CHECK(rows[i].vx == expected[i].vx);
        CHECK(rows[i].vy == expected[i].vy);
        CHECK(rows[i].angular_velocity == expected[i].w);
    }
}

TEST_CASE("scene files: the scene's world runs the program: gravity, dt, movement, canvas") {
    // gravity 30 px/s^2 and dt 0.01 s: 6 frames of 1000/60 ms are 100 ms, 10 steps;
    // step k puts the ball at y = 100 + dt^2 g k (k + 1) / 2 (symplectic Euler).
    const test::ScratchFolder folder("scene-world");
    folder.write("scene.json", R"({"world": {"gravity": [0, 30], "dt": 0.01, "movement": true,
                                              "width": 300, "height": 200},
                                   "bodies": [{"shape": "circle", "center": [100, 100], "radius": 5}]})");
    const test::ProgramRun run = test::runStageProgram(folder, arguments(folder, "scene.json", "--frames 6 --every 0"));
    INFO(run.error_text);
    REQUIRE(run.status == 0);
    const auto rows = test::readDump(folder.path / "dump.csv");
    REQUIRE(rows.size() == 11);
    for (long k = 0; k <= 10; ++k) {
        INFO("step " << k);
        CHECK(rows[k].step == k);
        // 1e-9: ten steps' rounding near 100 px, read back from 17 digits.
        CHECK_THAT(rows[k].cy, test::near(100 + 0.01 * 0.01 * 30 * k * (k + 1) / 2, 1e-9));
        CHECK_THAT(rows[k].vy, test::near(0.3 * k, 1e-9));
    }
    // The canvas is the scene's, 300 x 200: its frame's last row is row 199. A stage
    // beyond the book may grow the page under it by a band of its own (page.h).
    const browser::Image page = browser::read_png(folder.path / "out" / "final.png");
    CHECK(page.width == 300 + browser::kPanelWidth);
    REQUIRE(page.height >= 200);
    CHECK(page.at(0, 199) == browser::colors::kGray);
    if (page.height > 200) CHECK(page.at(0, 200) == browser::colors::kWhite);
}

namespace {

// A body of the book's scene as step 0 of a dump shows it.
struct StartRow {
    std::string shape;
    double cx, cy, angle;
    Vec2 velocity;
};

// The book's MyGame scene of this stage, written out from the book (and, for the demo,
// its random shapes drawn by hand as the book draws them), not taken from the stage.
std::vector<StartRow> bookSceneAtStepZero() {
    const std::string stage = STAGE_ID;
    const StartRow cursor{"rectangle", 400, 225, 0, {}};
    const std::vector<StartRow> borders{{"rectangle", 400, 0, 0, {}},
                                        {"rectangle", 400, 450, 0, {}},
                                        {"rectangle", 0, 225, 0, {}},
                                        {"rectangle", 800, 225, 0, {}}};
    std::vector<StartRow> rows;
    if (stage == "s4_1" || stage == "s4_2") {
        rows = {cursor};
    } else if (stage == "s4_3") {
        rows = {cursor, {"rectangle", 200, 400, 0, {}}};
    } else if (stage == "s4_4") {
        rows = {cursor, {"rectangle", 500, 200, 3.0, {}}, {"rectangle", 200, 400, 0.785, {}}};
    } else {
        // The cool demo: four platforms, no borders, then the random shapes.
        rows = {{"rectangle", 500, 200, 2.8, {}},
                {"rectangle", 200, 400, 0, {}},
                {"rectangle", 100, 200, 0, {}},
                {"rectangle", 10, 360, 0, {}}};
#if __has_include("contact_events.h")
        // 5.7's demo game (my_game.h): its zone and its goal, two sensors, after the platforms.
        rows.push_back({"rectangle", 200, 360, 0, {}});
        rows.push_back({"rectangle", 620, 425, 0, {}});
#endif
        browser::Random book(browser::Random::kDefaultSeed);  // the program's default seed
        for (const test::DemoShape& shape : test::demoShapesAsTheBookDraws(book)) {
            rows.push_back({shape.is_box ? "rectangle" : "circle", shape.center.x, shape.center.y, 0, shape.velocity});
        }
#if __has_include("polygon.h")
        // 5.8's five polygons, from the numbers after the book's (my_game.cpp): a place in
        // the top half, 3 + 6 r corners, a radius, a start, a number a corner, mass,
        // friction, restitution, then the velocity, each of its two parts in [-30, 30].
        for (int polygon = 0; polygon < 5; ++polygon) {
            const double x = book.next() * 800, y = book.next() * 450 / 2;
            const int corners = 3 + static_cast<int>(book.next() * 6);
            for (int skip = 0; skip < 2 + corners + 3; ++skip) book.next();
            const double vx = book.next() * 60 - 30, vy = book.next() * 60 - 30;
            rows.push_back({"polygon", x, y, 0, {vx, vy}});
        }
#endif
        return rows;
    }
    rows.insert(rows.end(), borders.begin(), borders.end());
    return rows;
}

}  // namespace

TEST_CASE("scene files: without --scene the dump starts from the book's scene") {
    const test::ScratchFolder folder("scene-book");
    const test::ProgramRun run = test::runStageProgram(folder, arguments(folder, "", "--frames 1 --every 0"));
    INFO(run.error_text);
    REQUIRE(run.status == 0);
    const auto rows = rowsOfStep(test::readDump(folder.path / "dump.csv"), 0);
    const std::vector<StartRow> expected = bookSceneAtStepZero();
    REQUIRE(rows.size() == expected.size());
    for (std::size_t i = 0; i < rows.size(); ++i) {
        INFO("body " << i);
        CHECK(rows[i].shape == expected[i].shape);
        CHECK(rows[i].cx == expected[i].cx);
        CHECK(rows[i].cy == expected[i].cy);
        CHECK(rows[i].angle == expected[i].angle);
        CHECK(rows[i].vx == expected[i].velocity.x);
        CHECK(rows[i].vy == expected[i].velocity.y);
        CHECK(rows[i].angular_velocity == 0);
    }
}

TEST_CASE("scene files: a refused scene exits with 2 and one line, and writes nothing") {
    struct Case {
        const char* name;
        const char* text;
        const char* says;
    };
    const Case cases[] = {
        {"not JSON", R"({"bodies": [)", "malformed JSON"},
        {"a typo", R"({"bodies": [{"shape": "circle", "center": [1, 2], "radus": 3}]})", "bodies[0].radus"},
        {"a negative size", R"({"bodies": [{"shape": "circle", "center": [1, 2], "radius": -2}]})", "bodies[0].radius"},
        {"a bad world", R"({"world": {"dt": 0}})", "world.dt"},
    };
    for (const Case& bad : cases) {
        INFO(bad.name);
        const test::ScratchFolder folder("scene-refused");
        folder.write("bad.json", bad.text);
        const test::ProgramRun run = test::runStageProgram(folder, arguments(folder, "bad.json", ""));
        CHECK(run.status == 2);
        CHECK(run.error_text.find("bad.json") != std::string::npos);
        CHECK(run.error_text.find(bad.says) != std::string::npos);
        CHECK(run.error_text.find('\n') == run.error_text.size() - 1);  // exactly one line
        CHECK_FALSE(fs::exists(folder.path / "out"));
        CHECK_FALSE(fs::exists(folder.path / "dump.csv"));
        CHECK_FALSE(fs::exists(folder.path / "dump.csv.partial"));
    }
    const test::ScratchFolder folder("scene-missing");
    const test::ProgramRun run = test::runStageProgram(folder, arguments(folder, "missing.json", ""));
    CHECK(run.status == 2);
    CHECK(run.error_text.find("missing.json") != std::string::npos);
    CHECK_FALSE(fs::exists(folder.path / "out"));
}

TEST_CASE("scene files: a dump that cannot be written stops the run before any picture") {
    const test::ScratchFolder folder("scene-no-dump");
    std::string command = "--frames 1 --keys '' --dump ";
    command.append(test::quoted(folder.path / "no" / "such" / "dump.csv"));
    command.append(" --out ").append(test::quoted(folder.path / "out"));
    const test::ProgramRun run = test::runStageProgram(folder, command);
    CHECK(run.status == 1);
    CHECK(run.error_text.find("dump.csv") != std::string::npos);
    CHECK_FALSE(fs::exists(folder.path / "out"));
}

// ---------------------------------------------------------------------------------------
// Hostile input (issue 15): each way in which a careless or hostile command line once
// crashed, hung, ran without end, printed several lines or replaced a file that was not
// the run's. Every one is now refused with exit status 2 and one line, nothing written.

namespace {

using test::checkRefused;

std::string outIn(const test::ScratchFolder& folder) { return " --out " + test::quoted(folder.path / "out"); }

}  // namespace

TEST_CASE("hostile input: a scene nested 100,000 deep is refused in one line, without a crash") {
    const test::ScratchFolder folder("hostile-deep");
    const std::size_t depth = 100'000;
    folder.write("deep.json", R"({"world": {"gravity": )" + std::string(depth, '[') + std::string(depth, ']') + "}}");
    checkRefused(folder, "--frames 5 --scene " + test::quoted(folder.path / "deep.json") + outIn(folder),
                 "world.gravity[0][0][0]: nested deeper than a scene can use");
}

TEST_CASE("hostile input: a scene that is a FIFO, a device, a folder or a loop of links is refused at once") {
    const test::ScratchFolder folder("hostile-scene");
    REQUIRE(::mkfifo((folder.path / "fifo").c_str(), 0600) == 0);  // no writer: a plain open would wait for ever
    fs::create_symlink(folder.path / "loop2", folder.path / "loop1");
    fs::create_symlink(folder.path / "loop1", folder.path / "loop2");
    const auto scene = [&](const std::string& file) { return "--frames 1 --scene " + file + outIn(folder); };
    checkRefused(folder, scene(test::quoted(folder.path / "fifo")),
                 "fifo: cannot read: it is a FIFO, not a regular file");
    checkRefused(folder, scene("/dev/zero"), "/dev/zero: cannot read: it is a device, not a regular file");
    checkRefused(folder, scene("/dev/urandom"), "/dev/urandom: cannot read: it is a device, not a regular file");
    checkRefused(folder, scene(test::quoted(folder.path)), "cannot read: it is a folder");
    checkRefused(folder, scene(test::quoted(folder.path / "loop1")), "loop1: cannot read: a loop of symbolic links");
    checkRefused(folder, scene("''"), "--scene: must name a file (got \"\")");
}

TEST_CASE("hostile input: a scene whose numbers would make a NaN is refused when it loads") {
    // Each once gave a dump of NaN from step 1: a radius whose inertia underflows to 0,
    // circles meeting at 1e308 px/s, a circle of radius 1e300 onto a rectangle.
    struct Case {
        const char* bodies;
        const char* says;
    };
    const Case cases[] = {
        {R"({"shape": "circle", "center": [100, 100], "radius": 1e-155},
            {"shape": "circle", "center": [100, 100], "radius": 10})",
         "bodies[0].radius: must be a number in [0.01, 1e5] (px) (got 1e-155)"},
        {R"({"shape": "circle", "center": [100, 100], "radius": 10, "velocity": [1e308, 0]},
            {"shape": "circle", "center": [130, 100], "radius": 10, "velocity": [-1e308, 0]})",
         "bodies[0].velocity[0]: must be a number in [-1e6, 1e6] (px/s) (got 1e+308)"},
        {R"({"shape": "circle", "center": [100, 100], "radius": 1e300},
            {"shape": "rectangle", "center": [100, 300], "width": 100, "height": 10, "mass": 0})",
         "bodies[0].radius: must be a number in [0.01, 1e5] (px) (got 1e+300)"},
    };
    for (const Case& bad : cases) {
        const test::ScratchFolder folder("hostile-nan");
        folder.write("scene.json", std::string(R"({"bodies": [)") + bad.bodies + "]}");
        checkRefused(folder, arguments(folder, "scene.json", "--frames 3"), bad.says);
    }
}

TEST_CASE("hostile input: --dump replaces only a regular file, never a link, a FIFO or a device") {
    const test::ScratchFolder folder("hostile-dump");
    std::ofstream(folder.path / "data.csv") << "someone's data\n";
    fs::create_symlink(folder.path / "data.csv", folder.path / "link.csv");
    REQUIRE(::mkfifo((folder.path / "fifo").c_str(), 0600) == 0);
    const auto dump = [&](const std::string& file) { return "--frames 3 --keys '' --dump " + file + outIn(folder); };
    checkRefused(folder, dump(test::quoted(folder.path / "link.csv")), "link.csv: it is a symbolic link");
    CHECK(test::readText(folder.path / "data.csv") == "someone's data\n");
    checkRefused(folder, dump(test::quoted(folder.path / "fifo")), "fifo: it is a FIFO");
    // Only ever named to be refused: a test that failed must not replace /dev/null.
    checkRefused(folder, dump("/dev/null"), "/dev/null: it is a device");
    CHECK(fs::is_character_file("/dev/null"));
    // A device node of the test's own, where the system lets a test make one (root).
    if (::mknod((folder.path / "null").c_str(), S_IFCHR | 0600, makedev(1, 3)) == 0) {
        checkRefused(folder, dump(test::quoted(folder.path / "null")), "null: it is a device");
        CHECK(fs::is_character_file(folder.path / "null"));
    }
    checkRefused(folder, dump("''"), "--dump: must name a file (got \"\")");
}

TEST_CASE("hostile input: --dump inside the --out folder is written there, run after run") {
    const test::ScratchFolder folder("hostile-dump-in-out");
    const std::string command = "--frames 2 --every 0 --no-gif --keys '' --dump " +
                                test::quoted(folder.path / "out" / "dump.csv") + outIn(folder);
    for (int run_number = 1; run_number <= 2; ++run_number) {  // the second replaces the first's folder
        INFO("run " << run_number);
        const test::ProgramRun run = test::runStageProgram(folder, command);
        INFO(run.error_text);
        CHECK(run.status == 0);
        CHECK(run.error_text.empty());
        CHECK(test::readDump(folder.path / "out" / "dump.csv").size() >= 2);
        CHECK(fs::exists(folder.path / "out" / "final.png"));
        CHECK(folder.files() == std::vector<std::string>{"out", "stderr.txt", "stdout.txt"});
    }
}

TEST_CASE("hostile input: every run is bounded: shapes, presses, pictures and the work of the whole run") {
    const test::ScratchFolder folder("hostile-bounds");
    std::string many = R"({"bodies": [)";
    for (int i = 0; i <= 2500; ++i)
        many.append(i == 0 ? "" : ",").append(R"({"shape": "circle", "center": [400, 200], "radius": 5})");
    folder.write("many.json", many + "]}");
    checkRefused(folder, arguments(folder, "many.json", "--frames 1"), "bodies: more than 2500 bodies (got 2501)");
    checkRefused(folder, "--frames 1 --keys 'f*2000 g'" + outIn(folder), "more than 2000 keys in all");
    checkRefused(folder, "--frames 10000000 --every 1" + outIn(folder), "--every: 10000000 frames would save");
    // 2,000 shapes made at one point: 3,000 frames may cost 6e9 pair tests with one
    // pass a step (4.1), 9e10 with the book's 15.
    checkRefused(folder, "--frames 3000 --every 0 --no-gif --keys 'f*2000'" + outIn(folder),
                 "the run is too long: 3000 frames");
    checkRefused(folder, "--frames 10000000 --every 0 --no-gif --keys ''" + outIn(folder),
                 "the run is too long: 10000000 frames");
}

TEST_CASE("hostile input: what the reader typed is quoted escaped, so every refusal is one line") {
    const test::ScratchFolder folder("hostile-lines");
    // printf makes the line break: the shell that runs the program (dash) has no $'\n'.
    checkRefused(folder, R"x(--frames "$(printf '1\n2')")x" + outIn(folder),
                 R"(--frames: must be a whole number from 1 to 10000000 (got "1\n2"))");
    checkRefused(folder, R"x(--seed "$(printf '7\r')")x" + outIn(folder), R"((got "7\r"))");
    checkRefused(folder, R"x("$(printf -- '--bo\ngus')")x" + outIn(folder), R"(unknown option "--bo\ngus")");
    folder.write("bad.json", "{\"bodies\": [{\"shape\": \"circ\xff\x1b[31m\"}]}");
    checkRefused(folder, arguments(folder, "bad.json", "--frames 1"), "malformed JSON");
    const test::ProgramRun run = test::runStageProgram(folder, arguments(folder, "bad.json", "--frames 1"));
    CHECK(run.error_text.find('\x1b') == std::string::npos);
    CHECK(run.error_text.find('\xff') == std::string::npos);
}

TEST_CASE("hostile input: --out problems are refusals too: status 2, one line") {
    const test::ScratchFolder folder("hostile-out");
    fs::create_directories(folder.path / "thesis");
    std::ofstream(folder.path / "thesis" / "chapter1.txt") << "years of work\n";
    checkRefused(folder, "--frames 1 --out " + test::quoted(folder.path / "thesis"),
                 "it holds \"chapter1.txt\", which no run wrote");
    std::ofstream(folder.path / "file") << "x";
    checkRefused(folder, "--frames 1 --out " + test::quoted(folder.path / "file"), "it exists and is not a folder");
    checkRefused(folder, "--frames 1 --out " + test::quoted(folder.path / "file" / "out"), "cannot write pictures to");
}

TEST_CASE("hostile input: SIGINT and SIGTERM end a run with no staging folder or partial dump left") {
    for (const int signal : {SIGINT, SIGTERM}) {
        INFO("signal " << signal);
        const test::ScratchFolder folder("hostile-signal");
        // A long run (half a minute; within the run's budget with 5.8's 31 shapes):
        // stopped as soon as its staging folder shows.
        const pid_t pid = test::startStageProgram(folder, "--frames 40000 --every 0 --no-gif --keys '' --dump " +
                                                              test::quoted(folder.path / "dump.csv") + outIn(folder));
        REQUIRE(pid > 0);
        const fs::path staging = folder.path / ("out.partial-" + std::to_string(pid));
        for (int wait = 0; wait < 1000 && !fs::exists(staging); ++wait) {
            std::this_thread::sleep_for(std::chrono::milliseconds(10));
        }
        CHECK(fs::exists(staging));
        CHECK(fs::exists(folder.path / ("dump.csv.partial-" + std::to_string(pid))));
        ::kill(pid, signal);
        int status = 0;
        REQUIRE(::waitpid(pid, &status, 0) == pid);
        // Ended by the signal itself, as an interrupted program should be (a shell shows 128 + it).
        CHECK(WIFSIGNALED(status));
        CHECK((WIFSIGNALED(status) ? WTERMSIG(status) : -1) == signal);
        CHECK(folder.files() == std::vector<std::string>{"stderr.txt", "stdout.txt"});
    }
}

TEST_CASE("hostile input: leftovers of a run that was killed outright are removed by the next run") {
    const test::ScratchFolder folder("hostile-stale");
    const std::string gone = "4194305";  // one past the largest process id Linux hands out: no process
    fs::create_directories(folder.path / ("out.partial-" + gone));
    std::ofstream(folder.path / ("dump.csv.partial-" + gone)) << "half a dump";
    const test::ProgramRun run = test::runStageProgram(folder, arguments(folder, "", "--frames 1 --every 0 --no-gif"));
    INFO(run.error_text);
    CHECK(run.status == 0);
    CHECK(folder.files() == std::vector<std::string>{"dump.csv", "out", "stderr.txt", "stdout.txt"});
}

TEST_CASE("hostile input: a step that leaves a number no double can be is named, body and step") {
    test::WorldFixture page(engine::kBookWorld);
    engine::RigidShape& ball = page.core.add(engine::Circle({100, 100}, 10, {.mass = 1}));
    page.core.add(engine::Rectangle({100, 300}, 200, 20, {.mass = 0}));
    CHECK_NOTHROW(browser::check_finite(engine::pageWorld(page.core)));
    ball.setVelocity({std::numeric_limits<double>::quiet_NaN(), 0});
    page.steps(1);
    try {
        browser::check_finite(engine::pageWorld(page.core));
        FAIL("check_finite let a NaN through");
    } catch (const browser::NonFiniteState& error) {
        CHECK(std::string(error.what())
                  .rfind("step 1: body 0 (circle) has a position or velocity that is not a finite number", 0) == 0);
    }
}

TEST_CASE("hostile input: at every corner of the ranges a moving body's inverse mass and inertia are finite and > 0") {
    // The ranges of docs/scene_format.md: masses [1e-3, 1e6], sizes [0.01, 1e5] px. The
    // extreme inertias are m r^2 / 2 = 5e-8 and m (w^2 + h^2) / 12 = 1.7e15 or so.
    std::vector<engine::BodyDescription> bodies;
    for (const double mass : {1e-3, 1e6}) {
        for (const double size : {0.01, 1e5}) {
            bodies.push_back({.shape = engine::ShapeType::Circle, .radius = size, .mass = mass});
            bodies.push_back({.shape = engine::ShapeType::Rectangle, .width = size, .height = size, .mass = mass});
            bodies.push_back({.shape = engine::ShapeType::Rectangle, .width = 0.01, .height = 1e5, .mass = mass});
        }
    }
    test::WorldFixture page(engine::kBookWorld);
    engine::buildScene(page.core, bodies);
    REQUIRE(page.core.objectCount() == bodies.size());
    for (std::size_t i = 0; i < bodies.size(); ++i) {
        INFO("body " << i);
        const engine::RigidShape& shape = page.core.object(i);
        CHECK(std::isfinite(shape.invMass()));
        CHECK(shape.invMass() > 0);
        CHECK(std::isfinite(shape.invInertia()));
        CHECK(shape.invInertia() > 0);
        CHECK(std::isfinite(1 / shape.invInertia()));  // the inertia itself
    }
}

}  // namespace scene_files_test
