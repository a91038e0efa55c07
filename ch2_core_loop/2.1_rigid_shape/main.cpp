// The stage's index.html: the canvas and the echo panel, the engine core with its
// scene, and the user control script that every key press goes to.

#include "browser.h"
#include "core.h"
#include "my_game.h"
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
