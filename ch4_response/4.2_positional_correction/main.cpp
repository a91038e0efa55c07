// The stage's index.html: the canvas and the echo panel, the engine core with its
// scene (the book's, or one from --scene FILE), and the user control script that every
// key press goes to. The stage program (common/stage_main.h) does the rest: the
// options, --scene and --dump, the run's budget and its exit statuses.

#include "core.h"
#include "my_game.h"
#include "page_world.h"
#include "scene_io.h"
#include "stage_main.h"
#include "user_control.h"

namespace {

// The book's own experiment: positional correction (M) and movement start off; 14
// shapes are created on top of each other at the cursor, low on the canvas. At frame
// 30 positional correction comes on and pushes them apart in a few steps, until none
// overlaps another. At frame 90 movement comes on: each flies off at the random
// velocity F/G gave it (up to 150 px/s a component), into the borders and into each
// other, and is pushed out again, step after step. Nothing answers their velocities
// yet, so nothing bounces: a shape that reaches a border stays pressed against it.
// A table, an option or a key a line, which the layout would re-wrap:
// clang-format off
const browser::StageDefaults kStage{
    .id = "s4_2",
    .title = "4.2 Positional Correction: relaxation pushes overlapping shapes apart",
    .keys = "m s*15 f g f g f g f g f g f g f g 5 m@30 comma@90",
    .frames = 300,
    .every = 30,
    // Every key user_control.cpp reacts to, as the README lists them.
    .key_help = {
        {"0-9 up down", "select an object: by its number, the one before, the one after"},
        {"w a s d", "move the selected object 10 px up, left, down, right"},
        {"q e", "turn it -0.1 / +0.1 rad"},
        {"i k", "its velocity -1 / +1 px/s along y"},
        {"j l", "its velocity -1 / +1 px/s along x"},
        {"u o", "its angular velocity -0.1 / +0.1 rad/s"},
        {"z x", "its mass -1 / +1 (0 makes it static)"},
        {"c v", "its friction -0.01 / +0.01"},
        {"b n", "its restitution -0.01 / +0.01"},
        {"comma", "movement on / off"},
        {"m", "positional correction on / off"},
        {"h", "excite: a random velocity for every moving shape"},
        {"f g", "a new rectangle / circle at the selected object"},
        {"r", "reset: keep only the first five objects"},
    },
    .overlay = "the positional correction of the last step (--overlay-all: the bounding circles, the collision info, velocities and spins too)",
    // The page notes the book's quirk beside the echo's mass (docs/errata.md): the echo
    // keeps the book's number.
    .echo_notes = {{"Mass:", "*", "the book's quirk: 1 / (1/mass rounded to 3 digits); docs/errata.md"}},
};
// clang-format on

class Page final : public browser::StagePage {
public:
    Page(browser::Window& window, browser::Random& random, const engine::Scene* scene)
        : core_(window, scene ? scene->world : engine::kBookWorld), control_(core_, random) {
        if (scene) {
            engine::buildScene(core_, scene->bodies);
        } else {
            engine::buildScene(core_);
        }
    }
    void onKeyDown(browser::Key key) override { control_.onKeyDown(key); }
    void onAnimationFrame() override { core_.runGameLoop(); }
    browser::PageWorld world() override { return engine::pageWorld(core_); }

private:
    engine::Core core_;
    engine::UserControl control_;
};

}  // namespace

int main(int argc, char** argv) { return browser::run_stage<Page>(argc, argv, kStage, engine::kSceneFiles); }
