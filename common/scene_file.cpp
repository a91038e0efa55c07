#include "scene_file.h"

#include <algorithm>
#include <cctype>
#include <charconv>
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

#include "input_file.h"
#include "message_text.h"
#include "png_io.h"  // FileError

namespace browser {

using lib::Vec2;
namespace fs = std::filesystem;
using json = nlohmann::json;

namespace {

// ---------------------------------------------------------------------------------------
// Refusals. Helpers deep in the reading throw a Refusal (where + what); load_scene puts
// the file name in front, so no helper needs to carry it around.

struct Refusal {
    std::string where;  // a JSON path ("springs[3].anchor"), or "line 2, column 7"
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
std::string shown(const json& value) { return shortened(value.dump(-1, ' ', true, json::error_handler_t::replace)); }

[[noreturn]] void refuse_value(std::string where, std::string_view problem, const json& got) {
    std::string text(problem);
    text.append(" (got ").append(shown(got)).append(")");
    refuse(std::move(where), std::move(text));
}

// JSON paths as a reader would write them: world.gravity[1], springs[3].anchor. A key
// that is not a plain word is quoted (springs[0]["my key"]), so that a strange key, even
// one holding a line break, cannot break the one-line message.
constexpr std::size_t kLongestPlainKey = 40;

bool is_plain_word(std::string_view key) {
    return !key.empty() &&
           std::all_of(key.begin(), key.end(), [](unsigned char c) { return std::isalnum(c) || c == '_'; });
}

std::string member_path(const std::string& object, const std::string& key) {
    std::string path = object;
    if (key.size() > kLongestPlainKey) {
        // Its start, quoted, with "..." inside the quotes where it is cut.
        std::string start = shown(json(key.substr(0, kLongestPlainKey / 2)));
        if (start.ends_with('"')) start.pop_back();
        return path.append("[").append(start).append("...\"]");
    }
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

// What a scene file may be: a regular file of at most kMaxSceneBytes, read as every
// tool reads its input (input_file.h: a FIFO, a device or a folder refused in one line),
// its refusal a SceneError like every other of the scene's.
std::string read_text(const fs::path& file) {
    try {
        return read_whole_file(file, kMaxSceneBytes, "a scene file");
    } catch (const FileError& error) {
        throw SceneError(error.what());
    }
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
// at line 1, column 9: "), whose position we have already given our own way, and
// without its "; last read: '...'" (the text itself, of any length), cut at a word.
std::string parser_reason(const json::exception& error) {
    std::string_view message = error.what();
    const std::size_t colon = message.find(": ", message.find(']'));
    if (colon != std::string_view::npos) message.remove_prefix(colon + 2);
    message = message.substr(0, message.find("; last read"));
    return first_words(message, kLongestShown);
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
            refusal = Refusal{path(), problem.append(printable(shortened(token))).append(")")};
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

    // The parser itself keeps its nesting on the heap, but a document deeper than a
    // scene can use would be refused later anyway, and printing or walking it would
    // recurse as deep as it goes; so it stops here, at the first level too many.
    bool open(bool is_array) {
        if (open_.size() == kMaxNesting) {
            refusal = Refusal{path(), "nested deeper than a scene can use (" + std::to_string(kMaxNesting) +
                                          " levels: {\"list\": [{\"key\": [[x, y]]}]})"};
            return false;
        }
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
// Values.

double number(const json& value, const std::string& path, const NumberRule& rule) {
    if (!value.is_number() || !rule.accepts(value.get<double>())) refuse_value(path, rule.words, value);
    return value.get<double>();
}

Vec2 vector(const json& value, const std::string& path, const NumberRule& rule) {
    if (!value.is_array() || value.size() != 2) refuse_value(path, "must be an array of two numbers [x, y]", value);
    return Vec2{number(value[0], element_path(path, 0), rule), number(value[1], element_path(path, 1), rule)};
}

// A list of points: the right number of [x, y], then the stage's check of them together.
std::vector<Vec2> points(const json& value, const std::string& path, const NumberRule& rule, const PointsRule& shape) {
    const std::string many = "must be an array of " + std::to_string(shape.fewest) + " to " +
                             std::to_string(shape.most) + " points [[x, y], ...]";
    if (!value.is_array() || value.size() < shape.fewest || value.size() > shape.most) {
        refuse_value(path, many, value);
    }
    std::vector<Vec2> read;
    for (std::size_t i = 0; i < value.size(); ++i) read.push_back(vector(value[i], element_path(path, i), rule));
    if (shape.check) {
        if (const std::optional<std::string> problem = shape.check(read)) refuse(path, *problem);
    }
    return read;
}

bool flag(const json& value, const std::string& path) {
    if (!value.is_boolean()) refuse_value(path, "must be true or false", value);
    return value.get<bool>();
}

std::string choices(std::span<const std::string_view> words);

// A word from a fixed list; its place in the list.
std::size_t word(const json& value, const std::string& path, std::span<const std::string_view> spellings) {
    for (std::size_t i = 0; i < spellings.size(); ++i) {
        if (value.is_string() && value.get_ref<const std::string&>() == spellings[i]) return i;
    }
    std::string problem = "must be ";
    refuse_value(path, problem.append(choices(spellings)), value);
}

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

void require_object(const json& value, const std::string& path) {
    if (!value.is_object()) refuse_value(path, "must be an object {...}", value);
}

// ---------------------------------------------------------------------------------------
// Keys. A value is checked first and only stored once it has passed; a world's keys are
// stored once the whole file has passed, so a refused file leaves every setting as it
// was.

using Assignment = std::function<void()>;

Assignment read_key(const SceneKey& key, const json& value, const std::string& path) {
    return std::visit(
        [&](const auto& target) -> Assignment {
            using Target = std::decay_t<decltype(target)>;
            if constexpr (std::is_same_v<Target, SceneKey::Number>) {
                return [setting = target.setting, v = number(value, path, target.rule)] { *setting = v; };
            } else if constexpr (std::is_same_v<Target, SceneKey::Count>) {
                return [setting = target.setting, v = number(value, path, target.rule)] {
                    *setting = static_cast<int>(v);
                };
            } else if constexpr (std::is_same_v<Target, SceneKey::Flag>) {
                return [setting = target.setting, v = flag(value, path)] { *setting = v; };
            } else if constexpr (std::is_same_v<Target, SceneKey::Vector>) {
                return [setting = target.setting, v = vector(value, path, target.rule)] { *setting = v; };
            } else if constexpr (std::is_same_v<Target, SceneKey::Points>) {
                return
                    [setting = target.setting, v = points(value, path, target.rule, target.points)] { *setting = v; };
            } else {
                return [choose = target.choose, i = word(value, path, target.spellings)] { choose(i); };
            }
        },
        key.target());
}

// The assignments of the keys `object` gives, in the order of `keys`. `owner` names the
// object in a refusal ("this stage's world", "a hard spring"); `known` leads with the
// keys read before these (an element's kind key).
std::vector<Assignment> read_keys(const json& object, const std::string& path, std::span<const SceneKey> keys,
                                  std::string_view owner, std::vector<std::string> known = {}) {
    std::vector<std::string> required = known;
    for (const SceneKey& key : keys) {
        known.emplace_back(key.name());
        if (key.required()) required.emplace_back(key.name());
    }
    refuse_unknown_keys(object, path, known, owner);
    std::vector<Assignment> assignments;
    for (const SceneKey& key : keys) {
        const std::string key_path = member_path(path, std::string(key.name()));
        const auto found = object.find(std::string(key.name()));
        if (found != object.end()) {
            assignments.push_back(read_key(key, *found, key_path));
        } else if (key.required()) {
            std::string problem = "missing; ";
            refuse(key_path, problem.append(owner).append(" needs ").append(comma_list(required)));
        }
    }
    return assignments;
}

std::vector<Assignment> read_world(const json& world, std::span<const SceneKey> keys) {
    const std::string path = "world";
    require_object(world, path);
    return read_keys(world, path, keys, "this stage's world");
}

// ---------------------------------------------------------------------------------------
// Lists. An element's keys depend on its kind, so the kind is read first: a key of
// another kind on it is as wrong as a typo.

// "\"hard\" or \"soft\"": the words a kind key takes, as a refusal lists them.
std::string choices(std::span<const std::string_view> words) {
    std::string text;
    for (std::size_t i = 0; i < words.size(); ++i) {
        if (i > 0) text.append(i + 1 == words.size() ? " or " : ", ");
        text.append("\"").append(words[i]).append("\"");
    }
    return text;
}

void read_element(const json& object, const std::string& path, const SceneList& list) {
    require_object(object, path);
    const std::string kind_key(list.kind_key);
    const std::string kind_path = member_path(path, kind_key);
    const auto kind = object.find(kind_key);
    if (kind == object.end()) {
        std::string problem = "missing; every ";
        refuse(kind_path, problem.append(list.element)
                              .append(" needs \"")
                              .append(list.kind_key)
                              .append("\": ")
                              .append(choices(list.kinds)));
    }
    const std::size_t chosen = word(*kind, kind_path, list.kinds);
    const std::vector<SceneKey> keys = list.add(chosen);
    std::string owner = "a ";
    owner.append(list.kinds[chosen]).append(" ").append(list.element);
    for (const Assignment& assign : read_keys(object, path, keys, owner, {kind_key})) assign();
}

void read_list(const json& elements, const std::string& path, const SceneList& list) {
    if (!elements.is_array()) {
        std::string problem = "must be an array [...] of ";
        refuse_value(path, problem.append(list.name), elements);
    }
    if (elements.size() > list.most) {
        refuse(path, "more than " + std::to_string(list.most) + " " + std::string(list.name) + " (got " +
                         std::to_string(elements.size()) + "); " + std::string(list.why_most));
    }
    for (std::size_t i = 0; i < elements.size(); ++i) read_element(elements[i], element_path(path, i), list);
}

void read_scene(const json& root, std::span<const SceneKey> world_keys, std::span<const SceneList> lists) {
    require_object(root, "");
    std::vector<std::string> parts{"world"};
    for (const SceneList& list : lists) parts.emplace_back(list.name);
    refuse_unknown_keys(root, "", parts, "a scene");
    std::vector<Assignment> world;
    if (const auto found = root.find("world"); found != root.end()) world = read_world(*found, world_keys);
    for (const SceneList& list : lists) {
        const std::string name(list.name);
        if (const auto found = root.find(name); found != root.end()) read_list(*found, name, list);
    }
    for (const Assignment& assign : world) assign();
}

// The shortest text that reads back to exactly `value`.
std::string number_json(double value) {
    char text[32];
    const auto result = std::to_chars(text, text + sizeof text, value);
    return std::string(text, result.ptr);
}

// The words of a rule without its "must be ".
std::string values_of(const NumberRule& rule) {
    std::string_view words = rule.words;
    constexpr std::string_view kMustBe = "must be ";
    if (words.starts_with(kMustBe)) words.remove_prefix(kMustBe.size());
    return std::string(words);
}

}  // namespace

std::string scene_text(const fs::path& file) { return read_text(file); }

void load_scene(const fs::path& file, std::span<const SceneKey> world_keys, std::span<const SceneList> lists) {
    read_scene_text(read_text(file), file.string(), world_keys, lists);
}

void read_scene_text(const std::string& text, std::string_view source, std::span<const SceneKey> world_keys,
                     std::span<const SceneList> lists) {
    try {
        if (text.size() > kMaxSceneBytes) {
            refuse("", "longer than " + std::to_string(kMaxSceneBytes) + " bytes, the most a scene may hold");
        }
        // The parser would stop at a NUL and take the text before it as the whole scene.
        if (const std::size_t nul = text.find('\0'); nul != std::string::npos) {
            refuse(line_and_column(text, nul + 1), "a NUL byte, which a scene file never holds");
        }
        read_scene(parse(text), world_keys, lists);
    } catch (const Refusal& refusal) {
        std::string message = printable(source);
        message.append(": ").append(refusal.where.empty() ? "top level" : refusal.where);
        throw SceneError(message.append(": ").append(refusal.problem));
    }
}

KeyDescription describe(const SceneKey& key) {
    KeyDescription description{.name = std::string(key.name()), .required = key.required()};
    std::visit(
        [&](const auto& target) {
            using Target = std::decay_t<decltype(target)>;
            if constexpr (std::is_same_v<Target, SceneKey::Number>) {
                description.values = values_of(target.rule);
                description.value_now = number_json(*target.setting);
            } else if constexpr (std::is_same_v<Target, SceneKey::Count>) {
                description.values = values_of(target.rule);
                description.value_now = std::to_string(*target.setting);
            } else if constexpr (std::is_same_v<Target, SceneKey::Flag>) {
                description.values = "true or false";
                description.value_now = *target.setting ? "true" : "false";
            } else if constexpr (std::is_same_v<Target, SceneKey::Vector>) {
                description.values = "[x, y], each " + values_of(target.rule);
                description.value_now =
                    "[" + number_json(target.setting->x) + ", " + number_json(target.setting->y) + "]";
            } else if constexpr (std::is_same_v<Target, SceneKey::Points>) {
                description.values = std::to_string(target.points.fewest) + " to " +
                                     std::to_string(target.points.most) + " points [[x, y], ...], each " +
                                     values_of(target.rule);
                std::string now = "[";
                for (const Vec2 point : *target.setting) {
                    if (now.size() > 1) now.append(", ");
                    now.append("[").append(number_json(point.x)).append(", ").append(number_json(point.y)).append("]");
                }
                description.value_now = now.append("]");
            } else {
                description.values = choices(target.spellings);
                if (const auto now = target.now())
                    description.value_now = "\"" + std::string(target.spellings[*now]) + "\"";
            }
        },
        key.target());
    return description;
}

}  // namespace browser
