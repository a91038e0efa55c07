#pragma once
// Thin and spinning shapes shot at a thin static wall, for stage 5.6's continuous
// collision (continuous.h): the trials behind the envelope its README states. The stage
// test runs a slice of the grid and a few thousand random shots; the bench program
// bench/thin_shots_study.cpp runs the whole grid and 200,000 random shots, and prints
// the counts.
//
// A shot is a rectangle (a plate, a needle, a square...) or a circle, turned and
// spinning, flying at a static wall 1e5 px tall from where it reaches the wall in about
// a step and a half. It is *through* when, at the end of any of its steps, its centre
// is past the wall's middle while level with the wall (not round its end). It is *held*
// when the sweep kept it where its step began (time of impact 0) for kLongHold steps in
// a row: the safe failure, a shape stuck to the wall (see 5.6's README).

#include <cmath>
#include <cstddef>
#include <numbers>
#include <vector>

#include "browser.h"
#include "circle.h"
#include "core.h"
#include "random.h"
#include "rectangle.h"

namespace thin_shots {

using engine::Vec2;

struct Shot {
    bool circle = false;
    double width = 10, height = 1;  // px; a circle's radius is width / 2
    double wall = 2;                // px: the wall's thickness
    double angle = 0;               // rad, the shape's at the start
    double spin = 0;                // rad/s
    double speed = 1000;            // px/s
    double heading = 0;             // rad from straight at the wall
    double restitution = 0.2;       // both the shot's and the wall's
    double friction = 0.8;
    bool gravity = false;  // the book's 20 px/s^2 down, or none
    engine::SolverKind solver = engine::SolverKind::book;
};

struct Outcome {
    bool through = false;
    bool held = false;
};

inline constexpr double kWallX = 400.0;
inline constexpr double kWallY = 225.0;
inline constexpr double kWallHeight = 1e5;
inline constexpr int kSteps = 30;
inline constexpr int kLongHold = 10;

inline Outcome shoot(const Shot& shot) {
    engine::WorldSettings world = engine::kBookWorld;
    if (!shot.gravity) world.gravity = {0, 0};
    world.remove_out_of_bounds = false;
    world.solver = shot.solver;
    world.continuous = true;
    browser::Window window(world.dt * 1000.0);
    engine::Core core(window, world);
    const engine::PhysicalAttributes surface{.mass = 0, .friction = shot.friction, .restitution = shot.restitution};
    core.add(engine::Rectangle({kWallX, kWallY}, shot.wall, kWallHeight, surface));
    // Clear of the wall at the start, whatever the turn, and a step and a half away.
    const Vec2 toward{std::cos(shot.heading), std::sin(shot.heading)};
    const double reach = shot.circle ? shot.width / 2 : std::hypot(shot.width, shot.height) / 2;
    const double clear = reach + shot.wall / 2 + 0.1;
    const Vec2 start = Vec2{kWallX, kWallY} - toward * (clear / toward.x + 1.5 * shot.speed * world.dt);
    const engine::PhysicalAttributes body{.mass = 1, .friction = shot.friction, .restitution = shot.restitution};
    engine::RigidShape& shape =
        shot.circle ? static_cast<engine::RigidShape&>(core.add(engine::Circle(start, shot.width / 2, body)))
                    : core.add(engine::Rectangle(start, shot.width, shot.height, body));
    shape.rotate(shot.angle);
    shape.setVelocity(toward * shot.speed);
    shape.setAngularVelocity(shot.spin);
    Outcome outcome;
    int hold = 0;
    for (int step = 0; step < kSteps && !outcome.through; ++step) {
        core.update();
        bool kept = false;
        for (const engine::Sweep& sweep : core.continuous().sweeps()) kept = kept || sweep.impact == 0.0;
        hold = kept ? hold + 1 : 0;
        outcome.held = outcome.held || hold >= kLongHold;
        const Vec2 at = shape.center();
        outcome.through = at.x > kWallX && std::abs(at.y - kWallY) < kWallHeight / 2;
    }
    return outcome;
}

// The grid: plates, needles and spinning rectangles at every turn, spin and speed,
// against walls of 2, 0.1 and 0.01 px, head-on and slanting, on both solvers.
struct Shape {
    double width, height;
};
inline constexpr Shape kShapes[] = {{10, 1}, {40, 2}, {20, 0.05}, {5, 0.01}, {8, 4}, {6, 6}};
inline constexpr double kWalls[] = {2, 0.1, 0.01};
inline constexpr double kSpeeds[] = {300, 3000, 30000, 1e6};
inline constexpr double kSpins[] = {0, 30, -300, 1e4};
inline constexpr int kAngles = 8;  // 0 to pi in eighths, plus 0.1 rad
inline constexpr double kHeadings[] = {0, 0.7, 1.3};
inline constexpr engine::SolverKind kSolvers[] = {engine::SolverKind::book, engine::SolverKind::sequential_impulse};
inline constexpr double kRestitutions[] = {0.2, 1.0};

inline std::vector<Shot> grid() {
    std::vector<Shot> shots;
    for (const engine::SolverKind solver : kSolvers) {
        for (const Shape shape : kShapes) {
            for (const double wall : kWalls) {
                for (const double speed : kSpeeds) {
                    for (const double spin : kSpins) {
                        for (int angle = 0; angle < kAngles; ++angle) {
                            for (const double heading : kHeadings) {
                                for (const double restitution : kRestitutions) {
                                    shots.push_back({.width = shape.width,
                                                     .height = shape.height,
                                                     .wall = wall,
                                                     .angle = angle * std::numbers::pi / kAngles + 0.1,
                                                     .spin = spin,
                                                     .speed = speed,
                                                     .heading = heading,
                                                     .restitution = restitution,
                                                     .solver = solver});
                                }
                            }
                        }
                    }
                }
            }
        }
    }
    return shots;
}

// Random shots over the whole range a scene file allows where it matters here: sizes
// from 0.01 px (log-uniform), walls of 0.01 to 5 px, speeds of 10 to 1e6 px/s, spins up
// to 1e4 rad/s, within 80 degrees of straight, any restitution and friction, gravity in
// a third of them; a sixth are circles; the solvers take turns.
inline std::vector<Shot> randomShots(std::size_t count, std::uint64_t seed) {
    browser::Random random(seed);
    const auto uniform = [&](double low, double high) { return low + (high - low) * random.next(); };
    const auto spread = [&](double low, double high) { return std::exp(uniform(std::log(low), std::log(high))); };
    std::vector<Shot> shots;
    for (std::size_t i = 0; i < count; ++i) {
        Shot shot;
        shot.solver = i % 2 == 0 ? engine::SolverKind::book : engine::SolverKind::sequential_impulse;
        shot.circle = i % 6 == 5;
        shot.width = spread(0.01, 60);
        shot.height = spread(0.01, 60);
        shot.wall = spread(0.01, 5);
        shot.speed = spread(10, 1e6);
        shot.spin = uniform(-1, 1) * spread(0.1, 1e4);
        shot.angle = uniform(-std::numbers::pi, std::numbers::pi);
        shot.heading = uniform(-1.4, 1.4);
        shot.restitution = uniform(0, 1);
        shot.friction = uniform(0, 1);
        shot.gravity = uniform(0, 1) < 1.0 / 3;
        shots.push_back(shot);
    }
    return shots;
}

}  // namespace thin_shots
