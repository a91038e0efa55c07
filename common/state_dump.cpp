#include "state_dump.h"

#include <cerrno>
#include <charconv>
#include <cstring>
#include <stdexcept>
#include <string>
#include <system_error>
#include <utility>

#include <sys/stat.h>

#include <algorithm>
#include <optional>

#include "message_text.h"
#include "output_folder.h"
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

// Why `path` may not be replaced by a dump, if it may not: only a regular file is. Read
// with lstat, so a symbolic link is seen as one, not as what it points to.
std::optional<std::string> not_replaceable(const fs::path& path) {
    struct stat status {};
    if (::lstat(path.c_str(), &status) != 0) return std::nullopt;  // nothing there yet (or no folder: open says)
    if (S_ISREG(status.st_mode)) return std::nullopt;
    const char* what = S_ISDIR(status.st_mode)    ? "a folder"
                       : S_ISLNK(status.st_mode)  ? "a symbolic link"
                       : S_ISFIFO(status.st_mode) ? "a FIFO"
                       : S_ISCHR(status.st_mode) || S_ISBLK(status.st_mode) ? "a device"
                                                                           : "not a regular file";
    return std::string("it is ") + what + "; --dump writes only a regular file, new or one it replaces";
}

// `path` with its links and dots resolved as far as it exists.
fs::path resolved(const fs::path& path) {
    std::error_code error;
    fs::path full = fs::weakly_canonical(fs::absolute(path, error), error);
    return error ? path.lexically_normal() : full;
}

// Whether `path` is the folder `out` (0), lies inside it (1), or neither (-1).
int place_in(const fs::path& path, const fs::path& out) {
    if (out.empty()) return -1;
    const fs::path folder = resolved(out), file = resolved(path);
    const auto [end, rest] = std::mismatch(folder.begin(), folder.end(), file.begin(), file.end());
    if (end != folder.end()) return -1;
    return rest == file.end() ? 0 : 1;
}

}  // namespace

NonFiniteState::NonFiniteState(long step, std::size_t index, std::string_view shape)
    : std::runtime_error("step " + std::to_string(step) + ": body " + std::to_string(index) + " (" + std::string(shape) +
                         ") has a position or velocity that is not a finite number; the scene is beyond what this "
                         "engine can compute, and nothing was written") {}

StateDump::StateDump(fs::path path, const fs::path& out) : path_(std::move(path)) {
    if (path_.empty()) throw std::invalid_argument("StateDump: no file named");
    const fs::path out_folder = OutputFolder::normalized(out);
    const int place = place_in(path_, out_folder);
    if (place == 0) throw OutputRefused("cannot write state dump " + printable(path_.string()) + ": it is the --out folder");
    inside_out_ = place == 1;
    if (inside_out_) {
        // The run replaces the whole folder: the dump waits beside it, and moves in after.
        partial_ = out_folder;
        partial_ += ".dump-partial";
        std::error_code error;
        if (out_folder.has_parent_path()) fs::create_directories(out_folder.parent_path(), error);
    } else {
        if (const auto reason = not_replaceable(path_)) {
            throw OutputRefused("cannot write state dump " + printable(path_.string()) + ": " + *reason);
        }
        partial_ = fs::path(path_).concat(".partial");
    }
    note_interruptions();
    remove_stale_leftovers(partial_, "-");
    partial_ += process_suffix();
    std::error_code ignored;
    fs::remove(partial_, ignored);  // left over from a crashed run that had our process id
    leftover_.emplace(partial_);
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
    stop_if_interrupted();
    std::error_code error;
    if (inside_out_ && path_.has_parent_path()) fs::create_directories(path_.parent_path(), error);
    if (error) fail(error.message());
    // Checked again: the file named may have become something else during the run.
    if (const auto reason = not_replaceable(path_)) fail(*reason);
    fs::rename(partial_, path_, error);
    if (error) fail(error.message());
    finished_ = true;
    leftover_.reset();
}

void StateDump::fail(const std::string& reason) {
    out_.close();
    std::error_code ignored;
    fs::remove(partial_, ignored);
    std::string message = "cannot write state dump ";
    throw FileError(message.append(printable(path_.string())).append(": ").append(printable(reason)));
}

}  // namespace browser
