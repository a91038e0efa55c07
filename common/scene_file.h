#pragma once
// Scene files (--scene FILE): a JSON description of the world and its bodies that a
// learner edits instead of the stage's code. In short:
//   {"world":  {the keys the stage reads: "gravity": [x, y], "dt", ...},
//    "bodies": [{"shape": "rectangle", "center": [x, y], "width", "height", ...},
//               {"shape": "circle", "center": [x, y], "radius", ...}]}
// where every body may also give mass, friction, restitution, angle, velocity [x, y] and
// angular_velocity. Everything but a body's shape, center and size may be left out.
// Units are the book's: px, s, rad, +y down.
//
// The browser's part is the reading: JSON, paths, rules, and one format for every
// problem. The world's settings are the engine's. Each stage from 4.1 on owns its
// settings and says which world keys it reads (a list of WorldKey, each bound to one of
// its settings); a key it does not list is refused, so no stage ever silently ignores
// what a scene asks for. The bodies are the book's RigidShape parameters, the same in
// every stage that reads scene files, so their rules (rules::kMass, ...) are written
// here once rather than copied into the eight stages from 4.1 on: an engine fact kept
// in the browser on purpose, as a browser knows the HTML it reads.

#include <cmath>
#include <cstddef>
#include <filesystem>
#include <functional>
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

enum class ShapeKind { rectangle, circle };

// "rectangle" or "circle": the spelling used in scene files and state dumps.
std::string_view shape_name(ShapeKind shape);

struct BodyDescription {
    ShapeKind shape = ShapeKind::rectangle;
    lib::Vec2 center;
    double width = 0.0;   // rectangles only
    double height = 0.0;  // rectangles only
    double radius = 0.0;  // circles only
    double mass = 1.0;    // 0 makes the body static
    double friction = 0.8;
    double restitution = 0.2;
    double angle = 0.0;  // rad, applied after construction as the book's rotate(angle)
    lib::Vec2 velocity;
    double angular_velocity = 0.0;  // rad/s
    // 5.6 on: a bullet is also swept against moving shapes, not only static ones (5.6's
    // README). Only a stage that says it reads the key (StageBodyKeys) accepts it.
    bool bullet = false;

    friend bool operator==(const BodyDescription&, const BodyDescription&) = default;
};

// The body keys that only some stages read. Every stage reads the book's body keys; a
// key a stage does not read is refused, as an unknown world key is.
struct StageBodyKeys {
    bool bullet = false;  // "bullet": true / false (5.6 on)
};

// What a number in a scene file must be, and the words that say so in a refusal.
struct NumberRule {
    bool (*accepts)(double);
    const char* words;
};

// How much a scene may hold: every run fits in memory and ends (docs/scene_format.md).
// 2,500 bodies (the bench's largest scene has 2,003) take about 650 KB of JSON.
inline constexpr std::size_t kMaxSceneBytes = 2 << 20;  // 2 MiB
inline constexpr std::size_t kMaxBodies = 2500;
// {"bodies": [{"center": [x, y]}]} is as deep as a scene goes: four levels.
inline constexpr std::size_t kMaxNesting = 4;

// The rules the book's settings need; a stage may write its own for its own keys.
//
// No number of an accepted scene may make a NaN or an infinity. Every quantity a body
// derives from them is then a plain double: with masses in [1e-3, 1e6] and sizes in
// [0.01, 1e5] px, the inverse mass lies in [1e-6, 1e3] and the moment of inertia (m r^2
// / 2, m (w^2 + h^2) / 12) in [1e-8, 1e16], its inverse in [1e-16, 1e8]: finite and > 0
// for every moving body. The ranges are those the extremes suite
// (tests/features/extremes_test.cpp) runs and finds finite: shapes of 0.01 px to 1e5 px,
// masses of 1 against 1e6, speeds up to 1e6 px/s.
namespace rules {
inline constexpr NumberRule kFinite{[](double v) { return std::isfinite(v); }, "must be a finite number"};
inline constexpr NumberRule kPositive{[](double v) { return std::isfinite(v) && v > 0.0; },
                                      "must be a finite number > 0"};
inline constexpr NumberRule kNotNegative{[](double v) { return std::isfinite(v) && v >= 0.0; },
                                         "must be a finite number >= 0"};
inline constexpr NumberRule kPosition{[](double v) { return v >= -1e6 && v <= 1e6; },
                                      "must be a number in [-1e6, 1e6] (px)"};
inline constexpr NumberRule kSize{[](double v) { return v >= 0.01 && v <= 1e5; },
                                  "must be a number in [0.01, 1e5] (px)"};
// 0 makes a static body; a moving one needs an inverse mass and inertia to divide by.
inline constexpr NumberRule kMass{[](double v) { return v == 0.0 || (v >= 1e-3 && v <= 1e6); },
                                  "must be 0 (static) or a number in [1e-3, 1e6]"};
inline constexpr NumberRule kFriction{[](double v) { return v >= 0.0 && v <= 100.0; }, "must be a number in [0, 100]"};
inline constexpr NumberRule kAngle{[](double v) { return v >= -1e6 && v <= 1e6; },
                                   "must be a number in [-1e6, 1e6] (rad)"};
inline constexpr NumberRule kSpeed{[](double v) { return v >= -1e6 && v <= 1e6; },
                                   "must be a number in [-1e6, 1e6] (px/s)"};
inline constexpr NumberRule kTurnRate{[](double v) { return v >= -1e4 && v <= 1e4; },
                                      "must be a number in [-1e4, 1e4] (rad/s)"};
inline constexpr NumberRule kAcceleration{[](double v) { return v >= -1e6 && v <= 1e6; },
                                          "must be a number in [-1e6, 1e6] (px/s^2)"};
inline constexpr NumberRule kFraction{[](double v) { return v >= 0.0 && v <= 1.0; },
                                      "must be a finite number in [0, 1]"};
// The canvas is a picture in memory: 4096 x 4096 px is 64 MiB.
inline constexpr NumberRule kCanvasSize{[](double v) { return v > 0.0 && v <= 4096.0; },
                                        "must be a number in (0, 4096]"};
// One simulated second takes 1/dt steps; below 1e-5 s a short run never ends.
inline constexpr NumberRule kTimeStep{[](double v) { return v >= 1e-5 && v <= 1.0; }, "must be a number in [1e-5, 1]"};
// A number of loop passes: whole (JSON does not tell 15.0 from 15), and small enough
// that every step still ends soon.
inline constexpr NumberRule kPassCount{[](double v) { return v >= 0.0 && v <= 1000.0 && std::floor(v) == v; },
                                       "must be a whole number in [0, 1000]"};
}  // namespace rules

// One key of the "world" object that a stage reads, bound to the setting it fills:
//   WorldKey{"dt", settings.dt, rules::kTimeStep}
//   WorldKey{"movement", settings.movement}
//   WorldKey{"integrator", settings.integrator, {{"symplectic", Integrator::symplectic}, ...}}
// A key the file leaves out leaves its setting as it was: the stage's book default.
class WorldKey {
public:
    WorldKey(std::string_view name, double& setting, NumberRule rule = rules::kFinite)
        : name_(name), target_(Number{&setting, rule}) {}
    // A whole number; `rule` must accept only values an int holds.
    WorldKey(std::string_view name, int& setting, NumberRule rule) : name_(name), target_(Count{&setting, rule}) {}
    WorldKey(std::string_view name, bool& setting) : name_(name), target_(Flag{&setting}) {}
    WorldKey(std::string_view name, lib::Vec2& setting, NumberRule rule = rules::kFinite)
        : name_(name), target_(Vector{&setting, rule}) {}
    // One word from a fixed list, each naming a value of the setting's enum.
    template <class Enum>
    requires std::is_enum_v<Enum> WorldKey(std::string_view name, Enum& setting,
                                           std::vector<std::pair<std::string_view, Enum>> words)
        : name_(name),
          target_(Word{spellings(words), [&setting, words](std::size_t i) { setting = words[i].second; }}) {}

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
    struct Word {
        std::vector<std::string_view> spellings;
        std::function<void(std::size_t)> choose;  // sets the setting to the i-th word's value
    };

    std::string_view name() const { return name_; }
    const std::variant<Number, Count, Flag, Vector, Word>& target() const { return target_; }

private:
    template <class Enum>
    static std::vector<std::string_view> spellings(const std::vector<std::pair<std::string_view, Enum>>& words) {
        std::vector<std::string_view> names;
        for (const auto& word : words) names.push_back(word.first);
        return names;
    }

    std::string_view name_;
    std::variant<Number, Count, Flag, Vector, Word> target_;
};

// A scene that cannot be simulated. what() is one line:
//   "<file as given>: <JSON path>: <problem> (got <value>)"
// or, for text that is not JSON at all, "<file>: line L, column C: malformed JSON: ...".
struct SceneError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// Reads and checks `file`: its world keys go into the settings `world_keys` are bound
// to, and its bodies come back in file order (the object index the keys 0-9 select).
// Throws SceneError on the first problem found, before any setting is changed, so
// nothing is built from a scene that is only half right.
std::vector<BodyDescription> load_scene(const std::filesystem::path& file, std::span<const WorldKey> world_keys,
                                        StageBodyKeys body_keys = {});

// The same for a scene that is already text, such as one a program made in memory (the
// bench hands each stage its scenes this way). `source` stands for the file name in a
// refusal.
std::vector<BodyDescription> read_scene_text(const std::string& text, std::string_view source,
                                             std::span<const WorldKey> world_keys, StageBodyKeys body_keys = {});

}  // namespace browser
