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
// repeated; a crop off the canvas); 1 a picture could not be written; a run's own status
// when it failed otherwise (3: a number that is not finite); 130 or 143 when SIGINT or
// SIGTERM ended it (the runs are stopped, nothing is written, an old DIR stays as it was).
// The scene is read as the stage programs read one (docs/scene_format.md: a regular file
// of at most 2 MiB, nested at most five levels deep), a setting likewise.

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <time.h>

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <new>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "gif_writer.h"
#include "input_file.h"
#include "interruption.h"
#include "message_text.h"
#include "output_folder.h"
#include "png_io.h"
#include "scene_file.h"  // kMaxSceneBytes, kMaxNesting: a scene as the stages read one
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
    std::vector<long long> crop;       // x, y, width, height in canvas pixels; empty: the whole canvas
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

// How deep `text` nests, read without building anything: false as soon as it goes
// deeper than `most` levels (nlohmann's parser keeps its nesting on the heap, but
// writing and freeing a document recurse as deep as it goes).
class NestingCheck final : public json::json_sax_t {
public:
    explicit NestingCheck(std::size_t most) : most_(most) {}
    bool too_deep = false;

    bool null() override { return true; }
    bool boolean(bool) override { return true; }
    bool number_integer(number_integer_t) override { return true; }
    bool number_unsigned(number_unsigned_t) override { return true; }
    bool number_float(number_float_t, const string_t&) override { return true; }
    bool string(string_t&) override { return true; }
    bool binary(binary_t&) override { return true; }
    bool key(string_t&) override { return true; }
    bool start_object(std::size_t) override { return open(); }
    bool start_array(std::size_t) override { return open(); }
    bool end_object() override { return close(); }
    bool end_array() override { return close(); }
    bool parse_error(std::size_t, const std::string&, const json::exception&) override { return false; }

private:
    bool open() {
        too_deep = ++depth_ > most_;
        return !too_deep;
    }
    bool close() {
        --depth_;
        return true;
    }
    std::size_t most_;
    std::size_t depth_ = 0;
};

// `text` as a JSON object nested at most `most` levels; nothing when it is JSON but no
// object. Throws Stop (refused) naming `what`: `deep_line` when it nests deeper, the
// parser's reason (its "[json.exception...]" and "last read" left out) when it is not JSON.
std::optional<json> json_object(const std::string& text, std::size_t most, const std::string& what,
                                const std::string& deep_line) {
    NestingCheck check(most);
    json::sax_parse(text, &check);
    if (check.too_deep) throw Stop{kRefused, deep_line};
    json value;
    try {
        value = json::parse(text);
    } catch (const json::exception& error) {
        std::string_view reason = error.what();
        if (const std::size_t bracket = reason.find("] "); bracket != std::string_view::npos)
            reason.remove_prefix(bracket + 2);
        reason = reason.substr(0, reason.find("; last read"));
        throw Stop{kRefused, what + " is not JSON (" + browser::first_words(reason, browser::kLongestShown) + ")"};
    }
    if (!value.is_object()) return std::nullopt;
    return value;
}

json read_scene(const fs::path& file) {
    std::string text;
    try {
        text = browser::read_whole_file(file, browser::kMaxSceneBytes);
    } catch (const browser::FileError& error) {
        throw Stop{kRefused, std::string("the scene ") + error.what()};
    }
    const std::string named = "the scene " + browser::in_quotes(file.string());
    std::optional<json> scene = json_object(
        text, browser::kMaxNesting, named,
        named + " is nested deeper than a scene can be (" + std::to_string(browser::kMaxNesting) + " levels)");
    if (!scene) throw Stop{kRefused, named + " is not a JSON object"};
    return *scene;
}

// The scene with `setting`'s keys laid over its "world". A world key's value goes two
// levels below the scene's top, so a setting may nest two levels less than a scene.
json scene_with(json scene, const std::string& setting, const std::string& side) {
    const std::string named = "the " + side + " setting " + browser::in_quotes(setting);
    if (setting.size() > browser::kMaxSceneBytes) {
        throw Stop{kRefused, "the " + side + " setting is longer than a scene file may be"};
    }
    const std::size_t most = browser::kMaxNesting - 1;
    const std::optional<json> keys = json_object(
        setting, most, named, named + " is nested deeper than world keys go (" + std::to_string(most) + " levels)");
    if (!keys) throw Stop{kRefused, named + " is not a JSON object of world keys, e.g. '{\"dt\": 0.01}'"};
    if (!scene.contains("world")) scene["world"] = json::object();
    for (const auto& [key, value] : keys->items()) scene["world"][key] = value;
    return scene;
}

std::string first_line(const fs::path& file) {
    std::ifstream in(file);
    std::string line;
    std::getline(in, line);
    return line;
}

// Waits for the run to end. SIGINT or SIGTERM to this program (noted since the output
// folder was made, interruption.h) is passed on to the run; once the run has ended, this
// program removes its staging folder and ends by the same signal. Sent to the whole
// group (Ctrl-C), the run has it already, and the second one ends it at once.
int wait_for(pid_t child) {
    for (;;) {
        int wait_status = 0;
        const pid_t ended = ::waitpid(child, &wait_status, WNOHANG);
        if (ended == child) {
            browser::stop_if_interrupted();
            return wait_status;
        }
        if (ended < 0 && errno != EINTR) throw Stop{kWriteFailed, "lost track of a run of the program"};
        if (const int signal = browser::pending_interruption(); signal != 0) {
            ::kill(child, signal);
            while (::waitpid(child, &wait_status, 0) < 0 && errno == EINTR) {}
            browser::end_by_interruption(signal);
        }
        // A signal cuts the pause short.
        const timespec pause{.tv_sec = 0, .tv_nsec = 10'000'000};
        ::nanosleep(&pause, nullptr);
    }
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
    const int wait_status = wait_for(child);
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

int frame_number(const std::string& name) { return std::atoi(name.c_str() + 6); }

// The PNG pictures both runs wrote, by name: frame_NNNN.png in the order of their frames
// (past frame 9999 the names grow a digit), then final.png, which shows the last.
std::vector<std::string> shared_pictures(const fs::path& left, const fs::path& right) {
    std::vector<std::string> frames;
    bool final_picture = false;
    for (const fs::directory_entry& entry : fs::directory_iterator(left)) {
        const std::string name = entry.path().filename().string();
        if (!browser::is_picture_name(name) || !name.ends_with(".png") || !fs::exists(right / name)) continue;
        if (name == browser::kFinalPicture) final_picture = true;
        else if (name.starts_with("frame_")) frames.push_back(name);
    }
    std::sort(frames.begin(), frames.end(),
              [](const std::string& a, const std::string& b) { return frame_number(a) < frame_number(b); });
    if (final_picture) frames.push_back(browser::kFinalPicture);
    return frames;
}

std::string frame_picture_name(int frame) {
    char name[32];
    std::snprintf(name, sizeof name, "frame_%04d.png", frame);
    return name;
}

// --crop's text: four whole numbers, none negative, the width and height at least 1;
// none larger than kLargestCrop, far beyond any canvas, so that no sum of them overflows.
constexpr long long kLargestCrop = 1'000'000;
std::vector<long long> crop_rectangle(const std::string& text) {
    std::vector<long long> numbers;
    const char* at = text.data();
    const char* end = text.data() + text.size();
    while (numbers.size() < 4) {
        long long number = -1;
        const auto [stop, error] = std::from_chars(at, end, number);
        if (error != std::errc{} || number < 0 || number > kLargestCrop) break;
        numbers.push_back(number);
        at = stop;
        if (numbers.size() < 4 && (at == end || *at++ != ',')) break;
    }
    if (numbers.size() != 4 || at != end) {
        throw Stop{kRefused,
                   "--crop " + browser::in_quotes(text) + ": give X,Y,W,H, four whole numbers of canvas pixels"};
    }
    if (numbers[2] < 1 || numbers[3] < 1) {
        throw Stop{kRefused, "--crop X,Y,W,H: the width and height must be at least 1 px"};
    }
    return numbers;
}

// --crop X,Y,W,H within the canvas the runs drew (`canvas`, device pixels at `scale`).
void check_crop(const std::vector<long long>& crop, const browser::Image& canvas, int scale) {
    if (crop.empty()) return;
    const long long width = canvas.width / scale, height = canvas.height / scale;
    if (crop[0] + crop[2] > width || crop[1] + crop[3] > height) {
        throw Stop{kRefused, "--crop " + std::to_string(crop[0]) + "," + std::to_string(crop[1]) + "," +
                                 std::to_string(crop[2]) + "," + std::to_string(crop[3]) +
                                 ": the crop must lie within the canvas, " + std::to_string(width) + " x " +
                                 std::to_string(height) + " px"};
    }
}

void compare(const Request& request) {
    for (const std::string& option : request.options) {
        for (const std::string& own : kOwnOptions) {
            if (option == own || option.starts_with(own + "=")) {
                throw Stop{kRefused, own + " is " + kProgram + "'s to set; give the program's picture options only"};
            }
        }
    }
    // The program checks both; they are read here only once it has accepted them.
    int scale = 1;
    if (const auto text = option_value(request.options, "--scale")) scale = std::clamp(std::atoi(text->c_str()), 1, 4);
    double frame_ms = kBookFrameMs;
    if (const auto text = option_value(request.options, "--frame-ms")) frame_ms = std::atof(text->c_str());

    const json scene = read_scene(request.scene);
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
    const std::vector<std::string> pictures = shared_pictures(left, right);
    if (!pictures.empty())
        check_crop(request.crop, browser::canvas_of(browser::read_png(left / pictures[0]), scale), scale);
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
    // --trail: every saved frame before this one ghosted in turn onto a blank canvas,
    // one picture a side however many frames there are (side_by_side.h, with_trail).
    std::optional<browser::Image> trails[2];
    std::vector<std::string> frames;
    for (const std::string& name : pictures) {
        browser::stop_if_interrupted();
        browser::Image halves[2];
        for (int i = 0; i < 2; ++i) {
            const browser::Image canvas =
                browser::canvas_of(browser::read_png(folder.staging() / sides[i].name / name), scale);
            halves[i] = canvas;
            if (starts[i]) halves[i] = browser::with_start_ghost(halves[i], *starts[i]);
            if (trails[i]) halves[i] = browser::with_trail(halves[i], *trails[i]);
            if (request.trail && name != browser::kFinalPicture) {
                if (!trails[i]) trails[i] = browser::Image(canvas.width, canvas.height);
                trails[i] = browser::with_start_ghost(*trails[i], canvas);
            }
            if (!request.crop.empty()) {
                const auto at = [&](std::size_t k) { return static_cast<int>(request.crop[k] * scale); };
                halves[i] = browser::cropped(halves[i], at(0), at(1), at(2), at(3));
            }
        }
        browser::write_png(folder.staging() / name,
                           browser::side_by_side(halves[0], sides[0].setting, halves[1], sides[1].setting));
        if (name != browser::kFinalPicture) frames.push_back(name);
    }
    // --no-gif goes to both runs, and it holds for the joined frames too.
    const bool no_gif = std::find(request.options.begin(), request.options.end(), "--no-gif") != request.options.end();
    const bool gif = frames.size() >= 2 && browser::gif_supported() && !no_gif;
    if (gif) {
        const int every = frame_number(frames[1]) - frame_number(frames[0]);
        const browser::Image first = browser::read_png(folder.staging() / frames[0]);
        browser::GifWriter gif(folder.staging() / "animation.gif", first.width, first.height,
                               browser::gif_delay_centiseconds(frame_ms, every));
        for (const std::string& name : frames) {
            browser::stop_if_interrupted();
            gif.add(browser::read_png(folder.staging() / name));
        }
        gif.close();
    }
    browser::stop_if_interrupted();
    folder.commit();
    std::cout << "wrote " << (out / "").string() << ": " << frames.size() + 1 << " joined pictures"
              << (gif ? " and animation.gif" : "") << " (left " << browser::printable(request.settings[0]) << ", right "
              << browser::printable(request.settings[1]) << ")\n";
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
    // One value, split here: a vector option of CLI11's would take the "--" after it as
    // the end of its values, and the program's options after that as compare_runs' own.
    std::string crop;
    app.add_option("--crop", crop, "show only this part of each canvas, in canvas pixels")->type_name("X,Y,W,H");
    app.add_option("OPTIONS", request.options, "after --: the program's options for both runs");
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& error) {
        if (error.get_exit_code() == 0) return app.exit(error);  // --help
        std::cerr << kProgram << ": " << browser::printable(error.what()) << " (see " << kProgram << " --help)\n";
        return kRefused;
    }
    try {
        if (!crop.empty()) request.crop = crop_rectangle(crop);
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
        std::cerr << kProgram << ": " << browser::printable(error.path1().string()) << ": " << error.code().message()
                  << '\n';
        return kWriteFailed;
    } catch (const std::bad_alloc&) {
        std::cerr << kProgram << ": out of memory; nothing was written\n";
        return kWriteFailed;
    } catch (const std::exception& error) {
        std::cerr << kProgram << ": " << browser::printable(error.what()) << '\n';
        return kWriteFailed;
    }
}
