#include "state_dump.h"

#include <cerrno>
#include <charconv>
#include <cstring>
#include <stdexcept>
#include <string>
#include <system_error>
#include <utility>

#include "scene_file.h"

namespace browser {

namespace fs = std::filesystem;

namespace {

// What %.17g prints, but with std::to_chars, which ignores the C locale: a locale with
// a decimal comma would otherwise break both the CSV and strtod in another locale.
void append_number(std::string& line, double value) {
    constexpr int kRoundTripDigits = 17;  // enough to tell any two doubles apart
    char digits[32];                      // the longest, "-2.2250738585072014e-308", needs 24
    const auto end = std::to_chars(digits, digits + sizeof digits, value, std::chars_format::general,
                                   kRoundTripDigits).ptr;
    line.append(digits, end);
}

// errno after a failed stream operation, when the library set one; callers clear errno
// first so that an old value from elsewhere is not blamed.
std::string failure_reason() {
    return errno != 0 ? std::strerror(errno) : "the write failed";
}

bool is_shape_name(std::string_view shape) {
    return shape == shape_name(ShapeKind::rectangle) || shape == shape_name(ShapeKind::circle);
}

}  // namespace

StateDump::StateDump(fs::path path) : path_(std::move(path)), partial_(fs::path(path_).concat(".partial")) {
    std::error_code error;
    if (fs::is_directory(path_, error)) fail("it is a folder");
    errno = 0;
    out_.open(partial_, std::ios::binary | std::ios::trunc);
    if (!out_) fail(failure_reason());
    out_ << "step,index,shape,cx,cy,angle,vx,vy,angular_velocity\n";
}

StateDump::~StateDump() {
    if (finished_) return;
    out_.close();
    std::error_code ignored;
    fs::remove(partial_, ignored);
}

void StateDump::row(long step, std::size_t index, std::string_view shape, Vec2 center, double angle, Vec2 velocity,
                    double angular_velocity) {
    if (finished_) throw std::logic_error("StateDump::row after finish()");
    if (!is_shape_name(shape)) {
        std::string message = "StateDump::row: unknown shape \"";
        throw std::invalid_argument(message.append(shape).append("\""));
    }
    std::string line = std::to_string(step);
    line.append(",").append(std::to_string(index)).append(",").append(shape);
    for (const double value : {center.x, center.y, angle, velocity.x, velocity.y, angular_velocity}) {
        line += ',';
        append_number(line, value);
    }
    line += '\n';
    errno = 0;
    out_ << line;
    if (!out_) fail(failure_reason());
}

void StateDump::finish() {
    if (finished_) return;
    errno = 0;
    out_.close();  // flushes: a full disk shows here at the latest
    if (!out_) fail(failure_reason());
    std::error_code error;
    fs::rename(partial_, path_, error);
    if (error) fail(error.message());
    finished_ = true;
}

void StateDump::fail(const std::string& reason) {
    out_.close();
    std::error_code ignored;
    fs::remove(partial_, ignored);
    std::string message = "cannot write state dump ";
    throw FileError(message.append(path_.string()).append(": ").append(reason));
}

}  // namespace browser
