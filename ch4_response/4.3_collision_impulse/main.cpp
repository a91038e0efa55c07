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

// Frame 0: movement on; shapes appear above the platform (object 1): 6 to 9, the
// rectangle 8 above the circle 7, and to its right, 10 and 11. F/G throw each one at a
// random velocity; K adds 150 px/s down to each, so that all of them go down. The
// cursor, which is static and collides like any shape, goes up out of their way. On
// the platform they stop dead (restitution 0) and slide to rest, slowed at about g
// whatever the friction (the book's model): 6 and 7 within half a second; 8 runs into
// 9 and sets it sliding, and 9 slides off the platform's end. 10 and 11 bounce off the
// bottom and right borders, a little. At frame 180 H gives every shape a random kick.
// Nothing turns: this project changes linear velocities only.
// A table, an option or a key a line, which the layout would re-wrap:
// clang-format off
const browser::StageDefaults kStage{
    .id = "s4_3",
    .title = "4.3 Collision Impulse: shapes land, bounce and rest",
    .keys = "comma a*30 s*10 f d*10 g w*6 f d*10 s*6 g d*25 f d*10 g "
            "6 k*150 7 k*150 8 k*150 9 k*150 down k*150 down k*150 0 w*20 7 h@180",
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
        {"r", "reset: keep only the first six objects"},
    },
    .overlay = "the impulses of the last step (--overlay-all: the bounding circles, the collision info, velocities and spins, the correction too)",
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
