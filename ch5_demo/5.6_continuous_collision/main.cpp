// The stage's index.html: the canvas and the echo panel, the engine core with its
// scene (the book's, or one from --scene FILE), and the user control script that every
// key press goes to. With --dump FILE it also writes every body's state after every
// fixed step.

#include <cmath>
#include <iostream>
#include <optional>
#include <string>

#include "browser.h"
#include "core.h"
#include "my_game.h"
#include "scene_io.h"
#include "user_control.h"

namespace {

// The book's demo with every knob at its default, the book's engine: the pictures of
// 5.1 and 5.2. A scene file turns the knobs (docs/scene_format.md). Two seconds in, a
// box and a ball are thrown from the long slide; at five seconds H kicks every shape.
// A table, an option or a key a line, which the layout would re-wrap:
// clang-format off
const browser::StageDefaults kStage{
    .id = "s5_6",
    .title = "5.6 Continuous collision: the demo, fast shapes swept",
    .keys = "f@120 g h@300",
    .frames = 480,
    .every = 60,
    .gif = true,
    .extra_options = {
        {"--scene", "FILE", "build the world from this JSON scene file instead of the book's scene", ""},
        {"--dump", "FILE", "write every body's state after every fixed step to this CSV file", ""},
    },
    // Every key user_control.cpp reacts to, as the README lists them.
    .key_help = {
        {"0-9 up down", "select an object: by its number, the one before, the one after"},
        {"w a s d", "move the selected object 10 px up, left, down, right"},
        {"q e", "turn it -0.1 / +0.1 rad"},
        {"i k", "its velocity -1 / +1 px/s along y"},
        {"j l", "its velocity -1 / +1 px/s along x"},
        {"u o", "its angular velocity -0.1 / +0.1 rad/s"},
        {"z x", "its mass -1 / +1 (0 makes it static)"},
        {"c v", "its friction -0.01 / +0.01"},
        {"b n", "its restitution -0.01 / +0.01"},
        {"comma", "movement on / off"},
        {"m", "positional correction on / off"},
        {"y", "sleeping on / off (every change of the world, and every key that changes a shape, wakes what it touches)"},
        {"p", "continuous collision on / off"},
        {"h", "excite: a random velocity for every moving shape"},
        {"f g", "a new rectangle / circle at the selected object"},
        {"r", "reset: keep only the first seven objects"},
    },
    .overlay = "the islands, each in its colour, and each shape's rest timer as a ring; the collision info, velocities and spins, the correction, the impulses, lever arms and spin changes; the grid's cells and candidate pairs; on the sequential impulse solver its contacts: faces, points, impulses",
};
// clang-format on

class Page final : public browser::PageScripts {
public:
    Page(engine::Core& core, engine::UserControl& control) : core_(core), control_(control) {}
    void onKeyDown(browser::Key key) override { control_.onKeyDown(key); }
    void onAnimationFrame() override { core_.runGameLoop(); }
    browser::StepCost stepCost() const override { return engine::stepCost(core_); }

private:
    engine::Core& core_;
    engine::UserControl& control_;
};

// A scene's canvas size in whole pixels.
int pixels(double size) { return static_cast<int>(std::ceil(size)); }

// Runs the page, writing the state dump alongside when one is asked for: step 0 as
// built, then a row per body after every fixed step. The dump is only completed when
// the whole run succeeded. A step that leaves a number no double can be stops the run
// (exit status 3) before it draws a NaN picture; nothing is written then.
int runPage(Page& page, browser::Window& window, engine::Core& core, const browser::Options& options) {
    const std::string& dump_file = options.extra.at("--dump");
    try {
        std::optional<browser::StateDump> dump;
        if (!dump_file.empty()) {
            dump.emplace(dump_file, options.out_dir, browser::files_read(options));
            engine::dumpState(*dump, core);
        }
        core.onStep([&] {
            if (dump) engine::dumpState(*dump, core);
            engine::checkFinite(core);
        });
        const int status = browser::run(page, window, options);
        if (status == 0 && dump) dump->finish();
        return status;
    } catch (const browser::NonFiniteState& error) {
        std::cerr << error.what() << '\n';
        return 3;
    } catch (const browser::OutputRefused& error) {
        std::cerr << error.what() << '\n';
        return 2;
    } catch (const browser::FileError& error) {
        std::cerr << error.what() << '\n';
        return 1;
    }
}

}  // namespace

int main(int argc, char** argv) {
    const browser::ParsedCommandLine command_line = browser::parse_command_line(argc, argv, kStage);
    if (!command_line.options) return command_line.exit_status;
    browser::Options options = *command_line.options;

    // A scene that cannot be simulated stops the program before anything is written.
    std::optional<engine::Scene> scene;
    if (const std::string& scene_file = options.extra.at("--scene"); !scene_file.empty()) {
        try {
            scene = engine::loadScene(scene_file);
        } catch (const browser::SceneError& error) {
            std::cerr << error.what() << '\n';
            return 2;
        }
    }
    const engine::WorldSettings settings = scene ? scene->world : engine::kBookWorld;
    // The default key script was written for the book's scene; a scene file runs
    // untouched unless --keys says otherwise.
    if (scene && !options.keys_given) options.keys = browser::KeyScript();

    browser::Window window(options,
                           browser::Document{browser::Canvas(pixels(settings.width), pixels(settings.height))});
    browser::Random random(options.seed);

    engine::Core core(window, settings);
    if (scene) {
        engine::buildScene(core, scene->bodies);
    } else {
        engine::buildScene(core, random);
    }
    engine::UserControl control(core, random);
    Page page(core, control);
    return runPage(page, window, core, options);
}
