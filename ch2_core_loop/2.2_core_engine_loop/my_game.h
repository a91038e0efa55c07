#pragma once
// The book's MyGame.js: the scene the world starts with. Edit it to try another scene.

#include "core.h"

namespace engine {

// Object 0 is a tiny fixed square at the centre of the canvas, the cursor: new shapes
// appear at the selected object, so moving the cursor chooses where they appear.
// Objects 1 to 4 are fixed thin rectangles along the edges of the canvas.
void buildScene(Core& core);

}  // namespace engine
