#pragma once
// What a chapter 4 physics test needs: a world with settings of its choosing (gravity,
// dt, the movement and positional-correction flags), stepped one fixed update at a
// time without drawing, plus the sums that conservation laws are about. Only names
// every chapter 4 stage shares are used, so one test source compiles against each.

#include <cmath>
#include <cstddef>
#include <cstdint>

#include "browser.h"
#include "color_text.h"
#include "circle.h"
#include "core.h"
#include "random.h"
#include "rigid_shape.h"
#include "user_control.h"

namespace test {

using lib::Vec2;

// The book's chapter 4 world with its flags and gravity set as a test needs them.
inline engine::WorldSettings world(bool movement, Vec2 gravity = engine::kGravity) {
    engine::WorldSettings settings = engine::kBookWorld;
    settings.movement = movement;
    settings.gravity = gravity;
#if __has_include("islands.h")
    settings.sleep = false;  // 5.5: chapter 4's world never sleeps
#endif
#if __has_include("continuous.h")
    settings.continuous = false;  // 5.6: chapter 4's world is swept by nothing
#endif
    return settings;
}

struct WorldFixture {
    explicit WorldFixture(const engine::WorldSettings& settings, std::uint64_t seed = 1)
        : window(settings.dt * 1000.0), random(seed), core(window, settings) {}

    void press(browser::Key key, int times = 1) {
        for (int i = 0; i < times; ++i) control.onKeyDown(key);
    }
    // `count` fixed updates, each the book's collision pass and then every shape's update.
    void steps(int count) {
        for (int i = 0; i < count; ++i) core.update();
    }

    browser::Window window;
    browser::Random random;
    engine::Core core;
    engine::UserControl control{core, random};
};

// Two circles of radius 10 and the default attributes on the line y = 100, 30 px
// apart, flying at each other at 60 px/s each: they touch after 1/12 s (5 steps).
struct ApproachingCircles {
    explicit ApproachingCircles(WorldFixture& page)
        : left(page.core.add(engine::Circle({100, 100}, 10))), right(page.core.add(engine::Circle({130, 100}, 10))) {
        left.setVelocity({60, 0});
        right.setVelocity({-60, 0});
    }
    engine::Circle& left;
    engine::Circle& right;
};

// Total linear momentum, sum of m v. Static bodies are left out: their mass is infinite
// and their velocity 0.
inline Vec2 linearMomentum(const engine::Core& core) {
    Vec2 total;
    for (std::size_t i = 0; i < core.objectCount(); ++i) {
        const engine::RigidShape& shape = core.object(i);
        if (!shape.isStatic()) total += shape.velocity() * shape.mass();
    }
    return total;
}

// Total angular momentum about the fixed point `about`: each body's orbital part
// m (c - about) x v plus its spin I w (I = 1 / invInertia).
inline double angularMomentum(const engine::Core& core, Vec2 about) {
    double total = 0.0;
    for (std::size_t i = 0; i < core.objectCount(); ++i) {
        const engine::RigidShape& shape = core.object(i);
        if (shape.isStatic()) continue;
        total += shape.mass() * (shape.center() - about).cross(shape.velocity());
        total += shape.angularVelocity() / shape.invInertia();
    }
    return total;
}

inline bool finite(Vec2 v) { return std::isfinite(v.x) && std::isfinite(v.y); }

}  // namespace test
