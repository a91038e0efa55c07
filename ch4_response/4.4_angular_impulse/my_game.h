#pragma once
// The book's MyGame.js: the scene the world starts with. Edit it to try another scene,
// or give the program a scene file (--scene FILE, scene_io.h).

#include "core.h"

namespace engine {

// Object 0 is a tiny square at the centre of the canvas, the cursor: new shapes appear
// at the selected object, so moving the cursor chooses where they appear.
// Objects 1 to 4 are thin rectangles along the edges of the canvas. Objects 5 and 6
// are platforms to land on, 400 x 20: one at (200, 400) turned by 0.785 rad (45
// degrees, sloping down to the right on screen), gripping (friction 1) and dead
// (restitution 0); one at (500, 200) turned by 3.0 rad (almost half a turn: sloping
// gently down to the left). All seven are static (mass 0), so gravity leaves them
// where they are.
void buildScene(Core& core);

}  // namespace engine
