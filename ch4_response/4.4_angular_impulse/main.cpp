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

// Frame 0: movement on; two shapes appear above the upper platform (object 1): 7 and
// 8, and two above the steep one (object 2): 9 and 10. F/G throw each one at a random
// velocity; K sends them all down, and J takes back most of the push to the right that
// 9 and 10 got, so that they fall onto the steep platform. The cursor, static like the
// platforms, goes up out of their way. Circle 7 rolls down the upper platform to the
// left, spinning, and over its end; box 8 glances off it and drifts left above it.
// Circle 9 lands on the steep platform and slides down it, spinning up, then rolls on
// along the bottom; box 10 tips over as it lands and tumbles down the slope in one
// long hop.
// A table, an option or a key a line, which the layout would re-wrap:
// clang-format off
const browser::StageDefaults kStage{
    .id = "s4_4",
    .title = "4.4 Angular Impulse: shapes turn, roll and tumble",
    .keys = "comma d*20 w*10 g d*6 f a*50 g a*5 f 7 k*40 8 k*40 9 j*70 k*60 down j*80 k*60 0 w*10 9",
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
        {"r", "reset: keep only the first seven objects"},
    },
    .overlay = "the impulses, lever arms and spin changes (--overlay-all: the bounding circles, the collision info, velocities and spins, the correction too)",
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
