#pragma once
// Scene files (--scene FILE): a JSON description of a stage's world and of what is in
// it, which a learner edits instead of the stage's code (docs/scene_format.md):
//   {"world": {the world's keys},
//    "<list>": [{"<kind key>": "<kind>", the keys of that kind...}, ...], ...}
//
// The browser's part is the reading: JSON, paths, rules for numbers, and one format for
// every problem. What the words mean is the stage's. Each stage that reads scene files
// declares its vocabulary in its scene_io.cpp: the world keys it reads, each bound to
// one of its settings (SceneKey); the lists a scene may hold (SceneList); for each, the
// kinds of its elements and the keys of each kind, bound to the stage's own description
// of an element. A key it does not declare is refused, so no stage ever silently
// ignores what a scene asks for, and a stage that adds a key or a kind adds it in its
// own folder, where tools/stage_diff shows it arriving.

#include <cmath>
#include <cstddef>
#include <filesystem>
#include <functional>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

#include "vec2.h"

namespace browser {

// What a number in a scene file must be, and the words that say so in a refusal.
struct NumberRule {
    bool (*accepts)(double);
    const char* words;
};

// How much a scene file may hold, so that reading it fits in memory and ends: 2 MiB
// of text (a stage's own limit on its lists keeps a run within its budget), nested no
// deeper than the deepest value a scene has, a list of points in an element of a list,
// {"list": [{"key": [[x, y]]}]}: five levels (the corners of a shape that has them).
inline constexpr std::size_t kMaxSceneBytes = 2 << 20;  // 2 MiB
inline constexpr std::size_t kMaxNesting = 5;

// Rules any stage may use; a stage writes its own for its own keys (its scene_io.cpp:
// the engine's quantities are the engine's to bound). No number of an accepted scene
// may make a NaN or an infinity, so every rule refuses both.
namespace rules {
inline constexpr NumberRule kFinite{[](double v) { return std::isfinite(v); }, "must be a finite number"};
inline constexpr NumberRule kPositive{[](double v) { return std::isfinite(v) && v > 0.0; },
                                      "must be a finite number > 0"};
inline constexpr NumberRule kNotNegative{[](double v) { return std::isfinite(v) && v >= 0.0; },
                                         "must be a finite number >= 0"};
inline constexpr NumberRule kFraction{[](double v) { return v >= 0.0 && v <= 1.0; },
                                      "must be a finite number in [0, 1]"};
// The canvas is a picture in memory: 4096 x 4096 px is 64 MiB.
inline constexpr NumberRule kCanvasSize{[](double v) { return v > 0.0 && v <= 4096.0; },
                                        "must be a number in (0, 4096]"};
}  // namespace rules

// Whether a scene must give a key. A key it leaves out leaves its setting as it was: the
// stage's default.
enum class Presence { optional, required };
inline constexpr Presence kRequired = Presence::required;

// A list of points, [[x, y], ...]: how many it may hold, and a check of the whole list
// that the stage makes (what the points must be together), which answers with its
// refusal, the problem's words, or nothing when the list is good.
struct PointsRule {
    std::size_t fewest = 1;
    std::size_t most = 1;
    std::function<std::optional<std::string>(std::span<const lib::Vec2>)> check;
};

// One key that a stage reads, bound to the setting it fills: a key of the "world"
// object, bound to one of the stage's settings, or a key of a list's element, bound to a
// member of the stage's description of that element:
//   SceneKey{"dt", settings.dt, kTimeStep}
//   SceneKey{"movement", settings.movement}
//   SceneKey{"integrator", settings.integrator, {{"symplectic", Integrator::symplectic}, ...}}
//   SceneKey{"anchor", spring.anchor, rules::kFinite, browser::kRequired}
class SceneKey {
public:
    SceneKey(std::string_view name, double& setting, NumberRule rule = rules::kFinite,
             Presence presence = Presence::optional)
        : name_(name), presence_(presence), target_(Number{&setting, rule}) {}
    // A whole number; `rule` must accept only values an int holds.
    SceneKey(std::string_view name, int& setting, NumberRule rule, Presence presence = Presence::optional)
        : name_(name), presence_(presence), target_(Count{&setting, rule}) {}
    SceneKey(std::string_view name, bool& setting, Presence presence = Presence::optional)
        : name_(name), presence_(presence), target_(Flag{&setting}) {}
    SceneKey(std::string_view name, lib::Vec2& setting, NumberRule rule = rules::kFinite,
             Presence presence = Presence::optional)
        : name_(name), presence_(presence), target_(Vector{&setting, rule}) {}
    // A list of points, each [x, y] with both numbers under `rule`.
    SceneKey(std::string_view name, std::vector<lib::Vec2>& setting, NumberRule rule, PointsRule points,
             Presence presence = Presence::optional)
        : name_(name), presence_(presence), target_(Points{&setting, rule, std::move(points)}) {}
    // One word from a fixed list, each naming a value of the setting's enum.
    template <class Enum>
    requires std::is_enum_v<Enum> SceneKey(std::string_view name, Enum& setting,
                                           std::vector<std::pair<std::string_view, Enum>> words,
                                           Presence presence = Presence::optional)
        : name_(name),
          presence_(presence),
          target_(Word{spellings(words), chooser(setting, words), reader(setting, words)}) {}

    struct Number {
        double* setting;
        NumberRule rule;
    };
    struct Count {
        int* setting;
        NumberRule rule;
    };
    struct Flag {
        bool* setting;
    };
    struct Vector {
        lib::Vec2* setting;
        NumberRule rule;
    };
    struct Points {
        std::vector<lib::Vec2>* setting;
        NumberRule rule;
        PointsRule points;
    };
    struct Word {
        std::vector<std::string_view> spellings;
        std::function<void(std::size_t)> choose;          // sets the setting to the i-th word's value
        std::function<std::optional<std::size_t>()> now;  // the word the setting holds now, if one does
    };

    std::string_view name() const { return name_; }
    bool required() const { return presence_ == Presence::required; }
    const std::variant<Number, Count, Flag, Vector, Points, Word>& target() const { return target_; }

private:
    template <class Enum>
    using Words = std::vector<std::pair<std::string_view, Enum>>;
    template <class Enum>
    static std::vector<std::string_view> spellings(const Words<Enum>& words) {
        std::vector<std::string_view> names;
        for (const auto& word : words) names.push_back(word.first);
        return names;
    }
    template <class Enum>
    static std::function<void(std::size_t)> chooser(Enum& setting, const Words<Enum>& words) {
        return [&setting, words](std::size_t i) { setting = words[i].second; };
    }
    template <class Enum>
    static std::function<std::optional<std::size_t>()> reader(Enum& setting, const Words<Enum>& words) {
        return [&setting, words]() -> std::optional<std::size_t> {
            for (std::size_t i = 0; i < words.size(); ++i) {
                if (words[i].second == setting) return i;
            }
            return std::nullopt;
        };
    }

    std::string_view name_;
    Presence presence_;
    std::variant<Number, Count, Flag, Vector, Points, Word> target_;
};

// A list a scene may hold, such as a stage's bodies: each element an object whose
// kind key names one of the kinds, and the kind decides which other keys it takes.
struct SceneList {
    std::string_view name;                // the list's key in the scene: "springs"
    std::string_view element;             // what messages call one element: "spring"
    std::string_view kind_key;            // the key that names an element's kind, read first
    std::vector<std::string_view> kinds;  // the words it takes, each a kind
    // The most elements the list may hold, and why, in the words of the refusal:
    // "more than <most> <name> (got N); <why_most>".
    std::size_t most = 0;
    std::string_view why_most;
    // Adds an element of kinds[kind] to the stage's list and returns its keys (all but
    // the kind key), bound to it, in the order refusals list them. The reader fills the
    // element as it reads it, in file order; a refused scene may leave the stage's list
    // part filled, so a stage reads into a scene it throws away on a refusal.
    std::function<std::vector<SceneKey>(std::size_t kind)> add;
};

// A scene that cannot be simulated. what() is one line:
//   "<file as given>: <JSON path>: <problem> (got <value>)"
// or, for text that is not JSON at all, "<file>: line L, column C: malformed JSON: ...".
struct SceneError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// The text of a scene file, read as every scene file is: a regular file of at most
// kMaxSceneBytes, never a FIFO, a device or a folder. Throws SceneError with one line.
std::string scene_text(const std::filesystem::path& file);

// Reads and checks `file`: its world keys go into the settings `world_keys` are bound
// to, and the elements of each list into the stage's own lists through `lists`, in file
// order (for a stage's bodies, the object index the keys 0-9 select). Throws SceneError on the
// first problem found; the world's settings are then left as they were, so nothing is
// built from a scene that is only half right.
void load_scene(const std::filesystem::path& file, std::span<const SceneKey> world_keys,
                std::span<const SceneList> lists);

// The same for a scene that is already text, such as one a program made in memory (the
// bench hands each stage its scenes this way). `source` stands for the file name in a
// refusal.
void read_scene_text(const std::string& text, std::string_view source, std::span<const SceneKey> world_keys,
                     std::span<const SceneList> lists);

// A key as a reference table gives it (docs/scene_format.md; the tests hold the tables
// against the stages' own keys): its name, whether a scene must give it, the values it
// takes, in the words of a refusal without its "must be" (a number in [0.01, 1e5] (px);
// true or false; "book" or "coulomb"), and the value its setting holds now, as JSON:
// the stage's default when the key is bound to a setting that holds its default.
struct KeyDescription {
    std::string name;
    bool required = false;
    std::string values;
    std::string value_now;
};
KeyDescription describe(const SceneKey& key);

}  // namespace browser
