#pragma once
// The book's MyGame.js: the scene the world starts with. Edit it to try another scene,
// or give the program a scene file (--scene FILE, scene_io.h).

#include "core.h"

namespace engine {

// Object 0 is a tiny square at the centre of the canvas, the cursor: new shapes appear
// at the selected object, so moving the cursor chooses where they appear.
// Object 1 is a platform to land on, 400 x 20 at (200, 400), gripping (friction 1) and
// dead (restitution 0), made right after the cursor as in the book's MyGame.js; objects
// 2 to 5 are thin rectangles along the edges of the canvas (top, bottom, left, right).
// All six are static (mass 0), so gravity leaves them where they are.
void buildScene(Core& core);

}  // namespace engine
