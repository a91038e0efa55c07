#include "command_line.h"

#include <CLI/CLI.hpp>

#include <charconv>
#include <cmath>
#include <iostream>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string_view>

#include "canvas.h"
#include "build_features.h"
#include "random.h"
#include "strict_parse.h"

namespace browser {
namespace {

constexpr double kMaxFrameMs = 10'000.0;  // ten seconds a frame is already a slide show

// The pictures (frame_NNNN.png) and GIF frames a run may write: a thousand pages of
// the largest canvas are about a gigabyte.
constexpr int kMostPictures = 1'000;

// How many frames of `frames` are saved when every `every`-th is, from the first on.
int frames_saved(int frames, int every) { return (frames - 1) / every + 1; }

// The whole of `text` as a T, or nothing. from_chars takes no sign for unsigned types,
// no '+', no spaces and (here) no trailing characters, so "12abc", " 5" and "-1" for a
// seed all fail.
template <class T>
std::optional<T> parse_whole(std::string_view text) {
    T value{};
    const char* end = text.data() + text.size();
    const auto [stop, error] = std::from_chars(text.data(), end, value);
    if (text.empty() || error != std::errc{} || stop != end) return std::nullopt;
    return value;
}

int int_option(const char* name, const std::string& text, int low, int high) {
    const auto value = parse_whole<long long>(text);
    if (!value || *value < low || *value > high) {
        throw UsageError(std::string(name) + ": must be a whole number from " + std::to_string(low) + " to " +
                         std::to_string(high) + " (got " + in_quotes(text) + ")");
    }
    return static_cast<int>(*value);
}

std::uint64_t seed_option(const std::string& text) {
    const auto value = parse_whole<std::uint64_t>(text);
    if (!value) {
        throw UsageError("--seed: must be a whole number from 0 to " +
                         std::to_string(std::numeric_limits<std::uint64_t>::max()) + " (got " + in_quotes(text) + ")");
    }
    return *value;
}

double frame_ms_option(const std::string& text) {
    const auto value = parse_whole<double>(text);
    // from_chars reads "nan" and "inf" as numbers, hence the isfinite test.
    if (!value || !std::isfinite(*value) || *value <= 0.0 || *value > kMaxFrameMs) {
        std::ostringstream message;
        message << "--frame-ms: must be a number of milliseconds above 0 and at most " << kMaxFrameMs << " (got "
                << in_quotes(text) << ")";
        throw UsageError(message.str());
    }
    return *value;
}

// Whether the reader wants animation.gif: --gif or --no-gif, else the stage's choice.
bool gif_wanted(bool gif_given, bool no_gif_given, bool stage_default) {
    if (gif_given && no_gif_given) throw UsageError("--gif, --no-gif: give one or the other");
    return gif_given || (stage_default && !no_gif_given);
}

// Whether this build can write the GIF that is wanted. Asking for it with --gif in a
// build without giflib stops the run; a stage's default GIF is skipped with a note, so
// the stage's default run still works there.
bool gif_possible(bool gif_given, const std::string& program) {
    if (gif_supported()) return true;
    if (gif_given) throw UsageError(std::string(kNoGifSupport));
    std::cerr << program << ": note: no animation.gif, as this build has no GIF support"
              << " (install the Debian package libgif-dev and rebuild; --no-gif hides this note)\n";
    return false;
}

// The stage's key list, and the overlay key when it has an overlay.
std::vector<KeyHelp> with_overlay_key(const StageDefaults& defaults) {
    std::vector<KeyHelp> keys = defaults.key_help;
    if (!defaults.overlay.empty())
        keys.push_back(
            {key_name(kOverlayKey), "overlay: off -> this stage's layer -> every layer -> off (see --overlay)"});
    return keys;
}

// The keys the stage declares, from its key list. A bad name there is the stage's
// mistake, not the reader's.
KeySet stage_keys(const StageDefaults& defaults) {
    KeySet keys;
    for (const KeyHelp& line : with_overlay_key(defaults)) {
        try {
            keys.add(KeySet::parse(line.keys));
        } catch (const KeyScriptError& error) {
            throw std::logic_error("key list of " + defaults.id + ": " + error.what());
        }
    }
    return keys;
}

// The end of --help: how to write a key script, and the stage's own keys.
std::string help_footer(const StageDefaults& defaults) {
    std::string footer =
        "A key script is tokens KEY[*COUNT][@FRAME] separated by spaces, e.g. \"f*3 g@10 up\";\n"
        "a token without @ comes at the frame of the one before.";
    if (defaults.key_help.empty()) return footer + "\nKeys: a-z, 0-9, comma, up, down, slash.";
    const std::vector<KeyHelp> keys = with_overlay_key(defaults);
    std::size_t widest = 0;
    for (const KeyHelp& line : keys) widest = std::max(widest, line.keys.size());
    footer += "\n\nThe keys of this stage, in a --keys script or live with --live:";
    for (const KeyHelp& line : keys) {
        footer += "\n  " + line.keys + std::string(widest - line.keys.size() + 2, ' ') + line.meaning;
    }
    footer +=
        "\nLive, also: Space pauses and goes on, period runs one frame while paused,\n"
        "F12 saves the page shown as <stage>_frame_NNNN.png in the current folder,\n"
        "Escape or closing the window ends the session.";
    return footer;
}

// The program as the reader called it, with the options given that shape the run,
// in the order of `given`.
std::vector<std::string> replay_command(const CLI::App& app, int argc, const char* const* argv,
                                        const std::string& program,
                                        const std::vector<std::pair<std::string, std::string>>& given) {
    std::vector<std::string> command{argc >= 1 && argv != nullptr && argv[0] != nullptr ? argv[0] : program};
    for (const auto& [name, value] : given) {
        if (app.count(name) == 0) continue;
        command.push_back(name);
        command.push_back(value);
    }
    return command;
}

// Options that make pictures have no place in a live session, which writes none.
void refuse_picture_options_when_live(const CLI::App& app) {
    for (const char* name : {"--out", "--from", "--every", "--gif", "--gif-every"}) {
        if (app.count(name) > 0) {
            throw UsageError(std::string(name) +
                             ": a --live session writes no pictures; record it with --record FILE and replay that");
        }
    }
    if (app.count("--frames") > 0) {
        throw UsageError("--frames: a --live session runs until Escape; --record FILE tells how many frames it ran");
    }
}

std::string program_name(int argc, const char* const* argv, const StageDefaults& defaults) {
    if (argc < 1 || argv == nullptr || argv[0] == nullptr) return defaults.id;
    const std::string name = std::filesystem::path(argv[0]).filename().string();
    return name.empty() ? defaults.id : name;
}

// What the reader typed, option by option. Every value is read as text and checked
// afterwards, so each bad value gets a message in our words, naming the option and
// quoting what the reader typed.
struct OptionTexts {
    explicit OptionTexts(const StageDefaults& defaults)
        : out((std::filesystem::path("out") / defaults.id).string()),
          frames(std::to_string(defaults.frames)),
          every(std::to_string(defaults.every)),
          gif_every(std::to_string(defaults.gif_every)),
          seed(std::to_string(Random::kDefaultSeed)),
          keys(defaults.keys) {
        // Bound to the table before parsing; std::map keeps references to its values
        // valid as it grows.
        for (const ExtraOption& option : defaults.extra_options) extra.emplace(option.name, option.default_value);
    }
    std::string out, frames, from = "0", every, gif_every, seed, keys;
    std::string frame_ms;  // read only when given, so the default stays exactly 1000/60
    std::string scale = "1";
    bool gif = false, no_gif = false, live = false, overlay = false,
         overlay_all = false;  // switches: no value to check
    std::string record, live_events, live_screenshot;
    std::map<std::string, std::string> extra;  // the stage's own options, by name
};

// The option table: the common options and the stage's own, each bound to its text.
void declare_options(CLI::App& app, OptionTexts& texts, const StageDefaults& defaults) {
    std::ostringstream default_frame_ms;
    default_frame_ms << 1000.0 / 60.0;
    app.add_option("--out", texts.out, "folder for the pictures (replaced by each run)")
        ->type_name("DIR")
        ->capture_default_str();
    app.add_option("--frames", texts.frames, "how many animation frames to run")->type_name("N")->capture_default_str();
    app.add_option("--from", texts.from,
                   "save pictures from frame F on; the frames before it run unseen (a replay's idle start)")
        ->type_name("F")
        ->capture_default_str();
    app.add_option("--every", texts.every,
                   "also save every K-th frame as frame_NNNN.png, and all of them small on contact_sheet.png"
                   " (0: only final.png)")
        ->type_name("K")
        ->capture_default_str();
    app.add_flag("--gif", texts.gif, "also write animation.gif, the page every N-th frame (see --gif-every)");
    app.add_flag("--no-gif", texts.no_gif, "write no animation.gif, even where the stage writes one by default");
    app.add_option("--gif-every", texts.gif_every,
                   "a GIF picture after frames 0, N, 2N, ...; each shows N frames' time")
        ->type_name("N")
        ->capture_default_str();
    app.add_option("--seed", texts.seed, "seed of the random numbers")->type_name("S")->capture_default_str();
    app.add_option("--keys", texts.keys, "key presses, e.g. \"f*3 g@10 up e*5@20\"")
        ->type_name("SCRIPT")
        ->capture_default_str();
    app.add_option("--frame-ms", texts.frame_ms, "simulated milliseconds per frame")
        ->type_name("MS")
        ->default_str(default_frame_ms.str());
    app.add_option("--scale", texts.scale,
                   "draw the page K times larger (1 to 4), lines and text included,"
                   " in the window and in the pictures")
        ->type_name("K")
        ->capture_default_str();
    if (!defaults.overlay.empty()) {
        app.add_flag("--overlay", texts.overlay,
                     "start with the overlay on, this stage's own layer: " + defaults.overlay);
        app.add_flag("--overlay-all", texts.overlay_all,
                     "start with the overlay on, the layers of every stage before this one too");
    }
    app.add_flag("--live", texts.live, "play the page in a window, keys from the keyboard (Escape ends)");
    app.add_option("--record", texts.record,
                   "with --live: write the session's key presses to FILE as a key script"
                   " and print the command that replays it")
        ->type_name("FILE");
    // Test hooks, hidden from --help (an empty group): see live_window.h.
    app.add_option("--live-events", texts.live_events)->group("");
    app.add_option("--live-screenshot", texts.live_screenshot)->group("");

    for (const ExtraOption& option : defaults.extra_options) {
        try {
            // CLI11 refuses a name that is already in the table: given twice, or a common one.
            app.add_option(option.name, texts.extra.at(option.name), option.help)
                ->type_name(option.value_name)
                ->capture_default_str();
        } catch (const CLI::ConstructionError& error) {
            // A mistake in the stage's code, not in what the reader typed.
            throw std::logic_error("extra option " + in_quotes(option.name) + ": " + one_line(error.what()));
        }
    }
}

// CLI11 would read "--gif=false" as turning the flag on or off by its value; a switch
// with a value is more likely a slip, and --no-gif says it plainly.
void refuse_switch_values(const std::vector<std::string>& arguments) {
    for (const std::string& argument : arguments) {
        for (const std::string_view flag : {"--gif=", "--no-gif=", "--live=", "--overlay=", "--overlay-all="}) {
            if (argument.starts_with(flag)) {
                throw UsageError(std::string(flag.substr(0, flag.size() - 1)) + ": takes no value (got " +
                                 in_quotes(argument) + ")");
            }
        }
    }
}

// --live and the options that only go with it.
void check_live_switches(const CLI::App& app, const OptionTexts& texts) {
    if (texts.live) {
        refuse_picture_options_when_live(app);
        if (!live_window_supported()) throw UsageError(std::string(kNoLiveSupport));
    }
    for (const char* name : {"--record", "--live-events", "--live-screenshot"}) {
        if (!texts.live && app.count(name) > 0) throw UsageError(std::string(name) + ": only with --live");
    }
    for (const auto& [name, text] : {std::pair<const char*, const std::string&>{"--record", texts.record},
                                     {"--live-events", texts.live_events},
                                     {"--live-screenshot", texts.live_screenshot}}) {
        if (app.count(name) > 0 && text.empty()) throw UsageError(std::string(name) + ": must name a file (got \"\")");
    }
}

// The options that shape the pictures: their folder, size, how many and which, and
// whether a GIF is wanted (returned; whether this build can write it is asked last).
bool read_picture_options(const CLI::App& app, const OptionTexts& texts, const StageDefaults& defaults,
                          Options& options) {
    options.scale = int_option("--scale", texts.scale, 1, Canvas::kMaxScale);
    options.out_dir = texts.out;
    if (texts.out.empty()) throw UsageError("--out: must name a folder (got \"\")");
    options.frames = int_option("--frames", texts.frames, 1, KeyScript::kMaxFrame);
    options.from = int_option("--from", texts.from, 0, KeyScript::kMaxFrame);
    if (options.from >= options.frames) {
        throw UsageError("--from: frame " + std::to_string(options.from) + " is not run: --frames " +
                         std::to_string(options.frames) + " runs frames 0 to " + std::to_string(options.frames - 1));
    }
    options.every = int_option("--every", texts.every, 0, KeyScript::kMaxFrame);
    const bool want_gif = gif_wanted(texts.gif, texts.no_gif, defaults.gif);
    const int shown = options.frames - options.from;  // the frames whose pictures a run may save
    if (options.every > 0 && frames_saved(shown, options.every) > kMostPictures) {
        throw UsageError("--every: " + std::to_string(shown) + " frames would save " +
                         std::to_string(frames_saved(shown, options.every)) + " pictures, more than the " +
                         std::to_string(kMostPictures) + " a run may (a larger --every, or fewer --frames)");
    }
    options.gif_every = int_option("--gif-every", texts.gif_every, 1, KeyScript::kMaxFrame);
    if (app.count("--gif-every") > 0 && !want_gif) {
        throw UsageError("--gif-every: there is no GIF to space out (add --gif)");
    }
    if (want_gif && !texts.live && frames_saved(shown, options.gif_every) > kMostPictures) {
        throw UsageError("--gif-every: " + std::to_string(shown) + " frames would make a GIF of " +
                         std::to_string(frames_saved(shown, options.gif_every)) + " pictures, more than the " +
                         std::to_string(kMostPictures) +
                         " a run may (a larger --gif-every, fewer --frames, or --no-gif)");
    }
    return want_gif;
}

// The key script: well formed, only the stage's keys, and no press after the last frame.
void read_key_options(const CLI::App& app, const OptionTexts& texts, const KeySet& keys_of_stage, Options& options) {
    try {
        options.keys = KeyScript::parse(texts.keys);
    } catch (const KeyScriptError& error) {
        throw UsageError(std::string("--keys: ") + error.what());
    }
    options.stage_keys = keys_of_stage;
    if (!options.stage_keys.empty()) {
        if (const auto stray = options.keys.firstKeyOutside(options.stage_keys)) {
            throw UsageError("--keys: " + in_quotes(key_name(*stray)) +
                             " is not a key of this stage (its keys: " + options.stage_keys.text() + ")");
        }
    }
    options.keys_text = texts.keys;
    options.keys_given = app.count("--keys") > 0;
    // A live session starts from the page as it loads; the reader plays it, after any
    // presses of their own --keys script.
    if (texts.live && !options.keys_given) options.keys = KeyScript();
    // A press of the reader's own after the last frame would silently do nothing, which
    // hides a mistake. The default script may run past a shorter --frames: asking for
    // fewer frames than the demo needs is a fair request.
    if (!texts.live && options.keys_given && options.keys.lastFrame() >= options.frames) {
        const bool pointer =
            !options.keys.drags().empty() && options.keys.drags().back().releaseFrame() - 1 == options.keys.lastFrame();
        throw UsageError(std::string("--keys: ") + (pointer ? "a drag has a point" : "a key is pressed") +
                         " before frame " + std::to_string(options.keys.lastFrame()) + ", but --frames " +
                         std::to_string(options.frames) + " runs only frames 0 to " +
                         std::to_string(options.frames - 1));
    }
}

// A --live session's settings, and the command that replays what it records.
LiveOptions live_options(const CLI::App& app, const OptionTexts& texts, const StageDefaults& defaults, int argc,
                         const char* const* argv, const std::string& program) {
    LiveOptions live;
    live.on = true;
    live.record = texts.record;
    live.events = texts.live_events;
    live.screenshot = texts.live_screenshot;
    live.title = defaults.title + " (" + defaults.id + ")";
    live.stage_id = defaults.id;
    std::vector<std::pair<std::string, std::string>> shaping{
        {"--seed", texts.seed}, {"--frame-ms", texts.frame_ms}, {"--scale", texts.scale}};
    for (const auto& [name, value] : texts.extra) shaping.emplace_back(name, value);
    live.replay_command = replay_command(app, argc, argv, program, shaping);
    if (texts.overlay_all) {
        live.replay_command.emplace_back("--overlay-all");
    } else if (texts.overlay) {
        live.replay_command.emplace_back("--overlay");
    }
    // The stage's pictures; for a stage that saves none but final.png, one a half second.
    live.replay_every = defaults.every > 0 ? defaults.every : 30;
    live.replay_gif = !defaults.gif && gif_supported();
    return live;
}

}  // namespace

ParsedCommandLine parse_command_line(int argc, const char* const* argv, const StageDefaults& defaults) {
    const std::string program = program_name(argc, argv, defaults);
    OptionTexts texts(defaults);
    const KeySet keys_of_stage = stage_keys(defaults);  // a bad key list is found even with --help
    CLI::App app(defaults.title, program);
    app.footer(help_footer(defaults));
    // Unknown words stay in app.remaining() so we can name them ourselves.
    app.allow_extras();
    declare_options(app, texts, defaults);

    try {
        // CLI11 takes the arguments last-first and without the program name.
        std::vector<std::string> arguments;
        for (int i = argc - 1; i >= 1; --i) arguments.emplace_back(argv[i]);
        refuse_switch_values(arguments);
        if (!parse_strictly(app, arguments)) return {std::nullopt, 0};

        Options options;
        check_live_switches(app, texts);
        const bool want_gif = read_picture_options(app, texts, defaults, options);
        options.seed = seed_option(texts.seed);
        if (app.count("--frame-ms") > 0) options.frame_ms = frame_ms_option(texts.frame_ms);
        read_key_options(app, texts, keys_of_stage, options);
        // An empty name is a slip (an unset shell variable), never "no file": refused as
        // --out "" is, rather than silently running without the scene or the dump.
        for (const auto& [name, value] : texts.extra) {
            if (app.count(name) > 0 && value.empty()) throw UsageError(name + ": must name a file (got \"\")");
        }
        options.extra = texts.extra;
        options.overlay_offered = !defaults.overlay.empty();
        options.overlay = texts.overlay;
        options.overlay_all = texts.overlay_all;
        options.echo_notes = defaults.echo_notes;
        if (texts.live) options.live = live_options(app, texts, defaults, argc, argv, program);
        // Last, so the note about a skipped GIF never comes with an error about another option.
        options.gif = !texts.live && want_gif && gif_possible(texts.gif, program);
        return {std::move(options), 0};
    } catch (const UsageError& error) {
        std::cerr << program << ": " << error.what() << '\n';
        return {std::nullopt, 2};
    }
}

std::vector<std::filesystem::path> files_read(const Options& options) {
    std::vector<std::filesystem::path> files;
    if (const auto scene = options.extra.find("--scene"); scene != options.extra.end() && !scene->second.empty()) {
        files.emplace_back(scene->second);
    }
    if (!options.live.events.empty()) files.push_back(options.live.events);
    return files;
}

}  // namespace browser
