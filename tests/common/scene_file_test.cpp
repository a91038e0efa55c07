// Scene files: a good scene loads with exactly its numbers and every default filled in;
// a bad one is refused with one line naming the file, the JSON path and the problem.

#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <sys/stat.h>
#include <unistd.h>
#include <vector>

#include "message_text.h"
#include "scene_file.h"
#include "scratch_folder.h"

namespace fs = std::filesystem;
using browser::SceneError;
using browser::SceneKey;
using lib::Vec2;

namespace {

using test::ScratchFolder;

// A stage's vocabulary, as a stage writes it in its scene_io.cpp: the book's settings
// and, like the stages beyond the book, a count and a word from a list, so every kind of
// SceneKey is read; bodies of two shapes, each with its own size keys.
constexpr browser::NumberRule kTimeStep{[](double v) { return v >= 1e-5 && v <= 1.0; },
                                        "must be a number in [1e-5, 1]"};
constexpr browser::NumberRule kPassCount{[](double v) { return v >= 0.0 && v <= 1000.0 && std::floor(v) == v; },
                                         "must be a whole number in [0, 1000]"};
constexpr browser::NumberRule kPosition{[](double v) { return v >= -1e6 && v <= 1e6; },
                                        "must be a number in [-1e6, 1e6] (px)"};
constexpr browser::NumberRule kSize{[](double v) { return v >= 0.01 && v <= 1e5; },
                                    "must be a number in [0.01, 1e5] (px)"};
constexpr browser::NumberRule kMass{[](double v) { return v == 0.0 || (v >= 1e-3 && v <= 1e6); },
                                    "must be 0 (static) or a number in [1e-3, 1e6]"};
constexpr browser::NumberRule kFriction{[](double v) { return v >= 0.0 && v <= 100.0; },
                                        "must be a number in [0, 100]"};
constexpr browser::NumberRule kAngle{[](double v) { return v >= -1e6 && v <= 1e6; },
                                     "must be a number in [-1e6, 1e6] (rad)"};
constexpr browser::NumberRule kSpeed{[](double v) { return v >= -1e6 && v <= 1e6; },
                                     "must be a number in [-1e6, 1e6] (px/s)"};
constexpr browser::NumberRule kTurnRate{[](double v) { return v >= -1e4 && v <= 1e4; },
                                        "must be a number in [-1e4, 1e4] (rad/s)"};
constexpr std::size_t kMaxBodies = 2500;

enum class Method { plain, fancy };
struct WorldSettings {
    double width = 800.0;
    double height = 450.0;
    Vec2 gravity{0.0, 10.0};
    double dt = 1.0 / 60.0;
    int relaxation_iterations = 15;
    double correction_rate = 0.8;
    bool movement = false;
    bool positional_correction = true;
    bool remove_out_of_bounds = false;
    Method method = Method::plain;
    friend bool operator==(const WorldSettings&, const WorldSettings&) = default;
};

std::vector<SceneKey> worldKeys(WorldSettings& world) {
    namespace rules = browser::rules;
    return {
        {"width", world.width, rules::kCanvasSize},
        {"height", world.height, rules::kCanvasSize},
        {"gravity", world.gravity},
        {"dt", world.dt, kTimeStep},
        {"relaxation_iterations", world.relaxation_iterations, kPassCount},
        {"correction_rate", world.correction_rate, rules::kFraction},
        {"movement", world.movement},
        {"positional_correction", world.positional_correction},
        {"remove_out_of_bounds", world.remove_out_of_bounds},
        {"method", world.method, {{"plain", Method::plain}, {"fancy", Method::fancy}}},
    };
}

enum class ShapeKind { rectangle, circle };
struct BodyDescription {
    ShapeKind shape = ShapeKind::rectangle;
    Vec2 center;
    double width = 0.0;
    double height = 0.0;
    double radius = 0.0;
    double mass = 1.0;
    double friction = 0.8;
    double restitution = 0.2;
    double angle = 0.0;
    Vec2 velocity;
    double angular_velocity = 0.0;
    friend bool operator==(const BodyDescription&, const BodyDescription&) = default;
};

std::vector<SceneKey> bodyKeys(BodyDescription& body) {
    using browser::kRequired;
    std::vector<SceneKey> keys{{"center", body.center, kPosition, kRequired}};
    if (body.shape == ShapeKind::rectangle) {
        keys.push_back({"width", body.width, kSize, kRequired});
        keys.push_back({"height", body.height, kSize, kRequired});
    } else {
        keys.push_back({"radius", body.radius, kSize, kRequired});
    }
    keys.insert(keys.end(), {{"mass", body.mass, kMass},
                             {"friction", body.friction, kFriction},
                             {"restitution", body.restitution, browser::rules::kFraction},
                             {"angle", body.angle, kAngle},
                             {"velocity", body.velocity, kSpeed},
                             {"angular_velocity", body.angular_velocity, kTurnRate}});
    return keys;
}

// The "bodies" list, its elements going into `bodies`.
browser::SceneList bodyList(std::vector<BodyDescription>& bodies) {
    return {.name = "bodies",
            .element = "body",
            .kind_key = "shape",
            .kinds = {"rectangle", "circle"},
            .most = kMaxBodies,
            .why_most = "every step tests every pair of them",
            .add = [&bodies](std::size_t kind) {
                BodyDescription& body = bodies.emplace_back();
                body.shape = kind == 0 ? ShapeKind::rectangle : ShapeKind::circle;
                return bodyKeys(body);
            }};
}

// 5.1's defaults differ from WorldSettings{} in gravity, movement and out-of-bounds
// removal, so a test can tell a value taken from `defaults` from a member default.
const WorldSettings kDemoDefaults{.gravity = {0.0, 20.0}, .movement = true, .remove_out_of_bounds = true};

struct Scene {
    WorldSettings world;
    std::vector<BodyDescription> bodies;
};

// The scene in `file`, its world keys read into `defaults` as a stage reads them.
Scene load_scene(const fs::path& file, const WorldSettings& defaults) {
    Scene scene{defaults, {}};
    const browser::SceneList bodies = bodyList(scene.bodies);
    browser::load_scene(file, worldKeys(scene.world), {&bodies, 1});
    return scene;
}

// The message load_scene refuses `file` with ("" when it loads).
std::string refusal(const fs::path& file) {
    try {
        load_scene(file, kDemoDefaults);
    } catch (const SceneError& error) {
        return error.what();
    }
    return "";
}

}  // namespace

TEST_CASE("scene_file: the example scene loads with exactly its numbers") {
    ScratchFolder folder("example");
    const fs::path file = folder.write("scene.json", R"({
  "world": {
    "width": 800, "height": 450,
    "gravity": [0, 20],
    "dt": 0.016666666666666666,
    "relaxation_iterations": 15,
    "correction_rate": 0.8,
    "movement": true,
    "positional_correction": true,
    "remove_out_of_bounds": false
  },
  "bodies": [
    {"shape": "rectangle", "center": [500, 200], "width": 400, "height": 20,
     "mass": 0, "friction": 0.3, "restitution": 0, "angle": 2.8},
    {"shape": "circle", "center": [100, 50], "radius": 20,
     "mass": 5, "friction": 0.5, "restitution": 0.4,
     "velocity": [10, 0], "angular_velocity": 0}
  ]
})");
    // The chapter 4 defaults, so that every world value below must come from the file.
    const auto scene = load_scene(file, WorldSettings{});

    // The fields as the file above gives them, which the layout would put one a line:
    // clang-format off
    CHECK(scene.world == WorldSettings{.width = 800, .height = 450, .gravity = {0, 20}, .dt = 0.016666666666666666,
                                       .relaxation_iterations = 15, .correction_rate = 0.8, .movement = true,
                                       .positional_correction = true, .remove_out_of_bounds = false});
    CHECK(scene.world.dt == 1.0 / 60.0);
    REQUIRE(scene.bodies.size() == 2);
    CHECK(scene.bodies[0] == BodyDescription{.shape = ShapeKind::rectangle, .center = {500, 200}, .width = 400,
                                             .height = 20, .mass = 0, .friction = 0.3, .restitution = 0,
                                             .angle = 2.8});
    CHECK(scene.bodies[1] == BodyDescription{.shape = ShapeKind::circle, .center = {100, 50}, .radius = 20,
                                             .mass = 5, .friction = 0.5, .restitution = 0.4, .velocity = {10, 0},
                                             .angular_velocity = 0});
    // clang-format on
}

TEST_CASE("scene_file: a minimal scene takes every default") {
    ScratchFolder folder("minimal");
    for (const std::string text : {"{}", R"({"bodies": []})", R"({"world": {}, "bodies": []})"}) {
        INFO(text);
        const auto scene = load_scene(folder.write("scene.json", text), kDemoDefaults);
        CHECK(scene.world == kDemoDefaults);
        CHECK(scene.bodies.empty());
    }
}

TEST_CASE("scene_file: world keys left out come from the stage's defaults, one by one") {
    ScratchFolder folder("partial_world");
    const auto scene = load_scene(folder.write("scene.json", R"({"world": {"gravity": [1.5, -2], "movement": false}})"),
                                  kDemoDefaults);
    WorldSettings expected = kDemoDefaults;
    expected.gravity = {1.5, -2};
    expected.movement = false;
    CHECK(scene.world == expected);
}

TEST_CASE("scene_file: body keys left out take the book's body defaults") {
    ScratchFolder folder("body_defaults");
    const auto scene = load_scene(folder.write("scene.json", R"({"bodies": [
        {"shape": "rectangle", "center": [1, 2], "width": 3, "height": 4},
        {"shape": "circle", "center": [5, 6], "radius": 7}]})"),
                                  kDemoDefaults);
    REQUIRE(scene.bodies.size() == 2);
    for (const BodyDescription& body : scene.bodies) {
        CHECK(body.mass == 1.0);
        CHECK(body.friction == 0.8);
        CHECK(body.restitution == 0.2);
        CHECK(body.angle == 0.0);
        CHECK(body.velocity == Vec2{0, 0});
        CHECK(body.angular_velocity == 0.0);
    }
    CHECK(scene.bodies[0].width == 3.0);
    CHECK(scene.bodies[0].height == 4.0);
    CHECK(scene.bodies[1].radius == 7.0);
}

TEST_CASE("scene_file: bodies keep the file's order") {
    ScratchFolder folder("order");
    const auto scene = load_scene(folder.write("scene.json", R"({"bodies": [
        {"shape": "circle", "center": [3, 0], "radius": 1},
        {"shape": "rectangle", "center": [1, 0], "width": 1, "height": 1},
        {"shape": "circle", "center": [2, 0], "radius": 1}]})"),
                                  kDemoDefaults);
    REQUIRE(scene.bodies.size() == 3);
    CHECK(scene.bodies[0].center.x == 3.0);
    CHECK(scene.bodies[1].center.x == 1.0);
    CHECK(scene.bodies[1].shape == ShapeKind::rectangle);
    CHECK(scene.bodies[2].center.x == 2.0);
}

TEST_CASE("scene_file: edge values that are allowed load") {
    ScratchFolder folder("edges");
    const auto scene = load_scene(folder.write("scene.json", R"({
        "world": {"relaxation_iterations": 0, "correction_rate": 1, "gravity": [-1e300, 0]},
        "bodies": [{"shape": "circle", "center": [-1e6, 1e6], "radius": 0.01,
                    "mass": 0, "friction": 0, "restitution": 1, "angle": -1e6},
                   {"shape": "rectangle", "center": [0, 0], "width": 1e5, "height": 0.01, "mass": 1e-3,
                    "friction": 100, "angle": 1e6, "velocity": [-1e6, 1e6], "angular_velocity": -1e4},
                   {"shape": "circle", "center": [0, 0], "radius": 1e5, "mass": 1e6, "angular_velocity": 1e4}]})"),
                                  kDemoDefaults);
    CHECK(scene.world.relaxation_iterations == 0);
    CHECK(scene.world.correction_rate == 1.0);
    CHECK(scene.world.gravity.x == -1e300);  // this test's own world key takes any finite number
    CHECK(scene.bodies.at(0).radius == 0.01);
    CHECK(scene.bodies.at(0).restitution == 1.0);
    CHECK(scene.bodies.at(1).mass == 1e-3);
    CHECK(scene.bodies.at(1).velocity == Vec2{-1e6, 1e6});
    CHECK(scene.bodies.at(2).radius == 1e5);
    CHECK(scene.bodies.at(2).mass == 1e6);

    // JSON does not tell 15 from 15.0; neither does a count.
    CHECK(load_scene(folder.write("float.json", R"({"world": {"relaxation_iterations": 15.0}})"), kDemoDefaults)
              .world.relaxation_iterations == 15);
}

TEST_CASE("scene_file: the format's own example of a refusal, word for word") {
    ScratchFolder folder("headline");
    const fs::path file = folder.write("scene.json", R"({"bodies": [
        {"shape": "circle", "center": [0, 0], "radius": 1},
        {"shape": "circle", "center": [0, 0], "radius": 1},
        {"shape": "circle", "center": [0, 0], "radius": 1},
        {"shape": "circle", "center": [0, 0], "radius": -2}]})");
    CHECK(refusal(file) == file.string() + ": bodies[3].radius: must be a number in [0.01, 1e5] (px) (got -2)");
}

TEST_CASE("scene_file: a file that cannot be read is refused") {
    ScratchFolder folder("unreadable");
    CHECK(refusal(folder.path / "missing.json") ==
          (folder.path / "missing.json").string() + ": cannot read: no such file");
    CHECK(refusal(folder.path) == folder.path.string() + ": cannot read: it is a folder");
}

TEST_CASE("scene_file: malformed JSON is refused with line and column") {
    ScratchFolder folder("malformed");
    struct Case {
        std::string text;
        std::string where;
    };
    const std::vector<Case> cases{
        {"{\n  \"bodies\": [\n    {\"shape\": \"circle\",}\n  ]\n}", "line 3, column 24"},  // trailing comma
        {"{\"world\": {}} x", "line 1, column 15"},                                         // text after the end
        {"{\n  \"world\": {\n", "line 3, column 1"},                                        // cut short
        {"", "line 1, column 1"},                                                           // empty file
        {"{\"é\": tru}", "line 1, column 10"},  // a column counts characters, not UTF-8 bytes
    };
    for (const Case& c : cases) {
        INFO(c.text);
        const fs::path file = folder.write("scene.json", c.text);
        const std::string message = refusal(file);
        CHECK(message.rfind(file.string() + ": " + c.where + ": malformed JSON: ", 0) == 0);
        CHECK(message.find('\n') == std::string::npos);
    }
}

TEST_CASE("scene_file: every kind of bad value is refused with its path and problem") {
    ScratchFolder folder("bad_values");
    struct Case {
        std::string text;
        std::string expected;  // the message after "<file>: "; only its beginning for long ones
    };
    const std::string rectangle = R"("shape": "rectangle", "center": [0, 0], "width": 1, "height": 1)";
    const std::string circle = R"("shape": "circle", "center": [0, 0], "radius": 1)";
    const auto body = [](const std::string& keys) { return R"({"bodies": [{)" + keys + "}]}"; };
    const auto world = [](const std::string& keys) { return R"({"world": {)" + keys + "}}"; };
    const std::vector<Case> cases{
        // The shape of the document.
        {"[]", "top level: must be an object {...} (got [])"},
        {"3", "top level: must be an object {...} (got 3)"},
        {R"({"world": [800, 450]})", "world: must be an object {...} (got [800,450])"},
        {R"({"bodies": {}})", "bodies: must be an array [...] of bodies (got {})"},
        {R"({"bodies": [3]})", "bodies[0]: must be an object {...} (got 3)"},
        // Unknown keys, everywhere, and keys of the other shape.
        {R"({"bodys": []})", "bodys: unknown key; a scene takes world, bodies"},
        {world(R"("gravty": [0, 1])"),
         "world.gravty: unknown key; this stage's world takes width, height, gravity, dt, "},
        {body(circle + R"(, "raduis": 2)"),
         "bodies[0].raduis: unknown key; a circle body takes shape, center, "
         "radius, mass, friction, restitution, angle, velocity, angular_velocity"},
        {body(rectangle + R"(, "radius": 2)"),
         "bodies[0].radius: unknown key; a rectangle body takes shape, center, "
         "width, height, mass, "},
        {body(circle + R"(, "width": 2)"), "bodies[0].width: unknown key; a circle body takes "},
        // Missing keys and unknown shapes.
        {body(R"("center": [0, 0], "radius": 1)"), R"(bodies[0].shape: missing; every body needs "shape": )"},
        {body(R"("shape": "circle", "radius": 1)"),
         "bodies[0].center: missing; a circle body needs shape, center, radius"},
        {body(R"("shape": "circle", "center": [0, 0])"), "bodies[0].radius: missing; a circle body needs "},
        {body(R"("shape": "rectangle", "center": [0, 0], "height": 1)"),
         "bodies[0].width: missing; a rectangle body needs shape, center, width, height"},
        {body(R"("shape": "triangle", "center": [0, 0])"),
         R"(bodies[0].shape: must be "rectangle" or "circle" (got "triangle"))"},
        {body(R"("shape": 3)"), R"(bodies[0].shape: must be "rectangle" or "circle" (got 3))"},
        // Wrong types.
        {body(circle + R"(, "mass": "5")"),
         R"(bodies[0].mass: must be 0 (static) or a number in [1e-3, 1e6] (got "5"))"},
        {world(R"("movement": 1)"), "world.movement: must be true or false (got 1)"},
        {world(R"("positional_correction": "yes")"),
         R"(world.positional_correction: must be true or false (got "yes"))"},
        {world(R"("gravity": [0])"), "world.gravity: must be an array of two numbers [x, y] (got [0])"},
        {world(R"("gravity": [0, 1, 2])"), "world.gravity: must be an array of two numbers [x, y] (got [0,1,2])"},
        {world(R"("gravity": {"x": 0, "y": 1})"), "world.gravity: must be an array of two numbers [x, y] (got {"},
        {world(R"("gravity": [0, "down"])"), R"(world.gravity[1]: must be a finite number (got "down"))"},
        {body(circle + R"(, "velocity": [null, 0])"),
         "bodies[0].velocity[0]: must be a number in [-1e6, 1e6] (px/s) (got null)"},
        {world(R"("dt": true)"), "world.dt: must be a number in [1e-5, 1] (got true)"},
        // Numbers too large for a double; JSON has no way to write NaN or Infinity at all.
        {world(R"("gravity": [0, 1e999])"), "world.gravity[1]: must be a finite number (got 1e999)"},
        {body(R"("shape": "circle", "center": [0, 0], "radius": -1e999)"),
         "bodies[0].radius: must be a finite number (got -1e999)"},
        {world(R"("dt": 1)" + std::string(400, '0')),
         "world.dt: must be a finite number (got 1000000000000000000000000000000000000...)"},
        // Out of range.
        {body(R"("shape": "rectangle", "center": [0, 0], "width": 0, "height": 1)"),
         "bodies[0].width: must be a number in [0.01, 1e5] (px) (got 0)"},
        {body(R"("shape": "rectangle", "center": [0, 0], "width": 1, "height": -1.5)"),
         "bodies[0].height: must be a number in [0.01, 1e5] (px) (got -1.5)"},
        {body(R"("shape": "circle", "center": [0, 0], "radius": 0)"),
         "bodies[0].radius: must be a number in [0.01, 1e5] (px) (got 0)"},
        {body(circle + R"(, "mass": -1)"), "bodies[0].mass: must be 0 (static) or a number in [1e-3, 1e6] (got -1)"},
        {body(circle + R"(, "friction": -0.1)"), "bodies[0].friction: must be a number in [0, 100] (got -0.1)"},
        // Numbers whose derived quantities no double holds, or that the engine was never
        // shown to survive (issue 15): each refused before anything is built.
        {body(R"("shape": "circle", "center": [0, 0], "radius": 1e-155)"),
         "bodies[0].radius: must be a number in [0.01, 1e5] (px) (got 1e-155)"},
        {body(R"("shape": "circle", "center": [0, 0], "radius": 1e300)"),
         "bodies[0].radius: must be a number in [0.01, 1e5] (px) (got 1e+300)"},
        {body(circle + R"(, "mass": 1e-320)"),
         "bodies[0].mass: must be 0 (static) or a number in [1e-3, 1e6] (got 1e-320)"},
        {body(circle + R"(, "mass": 1e7)"),
         "bodies[0].mass: must be 0 (static) or a number in [1e-3, 1e6] (got 10000000.0)"},
        {body(circle + R"(, "velocity": [1e308, 0])"),
         "bodies[0].velocity[0]: must be a number in [-1e6, 1e6] (px/s) (got 1e+308)"},
        {body(circle + R"(, "angular_velocity": -1e5)"),
         "bodies[0].angular_velocity: must be a number in [-1e4, 1e4] (rad/s) (got -100000.0)"},
        {body(R"("shape": "circle", "center": [2e6, 0], "radius": 1)"),
         "bodies[0].center[0]: must be a number in [-1e6, 1e6] (px) (got 2000000.0)"},
        {body(circle + R"(, "angle": 1e7)"), "bodies[0].angle: must be a number in [-1e6, 1e6] (rad) (got 10000000.0)"},
        {body(circle + R"(, "friction": 101)"), "bodies[0].friction: must be a number in [0, 100] (got 101)"},
        {body(circle + R"(, "restitution": -0.1)"),
         "bodies[0].restitution: must be a finite number in [0, 1] (got -0.1)"},
        {body(circle + R"(, "restitution": 1.5)"),
         "bodies[0].restitution: must be a finite number in [0, 1] (got 1.5)"},
        {world(R"("dt": 0)"), "world.dt: must be a number in [1e-5, 1] (got 0)"},
        {world(R"("dt": -0.016)"), "world.dt: must be a number in [1e-5, 1] (got -0.016)"},
        {world(R"("relaxation_iterations": -1)"),
         "world.relaxation_iterations: must be a whole number in [0, 1000] (got -1)"},
        {world(R"("relaxation_iterations": 2.5)"),
         "world.relaxation_iterations: must be a whole number in [0, 1000] (got 2.5)"},
        {world(R"("relaxation_iterations": 1001)"),
         "world.relaxation_iterations: must be a whole number in [0, 1000] (got 1001)"},
        // Past what a run can afford: a huge canvas, a step too small to ever finish.
        {world(R"("dt": 1e-6)"), "world.dt: must be a number in [1e-5, 1] (got 1e-06)"},
        {world(R"("dt": 2)"), "world.dt: must be a number in [1e-5, 1] (got 2)"},
        {world(R"("width": 5000)"), "world.width: must be a number in (0, 4096] (got 5000)"},
        {world(R"("correction_rate": -0.2)"), "world.correction_rate: must be a finite number in [0, 1] (got -0.2)"},
        {world(R"("correction_rate": 1.01)"), "world.correction_rate: must be a finite number in [0, 1] (got 1.01)"},
        {world(R"("width": 0)"), "world.width: must be a number in (0, 4096] (got 0)"},
        {world(R"("height": -450)"), "world.height: must be a number in (0, 4096] (got -450)"},
        // A key given twice: one of the two would be dropped without a word.
        {body(circle + R"(, "mass": 1, "mass": 2)"), "bodies[0].mass: this key appears twice in the same object"},
    };
    for (const Case& c : cases) {
        INFO(c.text);
        const fs::path file = folder.write("scene.json", c.text);
        const std::string message = refusal(file);
        CHECK(message.rfind(file.string() + ": " + c.expected, 0) == 0);
        CHECK(message.find('\n') == std::string::npos);
    }
}

TEST_CASE("scene_file: messages stay one short line whatever the file holds") {
    ScratchFolder folder("one_line");
    // A key with a line break in it, quoted in the path.
    const fs::path strange_key = folder.write("key.json", R"({"world": {"a\nb": 1}})");
    CHECK(refusal(strange_key) == strange_key.string() + R"(: world["a\nb"]: unknown key; this stage's world takes )"
                                                         "width, height, gravity, dt, relaxation_iterations, "
                                                         "correction_rate, movement, positional_correction, "
                                                         "remove_out_of_bounds, method");
    // A long value, cut short.
    const fs::path long_value =
        folder.write("long.json", std::string(R"({"bodies": ")").append(500, 'x').append("\"}"));
    const std::string message = refusal(long_value);
    CHECK(message.find('\n') == std::string::npos);
    CHECK(message.size() < long_value.string().size() + 100);
    CHECK(message.find("...)") != std::string::npos);
}

TEST_CASE("scene_file: a file that is not a regular file is refused without reading it") {
    ScratchFolder folder("not_regular");
    // A FIFO with no writer would block a plain open for ever; /dev/zero never ends.
    const fs::path fifo = folder.path / "fifo.json";
    REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
    CHECK(refusal(fifo) == fifo.string() + ": cannot read: it is a FIFO, not a regular file");
    CHECK(refusal("/dev/zero") == "/dev/zero: cannot read: it is a device, not a regular file");
    // A loop of symbolic links is not a missing file.
    const fs::path loop = folder.path / "a.json";
    fs::create_symlink(folder.path / "b.json", loop);
    fs::create_symlink(loop, folder.path / "b.json");
    CHECK(refusal(loop) == loop.string() + ": cannot read: a loop of symbolic links");
    // A link to a good scene is read as the scene.
    fs::create_symlink(folder.write("good.json", "{}"), folder.path / "link.json");
    CHECK(refusal(folder.path / "link.json").empty());
}

TEST_CASE("scene_file: a file longer than a scene may be is refused, its length stated") {
    ScratchFolder folder("too_long");
    // Spaces are valid JSON around {}: only the length is wrong.
    const fs::path file = folder.write("big.json", std::string("{}").append(browser::kMaxSceneBytes - 1, ' '));
    CHECK(refusal(file) == file.string() + ": cannot read: longer than 2097152 bytes, the most a scene file may hold");
    const fs::path just = folder.write("just.json", std::string("{}").append(browser::kMaxSceneBytes - 2, ' '));
    CHECK(refusal(just).empty());
}

TEST_CASE("scene_file: nesting deeper than a scene can use is refused at the first level too many") {
    ScratchFolder folder("deep");
    // Deep enough to overflow the stack of any reader that recurses (issue 15: 100,000).
    const std::size_t depth = 100'000;
    const fs::path file = folder.write(
        "deep.json", std::string(R"({"world": {"gravity": )").append(depth, '[').append(depth, ']').append("}}"));
    CHECK(refusal(file) == file.string() + R"(: world.gravity[0][0][0]: nested deeper than a scene can use (5 levels: )"
                                           R"({"list": [{"key": [[x, y]]}]}))");
    // Five levels, as deep as a scene goes, are read (and refused for what they hold).
    const fs::path five = folder.write("five.json", R"({"world": {"gravity": [[[1]], 2]}})");
    CHECK(refusal(five) == five.string() + ": world.gravity[0]: must be a finite number (got [[1]])");
}

TEST_CASE("scene_file: a NUL byte is refused where it stands; the text after it is not ignored") {
    ScratchFolder folder("nul");
    const fs::path file = folder.write("nul.json", std::string("{\"bodies\": []}\n") + '\0' + "{\"bodies\": 5}");
    CHECK(refusal(file) == file.string() + ": line 2, column 1: a NUL byte, which a scene file never holds");
}

TEST_CASE("scene_file: a key a megabyte long is shown quoted and cut, and the parser's phrase is cut at a word") {
    ScratchFolder folder("long_key");
    const fs::path key = folder.write("key.json", std::string("{\"").append(1'000'000, 'k').append("\": 1}"));
    CHECK(refusal(key) ==
          key.string() + ": [\"" + std::string(20, 'k') + "...\"]: unknown key; a scene takes world, bodies");
    CHECK(browser::first_words("one two three", 9) == "one...");
    CHECK(browser::first_words("one two three", 13) == "one two three");
    CHECK(browser::first_words("abcdefghij", 6) == "abc...");
}

TEST_CASE("scene_file: more bodies than a run can afford are refused") {
    ScratchFolder folder("many");
    std::string text = R"({"bodies": [)";
    for (std::size_t i = 0; i <= kMaxBodies; ++i) {
        text.append(i == 0 ? "" : ",").append(R"({"shape": "circle", "center": [0, 0], "radius": 1})");
    }
    const fs::path file = folder.write("many.json", text + "]}");
    CHECK(refusal(file) ==
          file.string() + ": bodies: more than 2500 bodies (got 2501); every step tests every pair of them");
}

TEST_CASE("scene_file: text that is not UTF-8, or holds control characters, is escaped in the one line") {
    ScratchFolder folder("escaped");
    const fs::path bytes = folder.write("bytes.json", "{\"bodies\": [{\"shape\": \"circ\\u001b\xff\"}]}");
    const std::string message = refusal(bytes);
    CHECK(message.find('\xff') == std::string::npos);
    // The parser's phrase says what is wrong; the bytes it read are not quoted at all.
    CHECK_THAT(
        message,
        Catch::EndsWith("malformed JSON: syntax error while parsing value - invalid string: ill-formed UTF-8 byte"));
    // A file name with a line break and an escape sequence in it.
    const fs::path strange = folder.write("a\nb\x1b[31m.json", R"({"world": {"dt": 0}})");
    CHECK(refusal(strange) ==
          folder.path.string() + R"(/a\nb\x1b[31m.json: world.dt: must be a number in [1e-5, 1] (got 0))");
}

TEST_CASE("scene_file: the file name appears as it was given") {
    ScratchFolder folder("as_given");
    const fs::path file = folder.write("scene.json", R"({"world": {"dt": 0}})");
    // The same file reached through a detour: the message repeats the detour.
    const fs::path detour = folder.path / "." / "scene.json";
    CHECK(refusal(detour).rfind(detour.string() + ": world.dt: ", 0) == 0);
}

TEST_CASE("scene_file: a word from a list loads as its value, and a bad one is refused with the choices") {
    ScratchFolder folder("words");
    CHECK(load_scene(folder.write("fancy.json", R"({"world": {"method": "fancy"}})"), kDemoDefaults).world.method ==
          Method::fancy);
    CHECK(load_scene(folder.write("plain.json", R"({"world": {"method": "plain"}})"), kDemoDefaults).world.method ==
          Method::plain);
    const fs::path bad = folder.write("bad.json", R"({"world": {"method": "clever"}})");
    CHECK(refusal(bad) == bad.string() + R"(: world.method: must be "plain" or "fancy" (got "clever"))");
    const fs::path number = folder.write("number.json", R"({"world": {"method": 1}})");
    CHECK(refusal(number) == number.string() + R"(: world.method: must be "plain" or "fancy" (got 1))");
}

TEST_CASE("scene_file: a key the stage does not list is refused, naming the keys it reads") {
    // What a chapter 4 stage says to a knob of the stages beyond the book.
    ScratchFolder folder("not_read");
    const fs::path file = folder.write("scene.json", R"({"world": {"broad_phase": "grid"}})");
    CHECK_THAT(refusal(file), Catch::StartsWith(file.string() + ": world.broad_phase: unknown key; this stage's "
                                                                "world takes width, height, gravity, dt, "));
    // A stage that reads no world key at all refuses every one.
    std::vector<SceneKey> none;
    CHECK_THROWS_WITH(browser::load_scene(folder.write("dt.json", R"({"world": {"dt": 0.01}})"), none, {}),
                      Catch::Contains("world.dt: unknown key"));
    CHECK_NOTHROW(browser::load_scene(folder.write("empty.json", R"({"world": {}})"), none, {}));
    // A stage with no lists refuses bodies as any other unknown part of a scene.
    CHECK_THROWS_WITH(browser::load_scene(folder.write("bodies.json", R"({"bodies": []})"), none, {}),
                      Catch::Contains("bodies: unknown key; a scene takes world"));
}

TEST_CASE("scene_file: a refused file leaves every setting as it was") {
    // The world is read before the bodies; a bad body must not leave a half-read world.
    ScratchFolder folder("half");
    const fs::path file = folder.write("scene.json", R"({"world": {"gravity": [0, 99], "method": "fancy"},
        "bodies": [{"shape": "circle", "center": [0, 0], "radius": -1}]})");
    WorldSettings world = kDemoDefaults;
    std::vector<BodyDescription> read;
    const browser::SceneList bodies = bodyList(read);
    CHECK_THROWS_AS(browser::load_scene(file, worldKeys(world), {&bodies, 1}), SceneError);
    CHECK(world == kDemoDefaults);
}

TEST_CASE("scene_file: the lists, their kinds and their keys are the stage's own words") {
    // A vocabulary the browser has never heard of reads as the bodies do: nothing in the
    // reader knows a shape, a body or its keys.
    struct Spring {
        bool soft = false;
        double stiffness = 1.0;
        Vec2 anchor;
    };
    std::vector<Spring> springs;
    const browser::SceneList list{
        .name = "springs",
        .element = "spring",
        .kind_key = "type",
        .kinds = {"hard", "soft"},
        .most = 2,
        .why_most = "two are plenty",
        .add = [&springs](std::size_t kind) {
            Spring& spring = springs.emplace_back();
            spring.soft = kind == 1;
            std::vector<SceneKey> keys{{"anchor", spring.anchor, browser::rules::kFinite, browser::kRequired}};
            if (spring.soft) keys.push_back({"stiffness", spring.stiffness});
            return keys;
        }};
    ScratchFolder folder("springs");
    const auto read = [&](const std::string& text) {
        springs.clear();
        try {
            browser::read_scene_text(text, "s.json", {}, {&list, 1});
        } catch (const SceneError& error) {
            return std::string(error.what());
        }
        return std::string();
    };
    CHECK(
        read(R"({"springs": [{"type": "soft", "anchor": [1, 2], "stiffness": 3}, {"type": "hard", "anchor": [0, 0]}]})")
            .empty());
    REQUIRE(springs.size() == 2);
    CHECK(springs[0].soft);
    CHECK(springs[0].stiffness == 3);
    CHECK(springs[0].anchor == Vec2{1, 2});
    CHECK_FALSE(springs[1].soft);
    CHECK(read(R"({"springs": [{"anchor": [0, 0]}]})") ==
          R"(s.json: springs[0].type: missing; every spring needs "type": "hard" or "soft")");
    CHECK(read(R"({"springs": [{"type": "hard", "anchor": [0, 0], "stiffness": 3}]})") ==
          "s.json: springs[0].stiffness: unknown key; a hard spring takes type, anchor");
    CHECK(read(R"({"springs": [{"type": "soft"}]})") ==
          "s.json: springs[0].anchor: missing; a soft spring needs type, anchor");
    CHECK(read(R"({"springs": [{"type": "hard", "anchor": [0, 0]}, {"type": "hard", "anchor": [0, 0]},
                   {"type": "hard", "anchor": [0, 0]}]})") ==
          "s.json: springs: more than 2 springs (got 3); two are plenty");
    CHECK(read(R"({"bodies": []})") == "s.json: bodies: unknown key; a scene takes world, springs");
}

TEST_CASE("scene_file: a key described for a reference table: its values, and its setting's value now") {
    WorldSettings world = kDemoDefaults;
    const std::vector<SceneKey> keys = worldKeys(world);
    const auto described = [&](std::string_view name) {
        for (const SceneKey& key : keys) {
            if (key.name() == name) return browser::describe(key);
        }
        FAIL("no key " << name);
        return browser::KeyDescription{};
    };
    CHECK(described("dt").values == "a number in [1e-5, 1]");
    CHECK(described("dt").value_now == "0.016666666666666666");
    CHECK(described("gravity").values == "[x, y], each a finite number");
    CHECK(described("gravity").value_now == "[0, 20]");
    CHECK(described("relaxation_iterations").value_now == "15");
    CHECK(described("movement").values == "true or false");
    CHECK(described("movement").value_now == "true");
    CHECK(described("method").values == R"("plain" or "fancy")");
    CHECK(described("method").value_now == R"("plain")");
    world.method = Method::fancy;
    CHECK(described("method").value_now == R"("fancy")");
    CHECK_FALSE(described("dt").required);
    BodyDescription body{.shape = ShapeKind::circle};
    CHECK(browser::describe(bodyKeys(body).front()).required);
}
