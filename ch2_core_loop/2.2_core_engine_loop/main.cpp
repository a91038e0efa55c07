// The stage's index.html: the canvas and the echo panel, the engine core with its
// scene, and the user control script that every key press goes to.

#include "browser.h"
#include "core.h"
#include "my_game.h"
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

class Page final : public browser::PageScripts {
public:
    Page(engine::Core& core, engine::UserControl& control) : core_(core), control_(control) {}
    void onKeyDown(browser::Key key) override { control_.onKeyDown(key); }
    void onAnimationFrame() override { core_.runGameLoop(); }

private:
    engine::Core& core_;
    engine::UserControl& control_;
};

}  // namespace

int main(int argc, char** argv) {
    const browser::ParsedCommandLine command_line = browser::parse_command_line(argc, argv, kStage);
    if (!command_line.options) return command_line.exit_status;
    const browser::Options& options = *command_line.options;

    browser::Window window(options);
    browser::Random random(options.seed);

    engine::Core core(window);
    engine::buildScene(core);
    engine::UserControl control(core, random);
    Page page(core, control);
    return browser::run(page, window, options);
}
