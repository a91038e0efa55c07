#pragma once
// The piles of the study of 5.5's sleeping over many scenes (sleep_sweep.cpp,
// ch5_demo/5.5_sleeping/README.md, "Does it hold on any pile?"): shapes dropped from a
// jittered lattice into an open box (a floor and two walls), to settle into a pile
// `layers` deep. Everything a reader might change about a pile is a field, so that a
// sweep can change one thing at a time: the gravity, the surfaces, the sizes, the
// depth, the kinds of shape. The same recipe makes the same scene on every machine
// (a seeded browser::Random).

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "scene_description.h"

namespace bench::piles {

enum class Kinds { circles, squares, mixed };
std::string_view spelling(Kinds kinds);

struct PileRecipe {
    double gravity = 20.0;     // px/s^2, down: the book's demo
    double friction = 0.5;     // every shape's and wall's
    double restitution = 0.2;  // every shape's and wall's
    double smallest = 10.0;    // px across: a square's side, a circle's diameter
    double largest = 25.0;
    int layers = 10;  // how deep the pile lies, in shapes of the mean size
    Kinds kinds = Kinds::mixed;
    // Shapes of the mean size side by side on the floor: the box is as wide as that, so
    // that a pile of any size of shape has the same shape, 40 across and `layers` deep.
    int across = 40;
    // Where the shapes start, their sizes and their kinds: another seed, another pile of
    // the same recipe.
    std::uint64_t seed = 105;

    friend bool operator==(const PileRecipe&, const PileRecipe&) = default;
};

// How many shapes a pile of the recipe holds: across x layers.
int shapeCount(const PileRecipe& recipe);

// The scene: the book's world (15 passes, 0.8 correction, 1/60 s) at the recipe's size
// and gravity, shapes removed out of bounds never (none leave the box).
SceneDescription pile(const PileRecipe& recipe);

// The pile of issue 35 as the issue ran it: the recipe's defaults on the sequential
// impulse solver. 5.5 keeps a copy as ch5_demo/5.5_sleeping/pile.json, for its tests and
// its readers (tests/bench/sleep_piles_test.cpp checks that the two agree).
SceneDescription issuePile();

// One line that names the recipe, e.g. "g 20, mu 0.5, e 0.2, 10-25 px, 10 deep, mixed".
std::string describe(const PileRecipe& recipe);

}  // namespace bench::piles
