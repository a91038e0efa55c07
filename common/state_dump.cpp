#include "state_dump.h"

#include <cerrno>
#include <charconv>
#include <cstring>
#include <stdexcept>
#include <string>
#include <system_error>
#include <utility>

#include <algorithm>
#include <optional>

#include "message_text.h"
#include "output_folder.h"
#include "write_guard.h"

namespace browser {

namespace fs = std::filesystem;

namespace {

// What %.17g prints, but with std::to_chars, which ignores the C locale: a locale with
// a decimal comma would otherwise break both the CSV and strtod in another locale.
void append_number(std::string& line, double value) {
    constexpr int kRoundTripDigits = 17;  // enough to tell any two doubles apart
    char digits[32];                      // the longest, "-2.2250738585072014e-308", needs 24
    const auto end =
        std::to_chars(digits, digits + sizeof digits, value, std::chars_format::general, kRoundTripDigits).ptr;
    line.append(digits, end);
}

// errno after a failed stream operation, when the library set one; callers clear errno
// first so that an old value from elsewhere is not blamed.
std::string failure_reason() { return errno != 0 ? std::strerror(errno) : "the write failed"; }

// Why a dump inside the --out folder may not go where it is named, if it may not: the
// run replaces that folder with what it writes, so the dump goes directly into it, and
// under a name none of the run's own files has.
std::optional<std::string> not_placeable_in(const fs::path& path, const fs::path& out) {
    if (resolved(path).parent_path() != resolved(out)) {
        return "a dump inside the --out folder goes directly into it, not into a folder inside it";
    }
    const std::string name = path.filename().string();
    if (is_picture_name(name) || name == kManifest) {
        return "it is named as a file the run writes into the --out folder (final.png, frame_NNNN.png, "
               "contact_sheet.png, animation.gif, .manifest); name the dump otherwise";
    }
    return std::nullopt;
}

}  // namespace

bool is_plain_word(std::string_view text) {
    return !text.empty() && std::all_of(text.begin(), text.end(), [](char c) {
        return (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_';
    });
}

NonFiniteState::NonFiniteState(long step, std::size_t index, std::string_view kind)
    : std::runtime_error("step " + std::to_string(step) + ": body " + std::to_string(index) + " (" + std::string(kind) +
                         ") has a position or velocity that is not a finite number; the scene is beyond what this "
                         "engine can compute, and nothing was written") {}

StateDump::StateDump(fs::path path, const fs::path& out, std::span<const fs::path> inputs) : path_(std::move(path)) {
    if (path_.empty()) throw std::invalid_argument("StateDump: no file named");
    const fs::path out_folder = OutputFolder::normalized(out);
    const auto refuse = [&](const std::string& reason) {
        throw OutputRefused("cannot write state dump " + printable(path_.string()) + ": " + reason);
    };
    if (!out_folder.empty() && is_within(out_folder, path_)) refuse("it is the --out folder or holds it");
    inside_out_ = !out_folder.empty() && is_within(path_, out_folder);
    if (inside_out_) {
        if (const auto reason = not_placeable_in(path_, out_folder)) refuse(*reason);
    }
    try {
        check_may_write(path_, WriteTarget::file, inputs);
    } catch (const OutputRefused& reason) {
        refuse(reason.what());
    }
    out_folder_ = out_folder;
    if (inside_out_) {
        // The run replaces the whole folder: the dump waits beside it, and moves in after.
        partial_ = out_folder;
        partial_ += ".dump-partial";
        std::error_code error;
        if (out_folder.has_parent_path()) fs::create_directories(out_folder.parent_path(), error);
    } else {
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
}

StateDump::~StateDump() {
    if (finished_) return;
    out_.close();
    std::error_code ignored;
    fs::remove(partial_, ignored);
}

void StateDump::row(long step, std::size_t index, std::string_view kind, lib::Vec2 center, double angle,
                    lib::Vec2 velocity, double angular_velocity) {
    write_row(step, index, std::nullopt, kind, center, angle, velocity, angular_velocity);
}

void StateDump::row(long step, std::size_t index, std::uint64_t id, std::string_view kind, lib::Vec2 center,
                    double angle, lib::Vec2 velocity, double angular_velocity) {
    write_row(step, index, id, kind, center, angle, velocity, angular_velocity);
}

void StateDump::write_row(long step, std::size_t index, std::optional<std::uint64_t> id, std::string_view kind,
                          lib::Vec2 center, double angle, lib::Vec2 velocity, double angular_velocity) {
    if (finished_) throw std::logic_error("StateDump::row after finish()");
    if (!is_plain_word(kind)) {
        std::string message = "StateDump::row: a kind must be a plain word, not \"";
        throw std::invalid_argument(message.append(kind).append("\""));
    }
    if (with_ids_ && *with_ids_ != id.has_value()) {
        throw std::logic_error(id ? "StateDump::row: an id, where the first row had none"
                                  : "StateDump::row: no id, where the first row had one");
    }
    std::string line;
    if (!with_ids_) {
        with_ids_ = id.has_value();
        line.append(id ? kDumpHeaderWithIds : kDumpHeader).append("\n");
    }
    line.append(std::to_string(step)).append(",").append(std::to_string(index));
    if (id) line.append(",").append(std::to_string(*id));
    line.append(",").append(kind);
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
    if (!with_ids_) out_ << kDumpHeader << '\n';  // no body in the whole run: no id either
    out_.close();                                 // flushes: a full disk shows here at the latest
    if (!out_) fail(failure_reason());
    stop_if_interrupted();
    std::error_code error;
    if (inside_out_ && path_.has_parent_path()) fs::create_directories(path_.parent_path(), error);
    if (error) fail(error.message());
    // Checked again: the file named may have become something else during the run.
    try {
        check_may_write(path_, WriteTarget::file);
    } catch (const OutputRefused& reason) {
        fail(reason.what());
    }
    fs::rename(partial_, path_, error);
    if (error) fail(error.message());
    finished_ = true;
    leftover_.reset();
    if (!inside_out_) return;
    try {
        OutputFolder::add_to_manifest(out_folder_, path_.filename().string());
    } catch (const fs::filesystem_error& manifest_error) {
        fail(manifest_error.code().message());
    }
}

void StateDump::fail(const std::string& reason) {
    out_.close();
    std::error_code ignored;
    fs::remove(partial_, ignored);
    std::string message = "cannot write state dump ";
    throw FileError(message.append(printable(path_.string())).append(": ").append(printable(reason)));
}

}  // namespace browser
