// The stage's index.html: the canvas and the echo panel, the engine core with its
// scene, and the user control script that every key press goes to. The stage program
// (common/stage_main.h) does the rest: the options, the run's budget and its exit
// statuses.

#include "core.h"
#include "my_game.h"
#include "page_world.h"
#include "stage_main.h"
#include "user_control.h"

namespace {

// Frame 0: walk the cursor left, drop five shapes along a line, turn three of them
// and pin one in place. Frame 60: move the cursor up and drop two more.
// A table, an option or a key a line, which the layout would re-wrap:
// clang-format off
const browser::StageDefaults kStage{
    .id = "s2_2",
    .title = "2.2 Core Engine Loop: fixed updates, moving and turning shapes",
    .keys = "a*20 f d*8 g d*8 f d*8 g d*8 f 5 e*3 7 q*4 9 e*2 h 0 w*6@60 a*10 g d*10 f",
    .frames = 240,
    .every = 30,
    // Every key user_control.cpp reacts to, as the README lists them.
    .key_help = {
        {"0-9 up down", "select an object: by its number, the one before, the one after"},
        {"w a s d", "move the selected object 10 px up, left, down, right"},
        {"q e", "turn it -0.1 / +0.1 rad"},
        {"h", "fix the selected object in place, or free it"},
        {"f g", "a new rectangle / circle at the selected object"},
        {"r", "reset: keep only the first five objects"},
    },
};
// clang-format on

class Page final : public browser::StagePage {
public:
    Page(browser::Window& window, browser::Random& random) : core_(window), control_(core_, random) {
        engine::buildScene(core_);
    }
    void onKeyDown(browser::Key key) override { control_.onKeyDown(key); }
    void onAnimationFrame() override { core_.runGameLoop(); }
    browser::PageWorld world() override { return engine::pageWorld(core_); }

private:
    engine::Core core_;
    engine::UserControl control_;
};

}  // namespace

int main(int argc, char** argv) { return browser::run_stage<Page>(argc, argv, kStage); }
