#include "stage_main.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <optional>
#include <string>

#include "png_io.h"  // FileError, OutputRefused
#include "state_dump.h"

namespace browser {

namespace {

bool finite(const ObjectState& object) {
    const double numbers[] = {object.center.x,   object.center.y,   object.angle,
                              object.velocity.x, object.velocity.y, object.angular_velocity};
    return std::all_of(std::begin(numbers), std::end(numbers), [](double v) { return std::isfinite(v); });
}

}  // namespace

void check_finite(const PageWorld& world) {
    const std::vector<ObjectState> objects = world.objects();
    for (std::size_t i = 0; i < objects.size(); ++i) {
        if (!finite(objects[i])) throw NonFiniteState(world.steps(), i, objects[i].kind);
    }
}

namespace {

// One row per object for the world's current step (0 before any).
void dump_state(StateDump& dump, const PageWorld& world) {
    const long step = world.steps();
    const std::vector<ObjectState> objects = world.objects();
    for (std::size_t i = 0; i < objects.size(); ++i) {
        const ObjectState& object = objects[i];
        if (object.id) {
            dump.row(step, i, *object.id, object.kind, object.center, object.angle, object.velocity,
                     object.angular_velocity);
        } else {
            dump.row(step, i, object.kind, object.center, object.angle, object.velocity, object.angular_velocity);
        }
    }
}

}  // namespace

int scene_refused(const SceneError& error) {
    std::cerr << error.what() << '\n';
    return 2;
}

ParsedCommandLine parse_stage_command_line(int argc, const char* const* argv, StageDefaults stage, bool scene_files) {
    if (scene_files) {
        stage.extra_options.push_back(
            {"--scene", "FILE", "build the world from this JSON scene file instead of the book's scene", ""});
        stage.extra_options.push_back(
            {"--dump", "FILE", "write every body's state after every fixed step to this CSV file", ""});
    }
    return parse_command_line(argc, argv, stage);
}

Window stage_window(const Options& options, std::pair<double, double> canvas) {
    const auto pixels = [](double size) { return static_cast<int>(std::ceil(size)); };
    return Window(options, Document{Canvas(pixels(canvas.first), pixels(canvas.second))});
}

// Runs the page, writing the state dump alongside when one is asked for: step 0 as
// built, then a row per object after every fixed step. The dump is only completed when
// the whole run succeeded. A step that leaves a number no double can be stops the run
// (exit status 3) before it draws a NaN picture; nothing is written then.
int run_stage_page(StagePage& page, Window& window, const Options& options) {
    const PageWorld world = page.world();
    const WorldCost cost = world.cost ? world.cost(options.keys) : WorldCost{};
    const auto dump_option = options.extra.find("--dump");
    const std::string dump_file = dump_option == options.extra.end() ? std::string() : dump_option->second;
    try {
        std::optional<StateDump> dump;
        if (!dump_file.empty()) {
            dump.emplace(dump_file, options.out_dir, files_read(options));
            dump_state(*dump, world);
        }
        if (world.on_step && world.objects) {
            world.on_step([&] {
                if (dump) dump_state(*dump, world);
                check_finite(world);
            });
        }
        const int status = run(page, window, options, cost);
        if (status == 0 && dump) dump->finish();
        return status;
    } catch (const NonFiniteState& error) {
        std::cerr << error.what() << '\n';
        return 3;
    } catch (const OutputRefused& error) {
        std::cerr << error.what() << '\n';
        return 2;
    } catch (const FileError& error) {
        std::cerr << error.what() << '\n';
        return 1;
    }
}

}  // namespace browser
