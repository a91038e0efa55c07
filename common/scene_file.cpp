#include "scene_file.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cerrno>
#include <climits>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <fstream>
#include <iterator>
#include <optional>
#include <set>
#include <string>
#include <type_traits>
#include <utility>
#include <variant>

#include <nlohmann/json.hpp>

namespace browser {

namespace fs = std::filesystem;
using json = nlohmann::json;

std::string_view shape_name(ShapeKind shape) {
    return shape == ShapeKind::circle ? "circle" : "rectangle";
}

namespace {
// Every value of each spelled enum, in declaration order, for reading and for messages.
constexpr std::array kShapeKinds{ShapeKind::rectangle, ShapeKind::circle};
constexpr std::array kIntegrators{Integrator::symplectic, Integrator::explicit_euler};
constexpr std::array kBroadPhases{BroadPhase::bounding_circle, BroadPhase::all_pairs, BroadPhase::grid};
constexpr std::array kFrictionModels{FrictionModel::book, FrictionModel::coulomb};

const auto& all_values(ShapeKind) { return kShapeKinds; }
const auto& all_values(Integrator) { return kIntegrators; }
const auto& all_values(BroadPhase) { return kBroadPhases; }
const auto& all_values(FrictionModel) { return kFrictionModels; }
std::string_view spelling(ShapeKind value) { return shape_name(value); }
std::string_view spelling(Integrator value) { return knob_name(value); }
std::string_view spelling(BroadPhase value) { return knob_name(value); }
std::string_view spelling(FrictionModel value) { return knob_name(value); }
}  // namespace

std::string_view knob_name(Integrator integrator) {
    return integrator == Integrator::explicit_euler ? "explicit" : "symplectic";
}

std::string_view knob_name(BroadPhase broad_phase) {
    switch (broad_phase) {
        case BroadPhase::all_pairs: return "all_pairs";
        case BroadPhase::grid: return "grid";
        case BroadPhase::bounding_circle: break;
    }
    return "bounding_circle";
}

std::string_view knob_name(FrictionModel friction_model) {
    return friction_model == FrictionModel::coulomb ? "coulomb" : "book";
}

namespace {

// ---------------------------------------------------------------------------------------
// Refusals. Helpers deep in the reading throw a Refusal (where + what); load_scene puts
// the file name in front, so no helper needs to carry it around.

struct Refusal {
    std::string where;  // a JSON path ("bodies[3].radius"), or "line 2, column 7"
    std::string problem;
};

[[noreturn]] void refuse(std::string where, std::string problem) {
    throw Refusal{std::move(where), std::move(problem)};
}

// Long values are cut, so that a message stays one readable line.
std::string shortened(std::string text) {
    constexpr std::size_t kLongest = 40;
    if (text.size() > kLongest) text.replace(kLongest - 3, std::string::npos, "...");
    return text;
}

// The offending value as JSON text, with non-ASCII escaped: whatever the file holds, the
// message gets no line break and no half of a UTF-8 character.
std::string shown(const json& value) {
    return shortened(value.dump(-1, ' ', true, json::error_handler_t::replace));
}

[[noreturn]] void refuse_value(std::string where, std::string_view problem, const json& got) {
    std::string text(problem);
    text.append(" (got ").append(shown(got)).append(")");
    refuse(std::move(where), std::move(text));
}

// JSON paths as a reader would write them: world.gravity[1], bodies[3].radius. A key
// that is not a plain word is quoted (bodies[0]["my key"]), so that a strange key, even
// one holding a line break, cannot break the one-line message.
bool is_plain_word(std::string_view key) {
    return !key.empty() &&
           std::all_of(key.begin(), key.end(), [](unsigned char c) { return std::isalnum(c) || c == '_'; });
}

std::string member_path(const std::string& object, const std::string& key) {
    std::string path = object;
    if (!is_plain_word(key)) return path.append("[").append(shown(json(key))).append("]");
    if (!path.empty()) path += '.';
    return path.append(key);
}

std::string element_path(const std::string& array, std::size_t index) {
    std::string path = array;
    return path.append("[").append(std::to_string(index)).append("]");
}

// ---------------------------------------------------------------------------------------
// From text to JSON.

std::string read_text(const fs::path& file) {
    const auto cannot_read = [&](const std::string& reason) {
        std::string message = file.string();
        throw SceneError(message.append(": cannot read: ").append(reason));
    };
    std::error_code error;
    if (!fs::exists(file, error)) cannot_read("no such file");
    if (fs::is_directory(file, error)) cannot_read("it is a folder");
    std::ifstream in(file, std::ios::binary);
    if (!in) cannot_read(std::strerror(errno));
    std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    if (in.bad()) cannot_read(std::strerror(errno));
    return text;
}

// The parser says where it stopped as a count of bytes read, the last of them being the
// offending one (at the end of the text: one past it). People count lines and columns,
// and columns in characters, so UTF-8 continuation bytes (10xxxxxx) are not counted.
std::string line_and_column(std::string_view text, std::size_t bytes_read) {
    const std::size_t offending = std::min(bytes_read > 0 ? bytes_read - 1 : 0, text.size());
    const std::string_view before = text.substr(0, offending);
    const std::size_t line_start = before.rfind('\n') + 1;  // npos + 1 wraps to 0: line 1
    const auto line = 1 + std::count(before.begin(), before.end(), '\n');
    const auto column = 1 + std::count_if(before.begin() + static_cast<std::ptrdiff_t>(line_start), before.end(),
                                          [](unsigned char c) { return (c & 0xC0) != 0x80; });
    std::string where = "line ";
    return where.append(std::to_string(line)).append(", column ").append(std::to_string(column));
}

// nlohmann's message without its prefix ("[json.exception.parse_error.101] parse error
// at line 1, column 9: "), whose position we have already given our own way.
std::string parser_reason(const json::exception& error) {
    const std::string_view message = error.what();
    const std::size_t colon = message.find(": ", message.find(']'));
    return std::string(colon == std::string_view::npos ? message : message.substr(colon + 2));
}

// A first pass over the text that builds nothing and only follows the JSON path. The
// parser that builds the document refuses a number too large for a double without
// saying where it is, and keeps only the last of two equal keys without saying anything
// at all; following the path lets both be refused like any other bad value.
class FirstPass final : public json::json_sax_t {
public:
    explicit FirstPass(std::string_view text) : text_(text) {}

    std::optional<Refusal> refusal;

    bool null() override { return value_read(); }
    bool boolean(bool) override { return value_read(); }
    bool number_integer(number_integer_t) override { return value_read(); }
    bool number_unsigned(number_unsigned_t) override { return value_read(); }
    bool number_float(number_float_t, const string_t&) override { return value_read(); }
    bool string(string_t&) override { return value_read(); }
    bool binary(binary_t&) override { return value_read(); }

    bool start_object(std::size_t) override { return open(false); }
    bool start_array(std::size_t) override { return open(true); }
    bool end_object() override { return close(); }
    bool end_array() override { return close(); }

    bool key(string_t& key) override {
        Container& object = open_.back();
        object.key = key;
        if (object.keys_seen.insert(key).second) return true;
        refusal = Refusal{path(), "this key appears twice in the same object"};
        return false;
    }

    bool parse_error(std::size_t bytes_read, const std::string& token, const json::exception& error) override {
        constexpr int kNumberOverflow = 406;  // nlohmann's out_of_range.406
        if (error.id == kNumberOverflow) {
            std::string problem = "must be a finite number (got ";
            refusal = Refusal{path(), problem.append(shortened(token)).append(")")};
        } else {
            std::string problem = "malformed JSON: ";
            refusal = Refusal{line_and_column(text_, bytes_read), problem.append(parser_reason(error))};
        }
        return false;
    }

private:
    struct Container {
        bool is_array = false;
        std::size_t index = 0;  // arrays: the element being read
        std::string key;        // objects: the member being read
        std::set<std::string> keys_seen;
    };

    bool open(bool is_array) {
        open_.push_back(Container{.is_array = is_array});
        return true;
    }
    bool close() {
        open_.pop_back();
        return value_read();
    }
    // A whole value has been read; in an array, the next one has the next index.
    bool value_read() {
        if (!open_.empty() && open_.back().is_array) ++open_.back().index;
        return true;
    }
    std::string path() const {
        std::string path;
        for (const Container& c : open_) path = c.is_array ? element_path(path, c.index) : member_path(path, c.key);
        return path;
    }

    std::string_view text_;
    std::vector<Container> open_;
};

json parse(const std::string& text) {
    FirstPass first_pass(text);
    if (!json::sax_parse(text, &first_pass)) throw first_pass.refusal.value();
    return json::parse(text);
}

// ---------------------------------------------------------------------------------------
// Values. A Rule is what a number must be, together with the words that say so.

struct Rule {
    bool (*accepts)(double);
    const char* words;
};

constexpr Rule kFinite{[](double v) { return std::isfinite(v); }, "must be a finite number"};
constexpr Rule kPositive{[](double v) { return std::isfinite(v) && v > 0.0; }, "must be a finite number > 0"};
constexpr Rule kNotNegative{[](double v) { return std::isfinite(v) && v >= 0.0; }, "must be a finite number >= 0"};
constexpr Rule kFraction{[](double v) { return v >= 0.0 && v <= 1.0; }, "must be a finite number in [0, 1]"};
// A number of loop passes: whole (15.0 is as good as 15, JSON does not tell them
// apart), and small enough for an int.
// Upper bounds keep a run finite: the canvas is a picture in memory (4096 x 4096 px is
// 64 MiB), one simulated second takes 1/dt steps, and every step runs every pass.
constexpr Rule kCount{[](double v) { return v >= 0.0 && v <= 1000.0 && std::floor(v) == v; },
                      "must be a whole number in [0, 1000]"};
constexpr Rule kCanvasSize{[](double v) { return v > 0.0 && v <= 4096.0; }, "must be a number in (0, 4096]"};
constexpr Rule kSubsteps{[](double v) { return v >= 1.0 && v <= 1000.0 && std::floor(v) == v; },
                         "must be a whole number in [1, 1000]"};
constexpr Rule kTimeStep{[](double v) { return v >= 1e-5 && v <= 1.0; }, "must be a number in [1e-5, 1]"};

double number(const json& value, const std::string& path, const Rule& rule) {
    if (!value.is_number() || !rule.accepts(value.get<double>())) refuse_value(path, rule.words, value);
    return value.get<double>();
}

// One `read` per kind of member, all with the same parameters so that a table of
// fields can call them alike; a rule means nothing to the kinds that are not numbers.
void read(const json& value, const std::string& path, const Rule& rule, double& out) {
    out = number(value, path, rule);
}

void read(const json& value, const std::string& path, const Rule& rule, int& out) {
    out = static_cast<int>(number(value, path, rule));
}

void read(const json& value, const std::string& path, const Rule& rule, Vec2& out) {
    if (!value.is_array() || value.size() != 2) refuse_value(path, "must be an array of two numbers [x, y]", value);
    out = Vec2{number(value[0], element_path(path, 0), rule), number(value[1], element_path(path, 1), rule)};
}

void read(const json& value, const std::string& path, const Rule&, bool& out) {
    if (!value.is_boolean()) refuse_value(path, "must be true or false", value);
    out = value.get<bool>();
}

// A word from a fixed list: a shape, an integrator, a broad phase, a friction model.
template <class Spelled>
    requires std::is_enum_v<Spelled>
void read(const json& value, const std::string& path, const Rule&, Spelled& out) {
    std::string choices = "must be ";
    for (const Spelled choice : all_values(out)) {
        if (value.is_string() && value.get_ref<const std::string&>() == spelling(choice)) {
            out = choice;
            return;
        }
        if (choice != all_values(out).front()) choices.append(choice == all_values(out).back() ? " or " : ", ");
        choices.append("\"").append(spelling(choice)).append("\"");
    }
    refuse_value(path, choices, value);
}

// ---------------------------------------------------------------------------------------
// Objects, each described by a table of its keys.

constexpr bool kRequired = true;

template <class Owner>
struct Field {
    const char* key;
    std::variant<double Owner::*, int Owner::*, bool Owner::*, Vec2 Owner::*, ShapeKind Owner::*,
                 Integrator Owner::*, BroadPhase Owner::*, FrictionModel Owner::*>
        member;
    Rule rule = kFinite;  // numbers, and both numbers of a vector
    bool required = false;
};

template <class Owner>
using Fields = std::vector<Field<Owner>>;

std::string comma_list(const std::vector<std::string>& words) {
    std::string list;
    for (const std::string& word : words) list.append(list.empty() ? "" : ", ").append(word);
    return list;
}

// A typo in a key would otherwise be ignored without a word, and the reader would wonder
// why the change has no effect; so each unknown key is refused with the keys known.
void refuse_unknown_keys(const json& object, const std::string& path, const std::vector<std::string>& known,
                         std::string_view owner) {
    for (const auto& item : object.items()) {
        if (std::find(known.begin(), known.end(), item.key()) != known.end()) continue;
        std::string problem = "unknown key; ";
        refuse(member_path(path, item.key()), problem.append(owner).append(" takes ").append(comma_list(known)));
    }
}

template <class Owner>
std::vector<std::string> keys_of(const Fields<Owner>& fields, bool only_required) {
    std::vector<std::string> keys;
    for (const Field<Owner>& field : fields) {
        if (field.required || !only_required) keys.emplace_back(field.key);
    }
    return keys;
}

// Fills `out` from `object`: members the object leaves out keep the value `out` has.
// `owner` names the object in messages ("world", "a circle body").
template <class Owner>
void read_object(const json& object, const std::string& path, const Fields<Owner>& fields, std::string_view owner,
                 Owner& out) {
    if (!object.is_object()) refuse_value(path, "must be an object {...}", object);
    refuse_unknown_keys(object, path, keys_of(fields, false), owner);
    for (const Field<Owner>& field : fields) {
        const std::string field_path = member_path(path, field.key);
        const auto found = object.find(field.key);
        if (found != object.end()) {
            std::visit([&](auto member) { read(*found, field_path, field.rule, out.*member); }, field.member);
        } else if (field.required) {
            std::string problem = "missing; ";
            refuse(field_path, problem.append(owner).append(" needs ").append(comma_list(keys_of(fields, true))));
        }
    }
}

const Fields<WorldSettings>& world_fields() {
    using W = WorldSettings;
    static const Fields<W> fields{
        {"width", &W::width, kCanvasSize},
        {"height", &W::height, kCanvasSize},
        {"gravity", &W::gravity},
        {"dt", &W::dt, kTimeStep},
        {"relaxation_iterations", &W::relaxation_iterations, kCount},
        {"correction_rate", &W::correction_rate, kFraction},
        {"movement", &W::movement},
        {"positional_correction", &W::positional_correction},
        {"remove_out_of_bounds", &W::remove_out_of_bounds},
    };
    return fields;
}

const Fields<WorldSettings>& world_fields_with_knobs() {
    using W = WorldSettings;
    static const Fields<W> fields = [] {
        Fields<W> all = world_fields();
        all.insert(all.end(), {{"substeps", &W::substeps, kSubsteps},
                               {"integrator", &W::integrator},
                               {"broad_phase", &W::broad_phase},
                               {"friction_model", &W::friction_model},
                               {"rotation", &W::rotation},
                               {"friction", &W::friction}});
        return all;
    }();
    return fields;
}

// A body's keys depend on its shape: a radius on a rectangle is as wrong as a typo.
// Listed in the order messages show them: what the body is, where, how big, the rest.
Fields<BodyDescription> body_fields(ShapeKind shape) {
    using B = BodyDescription;
    const Fields<B> sizes = shape == ShapeKind::rectangle
                                ? Fields<B>{{"width", &B::width, kPositive, kRequired},
                                            {"height", &B::height, kPositive, kRequired}}
                                : Fields<B>{{"radius", &B::radius, kPositive, kRequired}};
    Fields<B> fields{{"shape", &B::shape, kFinite, kRequired}, {"center", &B::center, kFinite, kRequired}};
    fields.insert(fields.end(), sizes.begin(), sizes.end());
    fields.insert(fields.end(), {{"mass", &B::mass, kNotNegative},
                                 {"friction", &B::friction, kNotNegative},
                                 {"restitution", &B::restitution, kFraction},
                                 {"angle", &B::angle},
                                 {"velocity", &B::velocity},
                                 {"angular_velocity", &B::angular_velocity}});
    return fields;
}

BodyDescription read_body(const json& object, const std::string& path) {
    if (!object.is_object()) refuse_value(path, "must be an object {...}", object);
    // The shape decides which keys the body may have, so it is read before the rest.
    const std::string shape_path = member_path(path, "shape");
    const auto shape = object.find("shape");
    if (shape == object.end()) refuse(shape_path, R"(missing; every body needs "shape": "rectangle" or "circle")");
    BodyDescription body;
    read(*shape, shape_path, kFinite, body.shape);
    std::string owner = "a ";
    read_object(object, path, body_fields(body.shape), owner.append(shape_name(body.shape)).append(" body"), body);
    return body;
}

std::vector<BodyDescription> read_bodies(const json& list, const std::string& path) {
    if (!list.is_array()) refuse_value(path, "must be an array [...] of bodies", list);
    std::vector<BodyDescription> bodies;
    for (std::size_t i = 0; i < list.size(); ++i) bodies.push_back(read_body(list[i], element_path(path, i)));
    return bodies;
}

SceneDescription read_scene(const json& root, const WorldSettings& defaults, WorldKeys keys) {
    if (!root.is_object()) refuse_value("", "must be an object {...}", root);
    refuse_unknown_keys(root, "", {"world", "bodies"}, "a scene");
    SceneDescription scene{defaults, {}};
    if (const auto world = root.find("world"); world != root.end()) {
        read_object(*world, "world", keys == WorldKeys::with_knobs ? world_fields_with_knobs() : world_fields(), "world",
                    scene.world);
    }
    if (const auto bodies = root.find("bodies"); bodies != root.end()) scene.bodies = read_bodies(*bodies, "bodies");
    return scene;
}

}  // namespace

SceneDescription load_scene(const fs::path& file, const WorldSettings& defaults, WorldKeys keys) {
    try {
        return read_scene(parse(read_text(file)), defaults, keys);
    } catch (const Refusal& refusal) {
        std::string message = file.string();
        message.append(": ").append(refusal.where.empty() ? "top level" : refusal.where);
        throw SceneError(message.append(": ").append(refusal.problem));
    }
}

}  // namespace browser
