#include "stage_main.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <list>
#include <optional>
#include <string>

#include "output_file.h"
#include "png_io.h"  // FileError, OutputRefused
#include "state_dump.h"
#include "write_guard.h"

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

namespace {

// The file an option names, "" when the option is not given.
std::string option_file(const Options& options, const std::string& option) {
    const auto found = options.extra.find(option);
    return found == options.extra.end() ? std::string() : found->second;
}

// One file of lines being written, with the log that fills it.
struct OpenLog {
    OpenLog(const StepLog& log, const std::string& file, const Options& options)
        : log(log), file(file, log.what, options.out_dir, files_read(options)) {}
    const StepLog& log;
    OutputFile file;
};

// Two of the run's files under one name would write over each other: refused before
// either is opened.
void refuse_shared_names(const std::vector<std::pair<std::string, std::string>>& files) {
    for (std::size_t i = 0; i < files.size(); ++i) {
        for (std::size_t j = 0; j < i; ++j) {
            if (resolved(files[i].second) == resolved(files[j].second)) {
                throw OutputRefused("cannot write " + files[i].first + " " + files[i].second + ": it is also the " +
                                    files[j].first + "; name each file the run writes otherwise");
            }
        }
    }
}

}  // namespace

// Runs the page, writing the state dump and the stage's logs alongside when they are
// asked for: step 0 as built, then after every fixed step. They are only completed when
// the whole run succeeded. A step that leaves a number no double can be stops the run
// (exit status 3) before it draws a NaN picture; nothing is written then.
int run_stage_page(StagePage& page, Window& window, const Options& options) {
    const PageWorld world = page.world();
    const WorldCost cost = world.cost ? world.cost(options.keys) : WorldCost{};
    const std::string dump_file = option_file(options, "--dump");
    try {
        std::vector<std::pair<std::string, std::string>> named;  // what, file
        if (!dump_file.empty()) named.emplace_back("state dump", dump_file);
        for (const StepLog& log : world.logs) {
            if (const std::string file = option_file(options, log.option); !file.empty()) {
                named.emplace_back(log.what, file);
            }
        }
        refuse_shared_names(named);

        std::optional<StateDump> dump;
        if (!dump_file.empty()) {
            dump.emplace(dump_file, options.out_dir, files_read(options));
            dump_state(*dump, world);
        }
        std::list<OpenLog> logs;  // a list: an OutputFile never moves
        for (const StepLog& log : world.logs) {
            const std::string file = option_file(options, log.option);
            if (file.empty()) continue;
            OpenLog& open = logs.emplace_back(log, file, options);
            open.file.write(log.header + "\n");
            if (log.start) log.start();
        }
        if (world.on_step && world.objects) {
            world.on_step([&] {
                if (dump) dump_state(*dump, world);
                std::string lines;
                for (OpenLog& open : logs) {
                    lines.clear();
                    open.log.append(lines);
                    open.file.write(lines);
                }
                check_finite(world);
            });
        }
        const int status = run(page, window, options, cost);
        if (status == 0) {
            if (dump) dump->finish();
            for (OpenLog& open : logs) open.file.finish();
        }
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
