#pragma once
// A scene as the bench makes, writes and runs it: the world keys of a scene file and
// its bodies. The bench's own type, so that nothing in the bench but the stage adapter
// (stage_engine.h) needs an engine's types: each stage reads the world as scene JSON,
// through its own engine::worldKeys, exactly as its program reads a scene file.
//
// The book's keys, which every chapter 5 stage reads, are always written. A key that a
// later stage adds is written only when set: left unset, it is that stage's own
// default, and a stage that does not read it is never asked to (a stage refuses a key
// it does not read, as its program does).

#include <optional>
#include <string_view>
#include <vector>

#include "vec2.h"

namespace bench {

using lib::Vec2;

// The choices of the stages after the book, spelled as in scene files
// (docs/scene_format.md).
enum class BroadPhase { bounding_circle, all_pairs, grid };     // 5.2 on
enum class Integrator { symplectic, explicit_euler };           // 5.3
enum class FrictionModel { book, coulomb };                     // 5.3
enum class Solver { book, sequential_impulse };                 // 5.4
enum class PositionMethod { split_impulse, baumgarte, relax };  // 5.4

std::string_view spelling(BroadPhase phase);
std::string_view spelling(Integrator integrator);
std::string_view spelling(FrictionModel model);
std::string_view spelling(Solver solver);
std::string_view spelling(PositionMethod method);

struct WorldDescription {
    // The book's keys. No defaults here: the book's values live in the stages, and
    // book_world() (stages.h) brings them from stage 5.1.
    double width = 0.0;   // px
    double height = 0.0;  // px
    Vec2 gravity;         // px/s^2
    double dt = 0.0;      // s
    bool movement = false;
    int relaxation_iterations = 0;
    double correction_rate = 0.0;
    bool positional_correction = false;
    bool remove_out_of_bounds = false;
    // The keys of the stages after the book; unset, the stage's own default.
    std::optional<BroadPhase> broad_phase;          // 5.2 on
    std::optional<int> substeps;                    // 5.3
    std::optional<Integrator> integrator;           // 5.3
    std::optional<FrictionModel> friction_model;    // 5.3
    std::optional<bool> rotation;                   // 5.3
    std::optional<bool> friction;                   // 5.3
    std::optional<Solver> solver;                   // 5.4
    std::optional<int> velocity_iterations;         // 5.4
    std::optional<bool> warm_starting;              // 5.4
    std::optional<PositionMethod> position_method;  // 5.4
    std::optional<double> restitution_threshold;    // 5.4, px/s
    std::optional<bool> sleep;                      // 5.5 on
    std::optional<bool> continuous;                 // 5.6
    // Not a key of a scene file but what the program around the engine does: true, a
    // game reads the step's collision events after every step (5.7 on, which keeps them
    // only while someone reads them); false or unset, no one does.
    std::optional<bool> events;  // 5.7

    friend bool operator==(const WorldDescription&, const WorldDescription&) = default;
};

// Sub-steps per fixed step: none asked for is one.
int substeps_of(const WorldDescription& world);

// A body of a scene, with the book's RigidShape parameters, the same in every chapter 5
// stage (each stage declares them for its scene files, scene_io.cpp: the stages' tests
// hold this against theirs, tests/bench/scenes_test.cpp).
enum class Shape { rectangle, circle };
std::string_view spelling(Shape shape);

struct BodyDescription {
    Shape shape = Shape::rectangle;
    Vec2 center;
    double width = 0.0;   // rectangles only
    double height = 0.0;  // rectangles only
    double radius = 0.0;  // circles only
    double mass = 1.0;    // 0 makes the body static
    double friction = 0.8;
    double restitution = 0.2;
    double angle = 0.0;  // rad
    Vec2 velocity;
    double angular_velocity = 0.0;  // rad/s

    friend bool operator==(const BodyDescription&, const BodyDescription&) = default;
};

struct SceneDescription {
    WorldDescription world;
    std::vector<BodyDescription> bodies;
};

}  // namespace bench
