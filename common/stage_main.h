#pragma once
// The stage program: what every stage's main() does, written once. A stage's main.cpp
// is its index.html: the stage's table (StageDefaults: title, default run, keys), and a
// Page that holds the engine core with its scene and the user control script every key
// press goes to. Everything else is here:
//   - the command line (command_line.h), with --scene FILE and --dump FILE for a stage
//     that reads scene files;
//   - the scene file, read by the stage's own vocabulary (scene_file.h) before anything
//     is drawn, its world's canvas size for the page, and a run that starts untouched
//     (no default key script) unless --keys says otherwise;
//   - the state dump (state_dump.h) after every fixed step, and the check that every
//     number of the world is still a number;
//   - the files of lines a stage writes beside the dump, each named by an option of its
//     own (StepLog: the collision events' --events FILE), under the dump's discipline (output_file.h);
//   - the run's budget (browser.h), from what the stage says its world costs;
//   - the run itself (browser::run), and the exit statuses: 0; 1 a file that cannot be
//     written; 2 a bad option, a refused scene or run, a place that may not be written;
//     3 a step left a number that is not finite; 4 out of memory.
//
// What a stage adds, it hands in through hooks: its page's world (PageWorld, usually
// made by its page_world.cpp), and, for scene files, how it reads one (SceneFiles, its
// scene_io.h).
//
//   class Page final : public browser::StagePage {
//   public:
//       Page(browser::Window& window, browser::Random& random) : core_(window), control_(core_, random) {
//           engine::buildScene(core_);
//       }
//       void onKeyDown(browser::Key key) override { control_.onKeyDown(key); }
//       void onAnimationFrame() override { core_.runGameLoop(); }
//       browser::PageWorld world() override { return engine::pageWorld(core_); }
//   ...
//   int main(int argc, char** argv) { return browser::run_stage<Page>(argc, argv, kStage); }

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "browser.h"
#include "command_line.h"
#include "keys.h"
#include "page_scripts.h"
#include "random.h"
#include "scene_file.h"
#include "state_dump.h"
#include "vec2.h"

namespace browser {

// One object of the world as --dump writes it, and as the finiteness check reads it.
struct ObjectState {
    std::string_view kind;  // the word the stage's scene files use for its kind, a plain word
    // Who the object is, in a stage whose objects have an identity that never changes
    // and is never given twice; the dump writes it beside the index (state_dump.h).
    std::optional<std::uint64_t> id;
    lib::Vec2 center;
    double angle = 0.0;  // rad
    lib::Vec2 velocity;
    double angular_velocity = 0.0;  // rad/s
};

// A file of lines a stage writes after every fixed step, beside the dump: what the
// world told in that step (the collision events of a stage that tells them, --events FILE). The harness opens it
// when its option names a file, writes `header` and then, after every fixed step, what
// `append` adds; it completes it only when the whole run succeeded (output_file.h).
struct StepLog {
    std::string option;                        // the option that names the file: one of the stage's extra_options
    std::string what;                          // what the file is, for messages: "cannot write <what> FILE: ..."
    std::string header;                        // its first line, without the line end
    std::function<void()> start;               // called once, before step 0, when the file is asked for
    std::function<void(std::string&)> append;  // appends the lines of the step just run, each ended by '\n'
};

// What the harness sees of a page's world. Each part may be left empty: a page with no
// world stepping in fixed steps (the first chapter's) has none, and only a stage with scene files dumps.
struct PageWorld {
    std::function<long()> steps;                         // the fixed steps run so far
    std::function<std::vector<ObjectState>()> objects;   // every object now, in list order
    std::function<void(std::function<void()>)> on_step;  // calls its argument after every fixed step
    std::function<WorldCost(const KeyScript&)> cost;     // what a run with these keys may cost
    std::vector<StepLog> logs;                           // the files of lines it can write, if any
};

// A stage's page: the book's two callbacks (PageScripts), and its world.
class StagePage : public PageScripts {
public:
    virtual PageWorld world() { return {}; }
};

// How a stage reads its scene files (its scene_io.h): a scene of its own type, and the
// canvas the scene's world asks for (nullptr: the stage's own scene, the book's).
template <class Scene>
struct SceneFiles {
    Scene (*load)(const std::filesystem::path& file);         // throws SceneError with one line
    std::pair<double, double> (*canvas)(const Scene* scene);  // width and height, px
};

// The last guard against a world beyond what the engine can compute: throws
// NonFiniteState naming the first object whose position or velocity is not a finite
// number.
void check_finite(const PageWorld& world);

// Runs `page` in `window` (browser::run) with its world's budget, dump and finiteness
// check. Returns the exit status.
int run_stage_page(StagePage& page, Window& window, const Options& options);

// The command line of a stage, with --scene FILE and --dump FILE added when it reads
// scene files.
ParsedCommandLine parse_stage_command_line(int argc, const char* const* argv, StageDefaults stage, bool scene_files);

// A stage's window, its canvas `canvas` px (rounded up to whole pixels) at --scale.
Window stage_window(const Options& options, std::pair<double, double> canvas);

// Prints a refused scene's one line; returns the exit status 2.
int scene_refused(const SceneError& error);

// A stage without scene files: its Page is made as Page(Window&, Random&).
template <class Page>
int run_stage(int argc, char** argv, const StageDefaults& stage) {
    const ParsedCommandLine command_line = parse_stage_command_line(argc, argv, stage, false);
    if (!command_line.options) return command_line.exit_status;
    const Options& options = *command_line.options;
    Window window(options);
    Random random(options.seed);
    Page page(window, random);
    return run_stage_page(page, window, options);
}

// A stage with scene files: its Page is made as Page(Window&, Random&, const Scene*),
// with the scene of --scene FILE, or nullptr for its own.
template <class Page, class Scene>
int run_stage(int argc, char** argv, const StageDefaults& stage, const SceneFiles<Scene>& files) {
    const ParsedCommandLine command_line = parse_stage_command_line(argc, argv, stage, true);
    if (!command_line.options) return command_line.exit_status;
    Options options = *command_line.options;
    // A scene that cannot be simulated stops the program before anything is written.
    std::optional<Scene> scene;
    if (const std::string& file = options.extra.at("--scene"); !file.empty()) {
        try {
            scene = files.load(file);
        } catch (const SceneError& error) {
            return scene_refused(error);
        }
        // The default key script was written for the stage's own scene; a scene file
        // runs untouched unless --keys says otherwise.
        if (!options.keys_given) options.keys = KeyScript();
    }
    const Scene* chosen = scene ? &*scene : nullptr;
    Window window = stage_window(options, files.canvas(chosen));
    Random random(options.seed);
    Page page(window, random, chosen);
    return run_stage_page(page, window, options);
}

}  // namespace browser
