#pragma once
// The book's own scene (MyGame) for any stage. Up to chapter 4 MyGame only places fixed
// shapes; the cool demo's (5.1) also throws random ones, so it takes the page's
// Math.random. The template only makes the choice of call wait until a stage's
// buildScene is known; no test needs to know which stage it runs against.

#include <catch2/catch.hpp>

#include <cstddef>
#include <utility>

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

// The borders of chapters 2 to 4 (objects 1 to 4: top, bottom, left, right) run 800 x 3
// along y = 0 and 450 and 3 x 450 along x = 0 and 800, so each corner of the canvas is a
// 1.5 x 1.5 overlap of two of them, parted by 1.5 px either way. Checks that a pass
// found exactly those four pairs, in the pass's order.
template <class Collisions>
void checkBorderCornersFound(const Collisions& found) {
    REQUIRE(found.size() == 4);
    const std::pair<std::size_t, std::size_t> corners[] = {{1, 3}, {1, 4}, {2, 3}, {2, 4}};
    for (std::size_t k = 0; k < 4; ++k) {
        CHECK(found[k].first == corners[k].first);
        CHECK(found[k].second == corners[k].second);
        CHECK(found[k].info.depth() == Approx(1.5));
    }
}

}  // namespace test
