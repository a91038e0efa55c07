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

// Frame 0: a rectangle and a circle on top of each other at the left; in the middle a
// turned rectangle with a circle just above it, apart but within each other's bounding
// circles (Figure 3-5); a lone circle at the right. Frame 40: the middle circle moves
// 20 px up, out of reach. Frame 80: the lone circle joins the pair at the left.
// A table, an option or a key a line, which the layout would re-wrap:
// clang-format off
const browser::StageDefaults kStage{
    .id = "s3_1",
    .title = "3.1 Broad Phase Method: bounding circles, overlapping pairs in green",
    .keys = "a*20 f g d*20 f 7 e*4 0 w*4 g d*25 g 8@40 w*2 9 a*42@80 s*4 0",
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
    .overlay = "the bounding circles, and each pair the broad phase passed with its test",
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
