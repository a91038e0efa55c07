#pragma once
// The book's own scene (MyGame) for any stage. Up to chapter 4 MyGame only places fixed
// shapes; the cool demo's (5.1) also throws random ones, so it takes the page's
// Math.random. The template only makes the choice of call wait until a stage's
// buildScene is known; no test needs to know which stage it runs against.

#include "my_game.h"
#include "random.h"

namespace test {

template <class Core>
void buildBookScene(Core& core, browser::Random& random) {
    if constexpr (requires { engine::buildScene(core, random); }) {
        engine::buildScene(core, random);
    } else {
        engine::buildScene(core);
    }
}

}  // namespace test
