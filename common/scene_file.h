#pragma once
// Scene files (--scene FILE): a JSON description of the world and its bodies that a
// learner edits instead of the stage's code. In short:
//   {"world":  {"width", "height", "gravity": [x, y], "dt", "relaxation_iterations",
//               "correction_rate", "movement", "positional_correction",
//               "remove_out_of_bounds", and in stage 5.1 the knobs below},
//    "bodies": [{"shape": "rectangle", "center": [x, y], "width", "height", ...},
//               {"shape": "circle", "center": [x, y], "radius", ...}]}
// where every body may also give mass, friction, restitution, angle, velocity [x, y] and
// angular_velocity. Everything but a body's shape, center and size may be left out.
// Units are the book's: px, s, rad, +y down.
//
// The reader only checks and describes; it knows nothing of any stage's engine. A stage
// passes its own book defaults for the world, gets a SceneDescription back, and builds
// its RigidShapes from it in file order.

#include <filesystem>
#include <stdexcept>
#include <string_view>
#include <vector>

#include "vec2.h"

namespace browser {

// The knobs that trade speed against accuracy (stage 5.1 only; docs/scene_format.md).
// Each enum's first value is what the book does.
enum class Integrator { symplectic, explicit_euler };     // "symplectic", "explicit"
enum class BroadPhase { bounding_circle, all_pairs, grid };  // "bounding_circle", ...
enum class FrictionModel { book, coulomb };                // "book", "coulomb"

// The spelling used in scene files, and in the bench's tables.
std::string_view knob_name(Integrator integrator);
std::string_view knob_name(BroadPhase broad_phase);
std::string_view knob_name(FrictionModel friction_model);

// The world's tunables. The member defaults are chapter 4's book values; 5.1 changes
// gravity to (0, 20) and turns on movement and remove_out_of_bounds:
//   WorldSettings{.gravity = {0, 20}, .movement = true, .remove_out_of_bounds = true}
// The members after remove_out_of_bounds are the knobs only 5.1's engine reads; their
// defaults are the book's engine, so a scene that leaves them out runs as in the book.
struct WorldSettings {
    double width = 800.0;   // px
    double height = 450.0;  // px
    Vec2 gravity{0.0, 10.0};  // px/s^2, +y down
    double dt = 1.0 / 60.0;   // s per fixed update
    int relaxation_iterations = 15;
    double correction_rate = 0.8;  // share of the overlap positional correction removes
    bool movement = false;
    bool positional_correction = true;
    bool remove_out_of_bounds = false;

    int substeps = 1;  // each fixed step runs as this many steps of dt / substeps
    Integrator integrator = Integrator::symplectic;
    BroadPhase broad_phase = BroadPhase::bounding_circle;
    FrictionModel friction_model = FrictionModel::book;
    bool rotation = true;  // false: no angular terms in impulses or motion
    bool friction = true;  // false: no tangent impulse

    friend bool operator==(const WorldSettings&, const WorldSettings&) = default;
};

enum class ShapeKind { rectangle, circle };

// "rectangle" or "circle": the spelling used in scene files and state dumps.
std::string_view shape_name(ShapeKind shape);

struct BodyDescription {
    ShapeKind shape = ShapeKind::rectangle;
    Vec2 center;
    double width = 0.0;   // rectangles only
    double height = 0.0;  // rectangles only
    double radius = 0.0;  // circles only
    double mass = 1.0;    // 0 makes the body static
    double friction = 0.8;
    double restitution = 0.2;
    double angle = 0.0;  // rad, applied after construction as the book's rotate(angle)
    Vec2 velocity;
    double angular_velocity = 0.0;  // rad/s

    friend bool operator==(const BodyDescription&, const BodyDescription&) = default;
};

struct SceneDescription {
    WorldSettings world;
    std::vector<BodyDescription> bodies;  // in file order: the object index keys 0-9 select
};

// A scene that cannot be simulated. what() is one line:
//   "<file as given>: <JSON path>: <problem> (got <value>)"
// or, for text that is not JSON at all, "<file>: line L, column C: malformed JSON: ...".
struct SceneError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// Which world keys a stage reads: chapter 4's engines know only the book's settings,
// so they refuse the knobs as unknown keys rather than silently ignore them.
enum class WorldKeys { book, with_knobs };

// Reads and checks `file`. World keys the file leaves out take their value from
// `defaults`; body keys it leaves out take BodyDescription's defaults. Throws SceneError
// on the first problem found, so nothing is built from a scene that is only half right.
SceneDescription load_scene(const std::filesystem::path& file, const WorldSettings& defaults,
                            WorldKeys keys = WorldKeys::book);

}  // namespace browser
