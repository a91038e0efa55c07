// The stage's index.html: it puts the canvas and the help text on the page, loads the
// engine core and the user control script, and sends every key press to the script.
// The stage program (common/stage_main.h) does the rest: the options, the run and
// its exit statuses.

#include "core.h"
#include "stage_main.h"
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

// Chapter 1 has no engine loop yet: the page only reacts to keys, and the help text
// stands in the echo panel.
class Page final : public browser::StagePage {
public:
    Page(browser::Window& window, browser::Random& random) : core_(window.document.canvas), control_(core_, random) {
        window.document.ui_echo = kHelp;
    }
    void onKeyDown(browser::Key key) override { control_.onKeyDown(key); }
    void onAnimationFrame() override {}

private:
    engine::Core core_;
    engine::UserControl control_;
};

}  // namespace

int main(int argc, char** argv) { return browser::run_stage<Page>(argc, argv, kStage); }
