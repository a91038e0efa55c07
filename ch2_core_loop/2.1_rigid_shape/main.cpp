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

// A table, an option or a key a line, which the layout would re-wrap:
// clang-format off
const browser::StageDefaults kStage{
    .id = "s2_1",
    .title = "2.1 Rigid Shape: rectangles and circles in one object list",
    .keys = "f g f g f g f 7",
    .frames = 1,
    .every = 0,
    // Every key user_control.cpp reacts to, as the README lists them.
    .key_help = {
        {"0-9", "select the object with that number"},
        {"up down", "select the object before / after"},
        {"f g", "a random rectangle / circle"},
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
