#pragma once
// A closed box for energy and escape tests: its inside is [100, 700] x [50, 400], its
// four static walls `wall` px thick, each with e = 1 and friction 0.8. With e = 1 no
// impulse can add energy and friction can only take it away, so a closed box's kinetic
// energy never rises above its start.

#include <algorithm>
#include <cmath>

#include "circle.h"
#include "core.h"
#include "rectangle.h"
#include "world_fixture.h"
#include "world_measures.h"

namespace test {

// How far a centre lies outside the rectangle [left, right] x [top, bottom]; 0 inside.
inline double outside(engine::Vec2 c, double left, double right, double top, double bottom) {
    return std::hypot(std::max({left - c.x, c.x - right, 0.0}), std::max({top - c.y, c.y - bottom, 0.0}));
}

struct ClosedBox {
    static constexpr double kLeft = 100, kRight = 700, kTop = 50, kBottom = 400;
    explicit ClosedBox(const engine::WorldSettings& world, double wall = 1e5) : page(world) {
        const engine::PhysicalAttributes hard{.mass = 0, .friction = 0.8, .restitution = 1};
        const double tall = kBottom - kTop + 2 * wall;
        const double wide = kRight - kLeft + 2 * wall;
        page.core.add(engine::Rectangle({kLeft - wall / 2, (kTop + kBottom) / 2}, wall, tall, hard));
        page.core.add(engine::Rectangle({kRight + wall / 2, (kTop + kBottom) / 2}, wall, tall, hard));
        page.core.add(engine::Rectangle({(kLeft + kRight) / 2, kTop - wall / 2}, wide, wall, hard));
        page.core.add(engine::Rectangle({(kLeft + kRight) / 2, kBottom + wall / 2}, wide, wall, hard));
    }
    double outside(engine::Vec2 c) const { return test::outside(c, kLeft, kRight, kTop, kBottom); }
    WorldFixture page;
};

// A 40 x 20 box, friction 0.8 and e = 1, at 100 px/s and 1 rad/s in a closed box with
// 100 px walls, for 600 steps of `world` (no gravity). Returns the most kinetic energy
// seen, as a share of the start: by the physics, at most 1. Checks on the way that
// every number stays finite and that the box stays inside, out by no more than a step
// and its size.
inline double roughBoxEnergyPeak(const engine::WorldSettings& world) {
    ClosedBox closed(world, 100);
    engine::Rectangle& box =
        closed.page.core.add(engine::Rectangle({400, 225}, 40, 20, {.mass = 1, .friction = 0.8, .restitution = 1}));
    box.setVelocity(engine::Vec2{0.6, 0.8} * 100);
    box.setAngularVelocity(1);
    const double energy = kineticEnergy(closed.page.core);
    double most_energy = energy;
    for (int step = 1; step <= 600; ++step) {
        closed.page.steps(1);
        REQUIRE_FALSE(firstNotFinite(closed.page.core));
        most_energy = std::max(most_energy, kineticEnergy(closed.page.core));
    }
    CHECK(closed.outside(box.center()) <= box.velocity().length() * world.dt + 2 * box.boundRadius());
    return most_energy / energy;
}

}  // namespace test
