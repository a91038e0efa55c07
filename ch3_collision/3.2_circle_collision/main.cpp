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

// Frame 0: two circles with the same centre at the left; two overlapping side by side
// in the middle; a rectangle and a circle on the cursor at the right. Frame 40: the
// middle right circle moves 20 px down. Frame 80: it turns and moves 10 px left,
// deeper in.
// A table, an option or a key a line, which the layout would re-wrap:
// clang-format off
const browser::StageDefaults kStage{
    .id = "s3_2",
    .title = "3.2 Circle Collision Detection: collision info between circles",
    .keys = "a*25 g g d*20 g d*3 g d*18 f g 8@40 s*2 e*4@80 a 0",
    .frames = 120,
    .every = 40,
    // Every key user_control.cpp reacts to, as the README lists them.
    .key_help = {
        {"0-9 up down", "select an object: by its number, the one before, the one after"},
        {"w a s d", "move the selected object 10 px up, left, down, right"},
        {"q e", "turn it -0.1 / +0.1 rad"},
        {"f g", "a new rectangle / circle at the selected object"},
        {"r", "reset: keep only the first five objects"},
    },
    .overlay = "the collision info of each colliding pair: start, end, normal and depth (--overlay-all: the bounding circles too)",
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
