#pragma once
// The book's MyGame.js: the scene the world starts with. Edit it to try another scene,
// or give the program a scene file (--scene FILE, scene_io.h).

#include "core.h"

namespace engine {

// Object 0 is a tiny square at the centre of the canvas, the cursor: new shapes appear
// at the selected object, so moving the cursor chooses where they appear.
// Objects 1 and 2 are platforms to land on, 400 x 20, made right after the cursor as
// in the book's MyGame.js: 1 at (500, 200) turned by 3.0 rad (almost half a turn:
// sloping gently down to the left on screen), 2 at (200, 400) turned by 0.785 rad (45
// degrees, sloping down to the right), gripping (friction 1) and dead (restitution 0).
// Objects 3 to 6 are thin rectangles along the edges of the canvas (top, bottom,
// left, right). All seven are static (mass 0), so gravity leaves them where they are.
void buildScene(Core& core);

}  // namespace engine
