#pragma once
// What tests measure a world by, worked out from each shape's centre,
// size, angle, mass and velocities only: whether every number is still finite, how deep
// two shapes overlap (judged by the independent oracle of oracle/collision_oracle.h,
// never by the engine's own collision tests), the kinetic energy, and the centre of mass.

#include <cmath>
#include <cstddef>
#include <optional>

#include "core.h"
#include "shape_outline.h"
#include "world_fixture.h"

namespace test {

// Centre, angle and both velocities: everything that a NaN, once in, spreads to.
inline bool finite(const engine::RigidShape& shape) {
    return finite(shape.center()) && finite(shape.velocity()) && std::isfinite(shape.angle()) &&
           std::isfinite(shape.angularVelocity());
}

// The index of the first shape with a NaN or an infinite number, or nothing.
inline std::optional<std::size_t> firstNotFinite(const engine::Core& core) {
    for (std::size_t i = 0; i < core.objectCount(); ++i) {
        if (!finite(core.object(i))) return i;
    }
    return std::nullopt;
}

// (m v^2 + I w^2) / 2 over the moving shapes, with I = 1 / invInertia.
inline double kineticEnergy(const engine::RigidShape& shape) {
    if (shape.isStatic()) return 0.0;
    const double w = shape.angularVelocity();
    return (shape.mass() * shape.velocity().dot(shape.velocity()) + w * w / shape.invInertia()) / 2;
}

inline double kineticEnergy(const engine::Core& core) {
    double total = 0.0;
    for (std::size_t i = 0; i < core.objectCount(); ++i) total += kineticEnergy(core.object(i));
    return total;
}

// The mass-weighted mean of the moving shapes' centres.
inline Vec2 centreOfMass(const engine::Core& core) {
    Vec2 weighted;
    double mass = 0.0;
    for (std::size_t i = 0; i < core.objectCount(); ++i) {
        const engine::RigidShape& shape = core.object(i);
        if (shape.isStatic()) continue;
        weighted += shape.center() * shape.mass();
        mass += shape.mass();
    }
    return weighted * (1.0 / mass);
}

}  // namespace test
