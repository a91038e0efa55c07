// The keys a stage's program declares (main.cpp's key list, which --help prints and
// key scripts and the live window are checked against) are exactly the keys its user
// control script reacts to: in a busy scene each declared key changes the page or the
// world, and every other key changes nothing at all.
#include <catch2/catch.hpp>

#include <cstddef>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "command_line.h"
#include "keys.h"
#include "page.h"
#include "random.h"
#include "stage_program.h"
#include "user_control.h"

#if __has_include("my_game.h")
#include "book_scene.h"
#include "stage_fixture.h"
#define STAGE_HAS_WORLD 1
#else
#include "core.h"
#define STAGE_HAS_WORLD 0  // chapter 1: a canvas and the user control script, no world
#endif

namespace stage_keys_test {

using browser::Key;

namespace {

// The key list --help prints: the lines after its heading, each "  KEYS  meaning",
// up to the line about the live window's own keys.
browser::KeySet declaredKeys(std::string& help) {
    test::ScratchFolder folder("stage_keys");
    const test::ProgramRun run = test::runStageProgram(folder, "--help");
    REQUIRE(run.status == 0);
    help = test::readText(folder.path / "stdout.txt");
    std::istringstream lines(help);
    std::string line;
    while (std::getline(lines, line) && line.rfind("The keys of this stage", 0) != 0) {}
    browser::KeySet keys;
    while (std::getline(lines, line) && line.rfind("  ", 0) == 0) {
        const std::size_t gap = line.find("  ", 2);
        REQUIRE(gap != std::string::npos);
        keys.add(browser::KeySet::parse(line.substr(2, gap - 2)));
    }
    return keys;
}

struct Observed {
    browser::Image page;  // the canvas and the echo panel
    std::size_t objects = 0, selected = 0;
    friend bool operator==(const Observed& a, const Observed& b) {
        return a.page.rgba == b.page.rgba && a.objects == b.objects && a.selected == b.selected;
    }
};

#if STAGE_HAS_WORLD
// The book's scene with at least twelve objects (spawned by F and G), the
// next-to-last selected: a shape that moves, neither the first nor the last, with
// more objects than a reset keeps and than the digits reach. Then `key`, if any,
// and two frames (so a fixed step surely ran).
Observed after(std::optional<Key> key) {
    test::StageFixture stage;
    test::buildBookScene(stage.core, stage.random);
    stage.frame();
    while (stage.core.objectCount() < 12) stage.press(stage.core.objectCount() % 2 == 0 ? Key::F : Key::G);
    stage.core.select(stage.core.objectCount() - 2);
    stage.frame();
    if (key) stage.press(*key);
    stage.frame();
    stage.frame();
    return {browser::render_page(stage.window.document), stage.core.objectCount(), stage.core.selectedIndex()};
}
#else
// Chapter 1 draws on key presses only: the canvas after a few shapes and then `key`.
Observed after(std::optional<Key> key) {
    browser::Canvas canvas;
    browser::Random random(1);
    engine::Core core(canvas);
    engine::UserControl control(core, random);
    control.onKeyDown(Key::F);
    control.onKeyDown(Key::G);
    if (key) control.onKeyDown(*key);
    return {canvas.pixels()};
}
#endif

}  // namespace

TEST_CASE("stage keys: the declared keys are the ones the user control script reacts to") {
    std::string help;
    const browser::KeySet declared = declaredKeys(help);
    INFO("declared: " << declared.text());
    REQUIRE_FALSE(declared.empty());
    const Observed untouched = after(std::nullopt);
    for (int k = 0; k < browser::kKeyCount; ++k) {
        const Key key = static_cast<Key>(k);
        INFO("key " << browser::key_name(key) << (declared.contains(key) ? " (declared)" : " (not declared)"));
        // The overlay key is the browser's, not the user control script's: the feature
        // test overlay_key checks what it does.
        if (key == browser::kOverlayKey && declared.contains(key)) continue;
        CHECK((after(key) == untouched) != declared.contains(key));
    }
}

TEST_CASE("stage keys: a key script pressing any other key is refused, nothing written") {
    std::string help;
    const browser::KeySet declared = declaredKeys(help);
    for (int k = 0; k < browser::kKeyCount; ++k) {
        const Key key = static_cast<Key>(k);
        if (declared.contains(key)) continue;
        INFO("key " << browser::key_name(key));
        test::ScratchFolder folder("stage_keys");
        const std::string out = (folder.path / "out").string();
        const test::ProgramRun run = test::runStageProgram(
            folder, "--frames 2 --out '" + out + "' --keys 'f@0 " + browser::key_name(key) + "@1'");
        CHECK(run.status == 2);
        CHECK(run.error_text == std::string(STAGE_PROGRAM).substr(std::string(STAGE_PROGRAM).rfind('/') + 1) +
                                    ": --keys: \"" + browser::key_name(key) +
                                    "\" is not a key of this stage (its keys: " + declared.text() + ")\n");
        CHECK(folder.files() == std::vector<std::string>{"stderr.txt", "stdout.txt"});
    }
}

}  // namespace stage_keys_test
