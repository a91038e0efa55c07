// The stage's index.html: it puts the canvas and the help text on the page, loads the
// engine core and the user control script, and sends every key press to the script.

#include "browser.h"
#include "core.h"
#include "user_control.h"

namespace {

// A table, an option or a key a line, which the layout would re-wrap:
// clang-format off
const browser::StageDefaults kStage{
    .id = "s1_1",
    .title = "1.1 HTML5 Canvas: the drawing core and the user control script",
    .keys = "f g f g f g f g f f g",
    .frames = 1,
    .every = 0,
    // Every key user_control.cpp reacts to, as the README lists them.
    .key_help = {
        {"f", "draw a random rectangle"},
        {"g", "draw a random circle"},
    },
};
// clang-format on

constexpr const char* kHelp =
    "HTML5 Canvas project\n"
    "\n"
    "Control:\n"
    "  F: draw a random rectangle\n"
    "  G: draw a random circle\n";

// Chapter 1 has no engine loop yet: the page only reacts to keys.
class Page final : public browser::PageScripts {
public:
    explicit Page(engine::UserControl& control) : control_(control) {}
    void onKeyDown(browser::Key key) override { control_.onKeyDown(key); }
    void onAnimationFrame() override {}

private:
    engine::UserControl& control_;
};

}  // namespace

int main(int argc, char** argv) {
    const browser::ParsedCommandLine command_line = browser::parse_command_line(argc, argv, kStage);
    if (!command_line.options) return command_line.exit_status;
    const browser::Options& options = *command_line.options;

    browser::Window window(options);
    window.document.ui_echo = kHelp;
    browser::Random random(options.seed);

    engine::Core core(window.document.canvas);
    engine::UserControl control(core, random);
    Page page(control);
    return browser::run(page, window, options);
}
