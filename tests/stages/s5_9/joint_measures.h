// The world 5.9's joint tests run in, and what they measure of it, shared by the stage
// tests (s5_9_test.cpp) and the sweeps (s5_9/joint_sweeps_test.cpp): a body found by
// its id, a joint's separation, the largest of them, and the world's energy; and a grid
// of pinned bodies (the stage test's and s5_9/positional_passes_test.cpp's).
#pragma once

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

#include "circle.h"
#include "joints.h"
#include "rectangle.h"
#include "world_fixture.h"

namespace s5_9_measures {

// The world the joints' tests run in: the sequential impulse solver, `gravity` px/s^2
// down, nothing removed at the canvas's edge, and no sleep unless a test wants it.
inline engine::WorldSettings jointWorld(double gravity) {
    engine::WorldSettings world = engine::kBookWorld;
    world.solver = engine::SolverKind::sequential_impulse;
    world.gravity = {0, gravity};
    world.remove_out_of_bounds = false;
    world.sleep = false;
    return world;
}

// The shape of id `id` (a test fails if there is none).
inline const engine::RigidShape& bodyOf(const engine::Core& core, engine::BodyId id) {
    for (std::size_t i = 0; i < core.objectCount(); ++i) {
        if (core.object(i).id() == id) return core.object(i);
    }
    FAIL("no body " << id);
    return core.object(0);
}

// How far a joint's anchors are from where the joint keeps them, px.
inline double separationOf(const engine::Core& core, const engine::Joint& joint) {
    return engine::separationOf(joint.definition, bodyOf(core, joint.definition.body_a),
                                bodyOf(core, joint.definition.body_b));
}

// The largest separation of any joint now, px.
inline double largestSeparation(const engine::Core& core) {
    double largest = 0.0;
    for (const engine::Joint& joint : core.joints().all()) largest = std::max(largest, separationOf(core, joint));
    return largest;
}

// Whether every body's centre, velocity, spin and angle are finite numbers.
inline bool allFinite(const engine::Core& core) {
    for (std::size_t i = 0; i < core.objectCount(); ++i) {
        const engine::RigidShape& shape = core.object(i);
        if (!test::finite(shape.center()) || !test::finite(shape.velocity()) ||
            !std::isfinite(shape.angularVelocity()) || !std::isfinite(shape.angle())) {
            return false;
        }
    }
    return true;
}

// Kinetic plus potential energy of every moving body (y grows downward: U = -m g y).
inline double energy(const engine::Core& core) {
    double total = 0.0;
    for (std::size_t i = 0; i < core.objectCount(); ++i) {
        const engine::RigidShape& shape = core.object(i);
        if (shape.isStatic()) continue;
        const double inertia = 1.0 / shape.invInertia();
        total += 0.5 * shape.mass() * shape.velocity().dot(shape.velocity()) +
                 0.5 * inertia * shape.angularVelocity() * shape.angularVelocity() -
                 shape.mass() * core.settings().gravity.dot(shape.center());
    }
    return total;
}

// The mean of the samples taken after steps ceil(from) to to (exclusive), where `from`
// and `to` are fractional steps (a swing's crossings, say).
inline double meanBetween(const std::vector<double>& samples, double from, double to) {
    double sum = 0.0;
    int count = 0;
    for (auto k = static_cast<std::size_t>(std::ceil(from)); k < static_cast<std::size_t>(to); ++k, ++count) {
        sum += samples[k];
    }
    return sum / count;
}

// A grid of `side` x `side` bodies `spacing` px apart, its top left one at `corner`
// and static, each pinned halfway to its right and lower neighbours (2 side (side - 1)
// pins): discs of radius `size`, or boxes of half side `size`. Added to `core` row by
// row, after whatever is there.
inline void hangGrid(engine::Core& core, engine::Vec2 corner, int side, double spacing, double size, bool boxes) {
    const std::size_t first = core.objectCount();
    for (int row = 0; row < side; ++row) {
        for (int column = 0; column < side; ++column) {
            const engine::Vec2 at = corner + engine::Vec2{column * spacing, row * spacing};
            const engine::PhysicalAttributes attributes =
                row == 0 && column == 0 ? engine::PhysicalAttributes{.mass = 0.0} : engine::PhysicalAttributes{};
            if (boxes) {
                core.add(engine::Rectangle(at, 2 * size, 2 * size, attributes));
            } else {
                core.add(engine::Circle(at, size, attributes));
            }
        }
    }
    const auto body = [&](int row, int column) -> const engine::RigidShape& {
        return core.object(first + static_cast<std::size_t>(row * side + column));
    };
    for (int row = 0; row < side; ++row) {
        for (int column = 0; column < side; ++column) {
            const engine::Vec2 here = body(row, column).center();
            if (column + 1 < side) {
                core.join(engine::pinAt(engine::JointType::revolute, body(row, column), body(row, column + 1),
                                        here + engine::Vec2{spacing / 2, 0}));
            }
            if (row + 1 < side) {
                core.join(engine::pinAt(engine::JointType::revolute, body(row, column), body(row + 1, column),
                                        here + engine::Vec2{0, spacing / 2}));
            }
        }
    }
}

}  // namespace s5_9_measures
