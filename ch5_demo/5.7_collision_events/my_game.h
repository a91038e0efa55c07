#pragma once
// The book's MyGame.js: the scene the world starts with. Edit it to try another scene,
// or give the program a scene file (--scene FILE, scene_io.h).

#include "core.h"
#include "random.h"

namespace engine {

// The cool demo: no borders, so shapes can fall off the canvas and the space never
// crowds. Four static platforms come first (objects 0 to 3):
//   (500, 200) 400 x 20, turned 2.8 rad, friction 0.3, restitution 0: a long slide
//   (200, 400) 400 x 20, friction 1, restitution 0.5: the floor on the left
//   (100, 200) 200 x 20, the default friction and restitution: a ledge
//   (10, 360)  20 x 100, friction 0, restitution 1: a slippery, springy post
// then ten times a rectangle and a circle with random size, mass, friction,
// restitution and velocity, somewhere in the top half of the canvas.
void buildScene(Core& core, browser::Random& random);

}  // namespace engine
