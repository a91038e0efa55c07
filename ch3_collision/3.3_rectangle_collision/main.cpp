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

// Frame 0: at the left a rectangle and a turned one over its right side; in the middle
// a rectangle and a square turned into a diamond, whose corner pokes into its side; at the
// right a rectangle inside a circle, and a second circle over the first. The cursor
// then goes up out of the way. Frame 40: the turned rectangle at the left turns more.
// Frame 80: the diamond moves 10 px into the rectangle beside it.
// A table, an option or a key a line, which the layout would re-wrap:
// clang-format off
const browser::StageDefaults kStage{
    .id = "s3_3",
    .title = "3.3 Rectangle Collision: the support-point SAT between rectangles",
    .keys = "a*25 f d*3 f 6 e*3 0 d*15 f d*4 f 8 e*8 a 0 d*17 f g d*3 g w*12 6@40 e*3 8@80 a 0",
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
