#pragma once
// The user control script (UserControl.js): what each key does to the world.
//   0-9          select the object with that index
//   Up / Down    select the previous / next object
//   W A S D      move the selected object 10 px up / left / down / right
//   Q / E        turn it 0.1 rad one way / the other
//   H            fix it in place, or let it sink again
//   F / G        create a rectangle / circle of random size at the selected object
//   R            reset: remove every object but the first kKeptOnReset

#include <cstddef>

#include "core.h"
#include "keys.h"
#include "random.h"

namespace engine {

class UserControl {
public:
    // The cursor and the four borders of my_game survive a reset.
    static constexpr std::size_t kKeptOnReset = 5;

    UserControl(Core& core, browser::Random& random) : core_(core), random_(random) {}
    void onKeyDown(browser::Key key);

private:
    void spawnRectangle(Vec2 center);
    void spawnCircle(Vec2 center);

    Core& core_;
    browser::Random& random_;  // stands in for Math.random()
};

}  // namespace engine
