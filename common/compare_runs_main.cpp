// compare_runs PROGRAM SCENE LEFT RIGHT [--out DIR] [--crop X,Y,W,H] [--ghost FRAME] [-- OPTION...]
//
// Two settings of one scene, side by side, with one command. LEFT and RIGHT are JSON
// objects of world keys ('{"dt": 0.01}'), each laid over the scene file's
// "world". The stage PROGRAM runs twice, unchanged, once per setting, with the same
// OPTIONs (--frames, --every, --keys, --seed, --scale, ...); then every picture both
// runs wrote is joined, the left run's canvas beside the right one's, each under its
// setting. Nothing is simulated here: each half is exactly what the program draws for
// that scene, and the folder keeps the evidence:
//   DIR/left.json, DIR/right.json   the two scenes that ran
//   DIR/left/, DIR/right/           the two runs' own pictures
//   DIR/final.png, DIR/frame_NNNN.png   the joined pictures
//   DIR/animation.gif               the joined frames, when there are two or more and
//                                   the OPTIONs do not say --no-gif
// With --crop X,Y,W,H each half shows only that part of its canvas (in canvas
// pixels, so --scale zooms into it). With --ghost each joined picture also shows the first frame faintly under it
// (needs --every), so that whatever moved since the start shows twice. With --trail each
// joined picture shows every earlier frame the runs saved faintly under it (the final
// picture: every frame), so a moving shape shows once a saved frame: several exposures
// in one picture.
// Exit status: 0 done; 2 refused before anything was written (a bad option, a scene or
// setting that is not a JSON object, a setting the program refuses: its one line is
// repeated); 1 a picture could not be written; a run's own status when it failed
// otherwise (3: a number that is not finite).

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "gif_writer.h"
#include "message_text.h"
#include "output_folder.h"
#include "png_io.h"
#include "side_by_side.h"

extern char** environ;

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

constexpr const char* kProgram = "compare_runs";
constexpr int kRefused = 2, kWriteFailed = 1;
constexpr double kBookFrameMs = 1000.0 / 60.0;

// A refusal or failure with its exit status; main prints the one line.
struct Stop {
    int status;
    std::string line;
};

struct Request {
    fs::path program, scene, out = "out/compare";
    std::string settings[2];
    std::optional<int> ghost;          // the frame drawn faintly under every picture
    bool trail = false;                // every earlier saved frame drawn faintly under each picture
    std::vector<int> crop;             // x, y, width, height in canvas pixels; empty: the whole canvas
    std::vector<std::string> options;  // for the program, after --
};

struct Side {
    const char* name;  // "left", "right": the file and folder names
    std::string setting;
};

// The options this tool sets itself, or that would make a run write no pictures.
const std::vector<std::string> kOwnOptions = {"--out", "--scene", "--live", "--record", "--dump", "--help"};

std::optional<std::string> option_value(const std::vector<std::string>& options, const std::string& name) {
    for (std::size_t i = 0; i < options.size(); ++i) {
        if (options[i] == name && i + 1 < options.size()) return options[i + 1];
        if (options[i].starts_with(name + "=")) return options[i].substr(name.size() + 1);
    }
    return std::nullopt;
}

json read_json(const fs::path& file, const std::string& what) {
    std::ifstream in(file);
    if (!in) throw Stop{kRefused, "cannot read " + what + " " + browser::in_quotes(file.string())};
    json value = json::parse(in, nullptr, false);
    if (!value.is_object())
        throw Stop{kRefused, what + " " + browser::in_quotes(file.string()) + " is not a JSON object"};
    return value;
}

// The scene with `setting`'s keys laid over its "world".
json scene_with(json scene, const std::string& setting, const std::string& side) {
    const json keys = json::parse(setting, nullptr, false);
    if (!keys.is_object()) {
        throw Stop{kRefused, "the " + side + " setting " + browser::in_quotes(setting) +
                                 " is not a JSON object of world keys, e.g. '{\"dt\": 0.01}'"};
    }
    if (!scene.contains("world")) scene["world"] = json::object();
    for (const auto& [key, value] : keys.items()) scene["world"][key] = value;
    return scene;
}

std::string first_line(const fs::path& file) {
    std::ifstream in(file);
    std::string line;
    std::getline(in, line);
    return line;
}

// Runs the program on one side's scene into folder/<side>/, its output kept in files
// beside it; a failed run stops the comparison with the run's own line.
void run_side(const Request& request, const Side& side, const fs::path& folder) {
    const fs::path scene = folder / (std::string(side.name) + ".json");
    const fs::path said = folder / (std::string(side.name) + ".stdout");
    const fs::path complaint = folder / (std::string(side.name) + ".stderr");
    std::vector<std::string> args = {request.program.string(), "--scene", scene.string(), "--out",
                                     (folder / side.name).string()};
    args.insert(args.end(), request.options.begin(), request.options.end());
    std::vector<char*> argv;
    for (std::string& arg : args) argv.push_back(arg.data());
    argv.push_back(nullptr);

    posix_spawn_file_actions_t files;
    posix_spawn_file_actions_init(&files);
    posix_spawn_file_actions_addopen(&files, 1, said.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawn_file_actions_addopen(&files, 2, complaint.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    pid_t child = 0;
    const int spawned = posix_spawn(&child, argv[0], &files, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&files);
    if (spawned != 0) throw Stop{kRefused, "cannot run " + browser::in_quotes(request.program.string())};
    int wait_status = 0;
    waitpid(child, &wait_status, 0);
    const int status = WIFEXITED(wait_status) ? WEXITSTATUS(wait_status) : 128 + WTERMSIG(wait_status);
    fs::remove(said);
    if (status != 0) {
        // The program's own line, made printable by it already; the scene it names is
        // the staging copy, which is gone with the refusal, so it is named by its side.
        std::string line = first_line(complaint);
        if (const std::size_t at = line.find(scene.string()); at != std::string::npos) {
            line.replace(at, scene.string().size(), scene.filename().string());
        }
        throw Stop{status,
                   "the " + std::string(side.name) + " run (" + browser::printable(side.setting) + "): " + line};
    }
    fs::remove(complaint);
}

// The PNG pictures both runs wrote, by name, in order: final.png and frame_NNNN.png.
std::vector<std::string> shared_pictures(const fs::path& left, const fs::path& right) {
    std::vector<std::string> names;
    for (const fs::directory_entry& entry : fs::directory_iterator(left)) {
        const std::string name = entry.path().filename().string();
        const bool page = name == "final.png" || (name.starts_with("frame_") && name.ends_with(".png"));
        if (page && fs::exists(right / name)) names.push_back(name);
    }
    std::sort(names.begin(), names.end());
    return names;
}

int frame_number(const std::string& name) { return std::atoi(name.c_str() + 6); }

// A saved frame's number and its canvas, for --trail.
struct Frame {
    int number;
    browser::Image canvas;
};

// The frames both runs saved, as the run whose folder is `side` drew them, in order.
std::vector<Frame> savedFrames(const fs::path& left, const fs::path& right, const fs::path& side, int scale) {
    std::vector<Frame> frames;
    for (const std::string& name : shared_pictures(left, right)) {
        if (name != "final.png")
            frames.push_back({frame_number(name), browser::canvas_of(browser::read_png(side / name), scale)});
    }
    return frames;
}

std::string frame_picture_name(int frame) {
    char name[32];
    std::snprintf(name, sizeof name, "frame_%04d.png", frame);
    return name;
}

void compare(const Request& request) {
    for (const std::string& option : request.options) {
        for (const std::string& own : kOwnOptions) {
            if (option == own || option.starts_with(own + "=")) {
                throw Stop{kRefused, own + " is " + kProgram + "'s to set; give the program's picture options only"};
            }
        }
    }
    int scale = 1;
    if (const auto text = option_value(request.options, "--scale")) scale = std::max(std::atoi(text->c_str()), 1);
    double frame_ms = kBookFrameMs;
    if (const auto text = option_value(request.options, "--frame-ms")) frame_ms = std::atof(text->c_str());

    const json scene = read_json(request.scene, "the scene");
    const Side sides[2] = {{"left", request.settings[0]}, {"right", request.settings[1]}};
    const json scenes[2] = {scene_with(scene, sides[0].setting, "left"), scene_with(scene, sides[1].setting, "right")};

    const fs::path out = browser::OutputFolder::normalized(request.out);
    // The files the runs read: the folder may not hold them.
    const fs::path inputs[] = {request.program, request.scene};
    browser::OutputFolder folder(out, inputs);
    for (int i = 0; i < 2; ++i) {
        std::ofstream(folder.staging() / (std::string(sides[i].name) + ".json")) << scenes[i].dump(2) << '\n';
        run_side(request, sides[i], folder.staging());
    }

    const fs::path left = folder.staging() / "left", right = folder.staging() / "right";
    std::optional<browser::Image> starts[2];
    if (request.ghost) {
        const std::string name = frame_picture_name(*request.ghost);
        if (!fs::exists(left / name)) {
            throw Stop{kRefused, "--ghost " + std::to_string(*request.ghost) +
                                     ": no picture of that frame; give the program an --every K that divides it"};
        }
        starts[0] = browser::canvas_of(browser::read_png(left / name), scale);
        starts[1] = browser::canvas_of(browser::read_png(right / name), scale);
    }
    const std::vector<Frame> saved[2] = {request.trail ? savedFrames(left, right, left, scale) : std::vector<Frame>{},
                                         request.trail ? savedFrames(left, right, right, scale) : std::vector<Frame>{}};
    std::vector<std::string> frames;
    for (const std::string& name : shared_pictures(left, right)) {
        browser::Image halves[2];
        for (int i = 0; i < 2; ++i) {
            halves[i] = browser::canvas_of(browser::read_png(folder.staging() / sides[i].name / name), scale);
            if (starts[i]) halves[i] = browser::with_start_ghost(halves[i], *starts[i]);
            for (const Frame& frame : saved[i]) {
                if (name == "final.png" || frame.number < frame_number(name)) {
                    halves[i] = browser::with_start_ghost(halves[i], frame.canvas);
                }
            }
            if (!request.crop.empty()) {
                halves[i] = browser::cropped(halves[i], request.crop[0] * scale, request.crop[1] * scale,
                                             request.crop[2] * scale, request.crop[3] * scale);
            }
        }
        browser::write_png(folder.staging() / name,
                           browser::side_by_side(halves[0], sides[0].setting, halves[1], sides[1].setting));
        if (name != "final.png") frames.push_back(name);
    }
    // --no-gif goes to both runs, and it holds for the joined frames too.
    const bool no_gif = std::find(request.options.begin(), request.options.end(), "--no-gif") != request.options.end();
    const bool gif = frames.size() >= 2 && browser::gif_supported() && !no_gif;
    if (gif) {
        const int every = frame_number(frames[1]) - frame_number(frames[0]);
        const browser::Image first = browser::read_png(folder.staging() / frames[0]);
        browser::GifWriter gif(folder.staging() / "animation.gif", first.width, first.height,
                               browser::gif_delay_centiseconds(frame_ms, every));
        for (const std::string& name : frames) gif.add(browser::read_png(folder.staging() / name));
        gif.close();
    }
    folder.commit();
    std::cout << "wrote " << (out / "").string() << ": " << frames.size() + 1 << " joined pictures"
              << (gif ? " and animation.gif" : "") << " (left " << request.settings[0] << ", right "
              << request.settings[1] << ")\n";
}

}  // namespace

int main(int argc, char** argv) {
    Request request;
    CLI::App app{
        "Runs a stage program on one scene with two settings of its world keys and joins "
        "their pictures side by side, each half labelled with its setting.",
        kProgram};
    app.add_option("PROGRAM", request.program, "the stage program, e.g. build/sX_Y_name")->required();
    app.add_option("SCENE", request.scene, "the scene file both runs start from")->required();
    app.add_option("LEFT", request.settings[0], "world keys for the left run, as a JSON object")->required();
    app.add_option("RIGHT", request.settings[1], "world keys for the right run, as a JSON object")->required();
    app.add_option("--out", request.out, "where the joined pictures go")->capture_default_str();
    app.add_option("--ghost", request.ghost, "draw this frame's picture faintly under each one (a frame --every saves)")
        ->type_name("FRAME")
        ->check(CLI::NonNegativeNumber);
    app.add_flag(
        "--trail", request.trail,
        "draw every earlier frame the runs saved (--every) faintly under each picture: several exposures in one");
    app.add_option("--crop", request.crop, "show only this part of each canvas, in canvas pixels")
        ->type_name("X,Y,W,H")
        ->delimiter(',')
        ->expected(4)
        ->check(CLI::NonNegativeNumber);
    app.add_option("OPTIONS", request.options, "after --: the program's options for both runs");
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& error) {
        if (error.get_exit_code() == 0) return app.exit(error);  // --help
        std::cerr << kProgram << ": " << browser::printable(error.what()) << " (see " << kProgram << " --help)\n";
        return kRefused;
    }
    try {
        compare(request);
        return 0;
    } catch (const Stop& stop) {
        std::cerr << kProgram << ": " << stop.line << '\n';
        return stop.status;
    } catch (const browser::OutputRefused& error) {
        std::cerr << kProgram << ": cannot write to " << browser::in_quotes(request.out.string()) << ": "
                  << error.what() << '\n';
        return kRefused;
    } catch (const browser::FileError& error) {
        std::cerr << kProgram << ": " << error.what() << '\n';
        return kWriteFailed;
    } catch (const fs::filesystem_error& error) {
        std::cerr << kProgram << ": " << error.code().message() << '\n';
        return kWriteFailed;
    }
}
