#pragma once
// The user control script (UserControl.js): what each key does to the world.
//   0-9          select the object with that index
//   Up / Down    select the previous / next object
//   W A S D      move the selected object 10 px up / left / down / right
//   Q / E        turn it 0.1 rad one way / the other
//   I / K        change its velocity by 1 px/s up / down
//   J / L        change its velocity by 1 px/s left / right
//   U / O        change its angular velocity by -0.1 / +0.1 rad/s
//   Z / X        change its mass by -1 / +1 (down to 0: static)
//   C / V        change its friction by -0.01 / +0.01
//   B / N        change its restitution by -0.01 / +0.01
//   comma        start / stop the motion of every shape
//   M            turn positional correction on / off
//   Y            turn sleeping on / off
//   P            turn continuous collision on / off
//   H            excite: give every non-static shape a random velocity
//   F / G        create a rectangle / circle of random size, attributes and velocity
//                at the selected object
//   slash        create a random convex polygon there (polygon.h's randomCorners: 3 to
//                8 corners), with random attributes and velocity: every letter has a
//                job already, so the polygon has the key after them
//   R            reset: remove every object but the first kKeptOnReset

#include <cstddef>

#include "core.h"
#include "keys.h"
#include "random.h"

namespace engine {

class UserControl {
public:
    // The book keeps this number from chapter 4, where it kept the cursor, the borders
    // and the platforms. The demo's scene has four platforms first, so a reset now also
    // keeps the first three random shapes.
    static constexpr std::size_t kKeptOnReset = 7;
    // H kicks every moving shape: each velocity component uniform in [-250, 250) px/s.
    static constexpr double kExciteSpeed = 250.0;
    // F/G/slash: a new shape flies off, each velocity component uniform in [-150, 150) px/s.
    static constexpr double kSpawnSpeed = 150.0;

    UserControl(Core& core, browser::Random& random) : core_(core), random_(random) {}
    void onKeyDown(browser::Key key);

private:
    void selectionKeys(browser::Key key);
    void worldKeys(browser::Key key);
    void selectedObjectKeys(browser::Key key, RigidShape& selected);
    void exciteAll();
    PhysicalAttributes randomAttributes();
    Vec2 randomVelocity(double largest_component);
    void spawnRectangle(Vec2 center);
    void spawnCircle(Vec2 center);
    void spawnPolygon(Vec2 center);

    Core& core_;
    browser::Random& random_;  // stands in for Math.random()
};

}  // namespace engine
