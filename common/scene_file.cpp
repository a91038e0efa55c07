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

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <nlohmann/json.hpp>

#include "message_text.h"

namespace browser {

using lib::Vec2;
namespace fs = std::filesystem;
using json = nlohmann::json;

std::string_view shape_name(ShapeKind shape) { return shape == ShapeKind::circle ? "circle" : "rectangle"; }

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
std::string shown(const json& value) { return shortened(value.dump(-1, ' ', true, json::error_handler_t::replace)); }

[[noreturn]] void refuse_value(std::string where, std::string_view problem, const json& got) {
    std::string text(problem);
    text.append(" (got ").append(shown(got)).append(")");
    refuse(std::move(where), std::move(text));
}

// JSON paths as a reader would write them: world.gravity[1], bodies[3].radius. A key
// that is not a plain word is quoted (bodies[0]["my key"]), so that a strange key, even
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

// What a scene file may be: a regular file of at most kMaxSceneBytes. Opened without
// blocking (a FIFO with no writer would wait for ever) and checked with fstat once open
// (a device, /dev/zero or /dev/urandom, would read without end), then read up to one
// byte past the limit, so a longer file is refused without reading it all.
std::string read_text(const fs::path& file) {
    const auto cannot_read = [&](const std::string& reason) {
        std::string message = printable(file.string());
        throw SceneError(message.append(": cannot read: ").append(reason));
    };
    const int fd = ::open(file.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY);
    if (fd < 0) {
        const int error = errno;
        if (error == ENOENT) cannot_read("no such file");
        if (error == ELOOP) cannot_read("a loop of symbolic links");
        cannot_read(std::strerror(error));
    }
    struct Closer {
        int fd;
        ~Closer() { ::close(fd); }
    } closer{fd};
    struct stat status {};
    if (::fstat(fd, &status) != 0) cannot_read(std::strerror(errno));
    if (S_ISDIR(status.st_mode)) cannot_read("it is a folder");
    if (!S_ISREG(status.st_mode)) {
        cannot_read(S_ISFIFO(status.st_mode)                             ? "it is a FIFO, not a regular file"
                    : S_ISCHR(status.st_mode) || S_ISBLK(status.st_mode) ? "it is a device, not a regular file"
                                                                         : "it is not a regular file");
    }
    const auto too_long = [&] {
        cannot_read("longer than " + std::to_string(kMaxSceneBytes) + " bytes, the most a scene file may hold");
    };
    if (status.st_size > static_cast<off_t>(kMaxSceneBytes)) too_long();
    std::string text;
    char buffer[1 << 16];
    for (;;) {
        const ssize_t got = ::read(fd, buffer, sizeof buffer);
        if (got < 0 && errno == EINTR) continue;
        if (got < 0) cannot_read(std::strerror(errno));
        if (got == 0) break;
        text.append(buffer, static_cast<std::size_t>(got));
        if (text.size() > kMaxSceneBytes) too_long();  // the file grew while we read it
    }
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
                                          " levels: {\"bodies\": [{\"center\": [x, y]}]})"};
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

bool flag(const json& value, const std::string& path) {
    if (!value.is_boolean()) refuse_value(path, "must be true or false", value);
    return value.get<bool>();
}

// A word from a fixed list; its place in the list.
std::size_t word(const json& value, const std::string& path, std::span<const std::string_view> spellings) {
    std::string choices = "must be ";
    for (std::size_t i = 0; i < spellings.size(); ++i) {
        if (value.is_string() && value.get_ref<const std::string&>() == spellings[i]) return i;
        if (i > 0) choices.append(i + 1 == spellings.size() ? " or " : ", ");
        choices.append("\"").append(spellings[i]).append("\"");
    }
    refuse_value(path, choices, value);
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
// The world: the keys the stage reads. Each value is checked first and only stored once
// the whole file has passed, so a refused file leaves every setting as it was.

using Assignment = std::function<void()>;

Assignment read_world_key(const WorldKey& key, const json& value, const std::string& path) {
    return std::visit(
        [&](const auto& target) -> Assignment {
            using Target = std::decay_t<decltype(target)>;
            if constexpr (std::is_same_v<Target, WorldKey::Number>) {
                return [setting = target.setting, v = number(value, path, target.rule)] { *setting = v; };
            } else if constexpr (std::is_same_v<Target, WorldKey::Count>) {
                return [setting = target.setting, v = number(value, path, target.rule)] {
                    *setting = static_cast<int>(v);
                };
            } else if constexpr (std::is_same_v<Target, WorldKey::Flag>) {
                return [setting = target.setting, v = flag(value, path)] { *setting = v; };
            } else if constexpr (std::is_same_v<Target, WorldKey::Vector>) {
                return [setting = target.setting, v = vector(value, path, target.rule)] { *setting = v; };
            } else {
                return [choose = target.choose, i = word(value, path, target.spellings)] { choose(i); };
            }
        },
        key.target());
}

std::vector<Assignment> read_world(const json& world, std::span<const WorldKey> keys) {
    const std::string path = "world";
    require_object(world, path);
    std::vector<std::string> known;
    for (const WorldKey& key : keys) known.emplace_back(key.name());
    refuse_unknown_keys(world, path, known, "this stage's world");
    std::vector<Assignment> assignments;
    for (const WorldKey& key : keys) {
        const auto found = world.find(std::string(key.name()));
        if (found != world.end()) assignments.push_back(read_world_key(key, *found, member_path(path, found.key())));
    }
    return assignments;
}

// ---------------------------------------------------------------------------------------
// Bodies. A body's keys depend on its shape: a radius on a rectangle is as wrong as a
// typo. Listed in the order messages show them: what the body is, where, how big, the rest.

struct BodyKey {
    const char* name;
    std::variant<double BodyDescription::*, Vec2 BodyDescription::*> member;
    NumberRule rule = rules::kFinite;
    bool required = false;
};

constexpr bool kRequired = true;

std::vector<BodyKey> body_keys(ShapeKind shape) {
    using B = BodyDescription;
    static const BodyKey kRectangleSizes[] = {{"width", &B::width, rules::kSize, kRequired},
                                              {"height", &B::height, rules::kSize, kRequired}};
    static const BodyKey kCircleSizes[] = {{"radius", &B::radius, rules::kSize, kRequired}};
    static const BodyKey kAttributes[] = {{"mass", &B::mass, rules::kMass},
                                          {"friction", &B::friction, rules::kFriction},
                                          {"restitution", &B::restitution, rules::kFraction},
                                          {"angle", &B::angle, rules::kAngle},
                                          {"velocity", &B::velocity, rules::kSpeed},
                                          {"angular_velocity", &B::angular_velocity, rules::kTurnRate}};
    const std::span<const BodyKey> sizes = shape == ShapeKind::rectangle ? std::span<const BodyKey>(kRectangleSizes)
                                                                         : std::span<const BodyKey>(kCircleSizes);
    std::vector<BodyKey> keys{{"center", &B::center, rules::kPosition, kRequired}};
    keys.reserve(1 + sizes.size() + std::size(kAttributes));
    for (const BodyKey& key : sizes) keys.push_back(key);
    for (const BodyKey& key : kAttributes) keys.push_back(key);
    return keys;
}

BodyDescription read_body(const json& object, const std::string& path, StageBodyKeys stage_keys) {
    require_object(object, path);
    // The shape decides which keys the body may have, so it is read before the rest.
    const std::string shape_path = member_path(path, "shape");
    const auto shape = object.find("shape");
    if (shape == object.end()) refuse(shape_path, R"(missing; every body needs "shape": "rectangle" or "circle")");
    constexpr std::array<std::string_view, 2> kShapes{"rectangle", "circle"};
    BodyDescription body;
    body.shape = word(*shape, shape_path, kShapes) == 0 ? ShapeKind::rectangle : ShapeKind::circle;

    const std::vector<BodyKey> keys = body_keys(body.shape);
    std::vector<std::string> known{"shape"}, required{"shape"};
    for (const BodyKey& key : keys) {
        known.emplace_back(key.name);
        if (key.required) required.emplace_back(key.name);
    }
    if (stage_keys.bullet) known.emplace_back("bullet");
    std::string owner = "a ";
    owner.append(shape_name(body.shape)).append(" body");
    refuse_unknown_keys(object, path, known, owner);
    for (const BodyKey& key : keys) {
        const std::string key_path = member_path(path, key.name);
        const auto found = object.find(key.name);
        if (found == object.end()) {
            if (!key.required) continue;
            std::string problem = "missing; ";
            refuse(key_path, problem.append(owner).append(" needs ").append(comma_list(required)));
        }
        std::visit(
            [&](auto member) {
                if constexpr (std::is_same_v<decltype(member), Vec2 BodyDescription::*>) {
                    body.*member = vector(*found, key_path, key.rule);
                } else {
                    body.*member = number(*found, key_path, key.rule);
                }
            },
            key.member);
    }
    if (const auto bullet = object.find("bullet"); stage_keys.bullet && bullet != object.end()) {
        body.bullet = flag(*bullet, member_path(path, "bullet"));
    }
    return body;
}

std::vector<BodyDescription> read_bodies(const json& list, const std::string& path, StageBodyKeys stage_keys) {
    if (!list.is_array()) refuse_value(path, "must be an array [...] of bodies", list);
    if (list.size() > kMaxBodies) {
        refuse(path, "more than " + std::to_string(kMaxBodies) + " bodies (got " + std::to_string(list.size()) +
                         "); every step tests every pair of them");
    }
    std::vector<BodyDescription> bodies;
    for (std::size_t i = 0; i < list.size(); ++i)
        bodies.push_back(read_body(list[i], element_path(path, i), stage_keys));
    return bodies;
}

std::vector<BodyDescription> read_scene(const json& root, std::span<const WorldKey> world_keys,
                                        StageBodyKeys stage_keys) {
    require_object(root, "");
    refuse_unknown_keys(root, "", {"world", "bodies"}, "a scene");
    std::vector<Assignment> world;
    if (const auto found = root.find("world"); found != root.end()) world = read_world(*found, world_keys);
    std::vector<BodyDescription> bodies;
    if (const auto found = root.find("bodies"); found != root.end()) bodies = read_bodies(*found, "bodies", stage_keys);
    for (const Assignment& assign : world) assign();
    return bodies;
}

}  // namespace

std::vector<BodyDescription> load_scene(const fs::path& file, std::span<const WorldKey> world_keys,
                                        StageBodyKeys stage_keys) {
    return read_scene_text(read_text(file), file.string(), world_keys, stage_keys);
}

std::vector<BodyDescription> read_scene_text(const std::string& text, std::string_view source,
                                             std::span<const WorldKey> world_keys, StageBodyKeys stage_keys) {
    try {
        if (text.size() > kMaxSceneBytes) {
            refuse("", "longer than " + std::to_string(kMaxSceneBytes) + " bytes, the most a scene may hold");
        }
        // The parser would stop at a NUL and take the text before it as the whole scene.
        if (const std::size_t nul = text.find('\0'); nul != std::string::npos) {
            refuse(line_and_column(text, nul + 1), "a NUL byte, which a scene file never holds");
        }
        return read_scene(parse(text), world_keys, stage_keys);
    } catch (const Refusal& refusal) {
        std::string message = printable(source);
        message.append(": ").append(refusal.where.empty() ? "top level" : refusal.where);
        throw SceneError(message.append(": ").append(refusal.problem));
    }
}

}  // namespace browser
