#pragma once
// The world's settings: the numbers the book keeps in its engine core (gEngine.Core:
// mWidth, mHeight, mGravity, mUpdateIntervalInSeconds, mMovement) and, from 4.2, in its
// physics (gEngine.Physics: mRelaxationCount, mPosCorrectionRate,
// mPositionalCorrectionFlag), gathered in one value so that the core, the physics and
// every shape read the same world, and a scene file can change them (scene_io.h says
// which keys it reads). The book's own values are written here, once. The demo adds
// the removal of shapes that fall off the canvas, 5.2 the choice of broad phase
// (broad_phase.h), and this stage the knobs that trade speed against accuracy. Each
// knob's default is what the book does, so a scene that leaves them out runs as 5.2.

#include "vec2.h"

namespace engine {

using lib::Vec2;

// The book's world advances in fixed steps of 1/60 s, whatever the frame rate.
inline constexpr double kFPS = 60.0;
inline constexpr double kFrameTime = 1.0 / kFPS;  // seconds per update
inline constexpr double kMPF = 1000.0 / kFPS;     // milliseconds per update

// Gravity pulls every body down, and +y is down on the canvas. The demo pulls twice as
// hard as chapter 4, so the shapes tumble briskly.
inline constexpr Vec2 kGravity{0.0, 20.0};  // px/s^2

// The book's relaxation: 15 passes per step, each removing 80% of every overlap it
// finds, so an overlap left alone shrinks to 0.2^15 (3e-11) of its depth in one step.
inline constexpr int kRelaxationCount = 15;
inline constexpr double kPosCorrectionRate = 0.8;

// How the relaxation pass finds the pairs worth a closer look (broad_phase.h).
enum class BroadPhaseKind { bounding_circle, all_pairs, grid };

// Which velocity moves a shape in a step (rigid_shape.cpp, update).
enum class Integrator { symplectic, explicit_euler };
// The tangent impulse (physics.cpp, frictionImpulse).
enum class FrictionModel { book, coulomb };

struct WorldSettings {
    double width = 800.0;   // px, the canvas
    double height = 450.0;  // px
    Vec2 gravity = kGravity;
    // Both the step of the integration and the fixed step of the loop, as the book
    // derives both from one constant.
    double dt = kFrameTime;  // s
    // The demo runs by itself: movement starts on (the comma key stops it).
    bool movement = true;
    int relaxation_iterations = kRelaxationCount;
    double correction_rate = kPosCorrectionRate;  // share of an overlap one pass removes
    // Positional correction starts on; the M key turns it off.
    bool positional_correction = true;
    // With no borders around the canvas, a shape that falls off would be simulated for
    // ever, unseen; so a shape whose centre leaves the canvas is removed.
    bool remove_out_of_bounds = true;
    // 5.2's grid, unless a scene asks for the book's bounding circles (or for
    // no broad phase at all).
    BroadPhaseKind broad_phase = BroadPhaseKind::grid;
    // Each fixed step runs as this many steps of dt / substeps.
    int substeps = 1;
    Integrator integrator = Integrator::symplectic;
    FrictionModel friction_model = FrictionModel::book;
    bool rotation = true;  // false: no angular terms in impulses or motion
    bool friction = true;  // false: no tangent impulse

    friend bool operator==(const WorldSettings&, const WorldSettings&) = default;
};

// The world of the book's cool demo, unless a scene file says otherwise.
inline constexpr WorldSettings kBookWorld{};

}  // namespace engine
