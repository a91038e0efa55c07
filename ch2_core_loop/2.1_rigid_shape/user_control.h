#pragma once
// The user control script (UserControl.js): what each key does to the world.
//   0-9          select the object with that index
//   Up / Down    select the previous / next object
//   F / G        create a rectangle / circle of random size at a random place

#include "core.h"
#include "keys.h"
#include "random.h"

namespace engine {

class UserControl {
public:
    UserControl(Core& core, browser::Random& random) : core_(core), random_(random) {}
    void onKeyDown(browser::Key key);

private:
    Vec2 randomPlace();
    void spawnRectangle();
    void spawnCircle();

    Core& core_;
    browser::Random& random_;  // stands in for Math.random()
};

}  // namespace engine
