#include "output_file.h"

#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <system_error>
#include <utility>

#include "message_text.h"
#include "output_folder.h"
#include "png_io.h"  // FileError, OutputRefused
#include "write_guard.h"

namespace browser {

namespace fs = std::filesystem;

namespace {

// errno after a failed stream operation, when the library set one; callers clear errno
// first so that an old value from elsewhere is not blamed.
std::string failure_reason() { return errno != 0 ? std::strerror(errno) : "the write failed"; }

// Why a file inside the --out folder may not go where it is named, if it may not: the
// run replaces that folder with what it writes, so the file goes directly into it, and
// under a name none of the run's own files has.
std::optional<std::string> not_placeable_in(const fs::path& path, const fs::path& out, std::string_view what) {
    if (resolved(path).parent_path() != resolved(out)) {
        return "a " + std::string(what) + " inside the --out folder goes directly into it, not into a folder inside it";
    }
    const std::string name = path.filename().string();
    if (is_picture_name(name) || name == kManifest) {
        return "it is named as a file the run writes into the --out folder (final.png, frame_NNNN.png, "
               "contact_sheet.png, animation.gif, .manifest); name the " +
               std::string(what) + " otherwise";
    }
    return std::nullopt;
}

}  // namespace

OutputFile::OutputFile(fs::path path, std::string_view what, const fs::path& out, std::span<const fs::path> inputs)
    : path_(std::move(path)), what_(what) {
    if (path_.empty()) throw std::invalid_argument("OutputFile: no file named");
    const fs::path out_folder = OutputFolder::normalized(out);
    const auto refuse = [&](const std::string& reason) {
        throw OutputRefused("cannot write " + what_ + " " + printable(path_.string()) + ": " + reason);
    };
    if (!out_folder.empty() && is_within(out_folder, path_)) refuse("it is the --out folder or holds it");
    inside_out_ = !out_folder.empty() && is_within(path_, out_folder);
    if (inside_out_) {
        if (const auto reason = not_placeable_in(path_, out_folder, what_)) refuse(*reason);
    }
    try {
        check_may_write(path_, WriteTarget::file, inputs);
    } catch (const OutputRefused& reason) {
        refuse(reason.what());
    }
    out_folder_ = out_folder;
    if (inside_out_) {
        // The run replaces the whole folder: the file waits beside it, and moves in after,
        // under a name that tells which of the folder's files it is ("out.dump.csv-partial").
        partial_ = out_folder;
        partial_ += "." + path_.filename().string() + "-partial";
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

OutputFile::~OutputFile() {
    if (finished_) return;
    out_.close();
    std::error_code ignored;
    fs::remove(partial_, ignored);
}

void OutputFile::write(std::string_view text) {
    if (finished_) throw std::logic_error("OutputFile::write after finish()");
    errno = 0;
    out_ << text;
    if (!out_) fail(failure_reason());
}

void OutputFile::finish() {
    if (finished_) return;
    errno = 0;
    out_.close();  // flushes: a full disk shows here at the latest
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

void OutputFile::fail(const std::string& reason) {
    out_.close();
    std::error_code ignored;
    fs::remove(partial_, ignored);
    throw FileError("cannot write " + what_ + " " + printable(path_.string()) + ": " + printable(reason));
}

}  // namespace browser
