#pragma once
// The world's settings: the numbers the book keeps in its engine core (gEngine.Core:
// mWidth, mHeight, mGravity, mUpdateIntervalInSeconds, mMovement) and, from 4.2, in its
// physics (gEngine.Physics: mRelaxationCount, mPosCorrectionRate,
// mPositionalCorrectionFlag), gathered in one value so that the core, the physics and
// every shape read the same world, and a scene file can change them (scene_io.h says
// which keys it reads). The book's own values are written here, once. The demo adds
// the removal of shapes that fall off the canvas, 5.2 the choice of broad phase
// (broad_phase.h), 5.3 the knobs that trade speed against accuracy, 5.4 a second
// contact solver with its own knobs (contact_solver.h), 5.5 sleeping (islands.h) and
// 5.6 continuous collision (continuous.h). Each knob's default but sleep and
// continuous is what the book does, so a scene that leaves them out and turns both off
// runs as 5.2.

#include <algorithm>

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

// Who resolves the contacts a step finds (physics.cpp): the book's relaxation passes,
// or the sequential impulse solver of 5.4 (contact_solver.h).
enum class SolverKind { book, sequential_impulse };
// How the sequential impulse solver removes overlap (contact_solver.h): pseudo
// velocities that move the shapes apart and are then forgotten (split impulses); an
// extra speed in the velocity target (Baumgarte), which stays in the shapes' velocity;
// or that extra speed taken back out by further iterations (relax).
enum class PositionMethod { split_impulse, baumgarte, relax };

// The sequential impulse solver's defaults (contact_solver.h says what each does). The
// canvas is in pixels; at the bench's scale of 30 px to the metre a 0.15 px slop and a
// 30 px/s threshold are the usual 5 mm and 1 m/s of engines that work in metres.
inline constexpr int kVelocityIterations = 8;
inline constexpr int kPositionIterations = 3;
inline constexpr double kRestitutionThreshold = 30.0;  // px/s
inline constexpr double kPositionRate = 0.2;           // share of the overlap past the slop, per step
inline constexpr double kSlop = 0.15;                  // px of overlap left alone

// Sleeping (islands.h; README.md derives every number). A shape rests while its sleep
// speed stays under the world's sleep speed: 3 px/s (the scene's sleep_speed), or the
// speed gravity gives in 0.15 s where that is more (15 px/s under 100 px/s^2). A shape
// at the top of its arc is then that slow for 2 * 0.15 = 0.3 s at most, less than the
// time to sleep, and the jitter of a resting pile, which grows with gravity, stays
// under it. Whatever its sleep speed, a resting shape does not creep: over the time to
// sleep it goes no farther than at 0.3 px/s (Box2D's 1 cm/s at the bench's 30 px to the
// metre). An island falls asleep when all of it has rested for half a second.
inline constexpr double kSleepSpeed = 3.0;       // px/s, the least
inline constexpr double kSleepSpeedTime = 0.15;  // s
inline constexpr double kCreepSpeed = 0.3;       // px/s
inline constexpr double kTimeToSleep = 0.5;      // s

// 5.9's joints (joints.h): how stiff a rod, a pin, a weld and a slider are, as a
// spring of this frequency and damping ratio pulling each error back (Box2D v3's
// defaults for its joints; README.md, "Soft constraints").
inline constexpr double kJointHertz = 0.0;         // 1/s
inline constexpr double kJointDampingRatio = 2.0;  // 1: critical; more: slower, with no overshoot

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
    SolverKind solver = SolverKind::book;
    // Read by the sequential impulse solver only; the book's passes leave them be.
    int velocity_iterations = kVelocityIterations;
    int position_iterations = kPositionIterations;  // split impulses' passes
    bool warm_starting = true;
    double restitution_threshold = kRestitutionThreshold;  // px/s: slower contacts do not bounce
    PositionMethod position_method = PositionMethod::split_impulse;
    double position_rate = kPositionRate;
    double slop = kSlop;
    // 5.5's sleeping, on unless a scene turns it off; with it off every scene runs
    // as in 5.4, bit for bit. The slop above is also the overlap the sleep rule forgives.
    bool sleep = true;
    double sleep_speed = kSleepSpeed;     // px/s, the least (sleepSpeed, below)
    double time_to_sleep = kTimeToSleep;  // s
    // 5.6's continuous collision (continuous.h): a shape that moves far in a step
    // against its own size is swept to where it first touches, so it cannot pass
    // through a thin wall. On unless a scene turns it off; off, every scene runs as in
    // 5.5, bit for bit, and on it changes nothing in a step with no fast shape.
    bool continuous = true;
    double joint_hertz = kJointHertz;
    double joint_damping_ratio = kJointDampingRatio;

    friend bool operator==(const WorldSettings&, const WorldSettings&) = default;
};

// The sleep speed of `world`: its sleep_speed, or what its gravity gives in 0.15 s
// where that is more.
inline double sleepSpeed(const WorldSettings& world) {
    return std::max(world.sleep_speed, kSleepSpeedTime * world.gravity.length());
}

// The world of the book's cool demo, unless a scene file says otherwise.
inline constexpr WorldSettings kBookWorld{};

}  // namespace engine
