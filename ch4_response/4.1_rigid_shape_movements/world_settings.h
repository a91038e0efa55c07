#pragma once
// The world's settings: the numbers the book keeps in its engine core (gEngine.Core:
// mWidth, mHeight, mGravity, mUpdateIntervalInSeconds, mMovement), gathered in one value
// so that the core, the physics and every shape read the same world, and a scene file
// can change them (scene_io.h says which keys it reads). The book's own values are
// written here, once.

#include "vec2.h"

namespace engine {

using lib::Vec2;

// The book's world advances in fixed steps of 1/60 s, whatever the frame rate.
inline constexpr double kFPS = 60.0;
inline constexpr double kFrameTime = 1.0 / kFPS;  // seconds per update
inline constexpr double kMPF = 1000.0 / kFPS;     // milliseconds per update

// Gravity pulls every body down, and +y is down on the canvas.
inline constexpr Vec2 kGravity{0.0, 10.0};  // px/s^2

struct WorldSettings {
    double width = 800.0;   // px, the canvas
    double height = 450.0;  // px
    Vec2 gravity = kGravity;
    // Both the step of the integration and the fixed step of the loop, as the book
    // derives both from one constant.
    double dt = kFrameTime;  // s
    // Movement starts off; the comma key turns it on.
    bool movement = false;

    friend bool operator==(const WorldSettings&, const WorldSettings&) = default;
};

// The world the book's chapter 4 simulates, unless a scene file says otherwise.
inline constexpr WorldSettings kBookWorld{};

}  // namespace engine
