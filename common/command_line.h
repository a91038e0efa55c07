#pragma once
// One command-line shape for every stage (CLI11):
//   --out DIR  --frames N  --from F  --every K  --seed S  --keys SCRIPT  --frame-ms MS
//   --gif  --no-gif  --gif-every N  --scale K  --live  --record FILE  --help
// and, on a stage with an overlay (StageDefaults::overlay), --overlay, --overlay-all and
// the key t
// plus text options a stage adds (--scene FILE, --dump FILE, ... in later chapters):
// list them in StageDefaults::extra_options and read their values from Options::extra.
// CLI11 stays inside command_line.cpp, so stages never see it.

#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "keys.h"
#include "page.h"

namespace browser {

// A text option one stage adds to the common ones. The parser only collects the text;
// the stage checks it (a scene file that does not load, ...) and reports problems itself.
struct ExtraOption {
    std::string name;           // "--scene": two dashes, not one of the common options
    std::string value_name;     // "FILE": shown by --help
    std::string help;           // one line for --help
    std::string default_value;  // the value when the option is not given ("" for none)
};

// A line of the stage's key list, as its README gives it: the keys, and what they do.
struct KeyHelp {
    std::string keys;     // names and ranges as KeySet::parse reads them: "0-9 up down", "w a s d"
    std::string meaning;  // "select an object"
};

// What a stage's program does when run with no options.
struct StageDefaults {
    std::string id;                          // names the default output folder out/<id>/
    std::string title;                       // the stage's number and name: shown by --help
    std::string keys;                        // the default key script
    int frames = 1;                          // how many animation frames to run
    int every = 0;                           // also write every K-th frame (0: only the last)
    bool gif = false;                        // also write animation.gif (--no-gif turns it off again)
    int gif_every = 2;                       // one GIF picture every N-th frame
    std::vector<ExtraOption> extra_options;  // the stage's own options, if any
    // Every key the page's script reacts to: --help lists them, and a key script that
    // presses any other key is refused. Empty: any key may be pressed.
    std::vector<KeyHelp> key_help;
    // What the stage's overlay draws, for --help ("" when it has none). A stage with one
    // takes --overlay (the overlay on from the first frame) and the key kOverlayKey.
    std::string overlay;
    // What the page notes on lines of the book's echo (page.h's EchoNote): a quirk of
    // the book's a stage keeps, said beside the line that shows it.
    std::vector<EchoNote> echo_notes;
};

// The key that takes a stage's overlay round (off, the stage's own layer, every layer),
// live or in a key script; no stage uses it for anything else.
inline constexpr Key kOverlayKey = Key::T;

// A --live session: the page in a window, played from the keyboard (live.h).
struct LiveOptions {
    bool on = false;                          // --live
    std::filesystem::path record;             // --record FILE: where the session's key script goes ("" for nowhere)
    std::string title;                        // the window's title
    std::string stage_id;                     // names the pages F12 saves (<id>_frame_NNNN.png)
    std::filesystem::path screenshot_folder;  // where F12 saves them: the current folder ("")
    // The command that replays a recorded session, but for its --keys, --frames and
    // picture options: the program as it was called, and every option given that shapes
    // the run (--seed, --frame-ms, --scale, the stage's own options).
    std::vector<std::string> replay_command;
    int replay_every = 30;    // the --every the printed replay command uses
    bool replay_gif = false;  // whether it adds --gif (the stage writes no GIF by default)
    // Test hooks, hidden from --help (live_window.h): key events to push into the
    // window's event queue, and where to save the last picture the window showed.
    std::filesystem::path events;
    std::filesystem::path screenshot;
};

struct Options {
    std::filesystem::path out_dir;
    int frames = 1;
    // --from F: the pictures, the contact sheet and the GIF start at frame F (frame F,
    // F + every, ...); the frames before it run all the same, unseen. A replay of a live
    // session starts at its first key press so, and not with the idle wait before it.
    int from = 0;
    int every = 0;
    bool gif = false;  // write animation.gif: a picture after frames 0, N, 2N, ... (N = gif_every)
    int gif_every = 2;
    std::uint64_t seed = 0;
    KeyScript keys;
    std::string keys_text;
    bool keys_given = false;  // --keys was on the command line (not the stage's default script)
    double frame_ms = 1000.0 / 60.0;
    int scale = 1;      // device pixels per canvas pixel, along each axis (--scale)
    KeySet stage_keys;  // the keys the stage's page reacts to (empty: any)
    LiveOptions live;
    bool overlay_offered = false;  // the stage has an overlay: kOverlayKey takes it round
    bool overlay = false;          // --overlay: it is on from the first frame, the stage's own layer
    bool overlay_all = false;      // --overlay-all: on from the first frame, every stage's layers
    // The stage's notes on lines of the echo (StageDefaults::echo_notes).
    std::vector<EchoNote> echo_notes;
    // One entry per StageDefaults::extra_options, keyed by name: extra.at("--scene").
    std::map<std::string, std::string> extra;
};

// The outcome of reading argv: options to run with, or an exit status when the
// program should stop now (0 after --help, 2 after a bad option, whose one-line
// message has already been printed to stderr, prefixed by the program's file name).
// A key scripted for a frame the run never reaches is a bad option too, since it would
// silently do nothing, and so are a key the stage does not handle, --gif-every without
// a GIF, --gif in a build without giflib (one line: build_features.h's kNoGifSupport),
// --live in a build without SDL2 (build_features.h's kNoLiveSupport), picture options with
// --live (a live session writes none: it records keys to replay), and --record without it. When the GIF is only the
// stage's default, such a build says on stderr that it skips the GIF and runs on.
struct ParsedCommandLine {
    std::optional<Options> options;
    int exit_status = 0;
};

ParsedCommandLine parse_command_line(int argc, const char* const* argv, const StageDefaults& defaults);

// The files a run reads (its --scene, its --live-events), which nothing it writes may
// be or hold (write_guard.h).
std::vector<std::filesystem::path> files_read(const Options& options);

}  // namespace browser
