#pragma once
// The book's MyGame.js: the scene the world starts with. Edit it to try another scene.

#include "core.h"

namespace engine {

// Four thin rectangles along the edges of the canvas, objects 0 to 3.
void buildScene(Core& core);

}  // namespace engine
