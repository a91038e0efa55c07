#include "output_folder.h"


#include <system_error>
#include <utility>

#include "png_io.h"  // FileError

namespace browser {
namespace {

namespace fs = std::filesystem;

void check_replaceable(const fs::path& out, const std::string& marker) {
    const std::string name = out.filename().string();
    if (name.empty() || name == "." || name == "..") {
        throw OutputRefused("the current folder, its parent or the root cannot be replaced; name a folder inside it");
    }
    const fs::file_status status = fs::symlink_status(out);
    if (!fs::exists(status)) return;
    // A symbolic link would be replaced by a folder, not followed; a link is not a run's.
    if (fs::is_symlink(status)) throw OutputRefused("it is a symbolic link, which a run does not replace");
    if (!fs::is_directory(status)) throw OutputRefused("it exists and is not a folder");
    if (!fs::is_empty(out) && !fs::exists(out / marker)) {
        throw OutputRefused("it is a folder that a run did not write (it has no " + marker +
                        "), so it is left alone; remove it or choose another --out");
    }
}

// "-<process id>". Built by appending: g++ 12 gives a false -Wrestrict warning
// for "-" + std::to_string(...).
}  // namespace

// "out/s1_1/" and "out/s1_1" name the same folder; without the trailing separator
// the staging folder would land inside it rather than beside it.
fs::path OutputFolder::normalized(const fs::path& given) {
    fs::path path = given.lexically_normal();
    if (!path.has_filename() && path.has_parent_path()) path = path.parent_path();
    return path;
}

OutputFolder::OutputFolder(const fs::path& out, std::string marker)
    : out_(normalized(out)), suffix_(process_suffix()) {
    check_replaceable(out_, marker);
    note_interruptions();
    fs::path staging = out_;
    staging += ".partial" + suffix_;
    // Before the run starts, a folder that cannot be made is one more refusal of --out.
    try {
        if (out_.has_parent_path()) fs::create_directories(out_.parent_path());
        remove_stale_leftovers(out_, ".partial-");
        remove_stale_leftovers(out_, ".old-");
        fs::remove_all(staging);  // left over from a crashed run that had our process id
        leftover_.emplace(staging);
        fs::create_directory(staging);
    } catch (const fs::filesystem_error& error) {
        throw OutputRefused(error.code().message());
    }
    staging_ = std::move(staging);
}

OutputFolder::~OutputFolder() {
    if (committed_) return;
    std::error_code ignored;
    fs::remove_all(staging_, ignored);
}

void OutputFolder::commit() {
    if (!fs::exists(fs::symlink_status(out_))) {
        fs::rename(staging_, out_);
        committed_ = true;
        leftover_.reset();
        return;
    }
    fs::path old = out_;
    old += ".old" + suffix_;
    fs::remove_all(old);
    fs::rename(out_, old);
    try {
        fs::rename(staging_, out_);
    } catch (...) {
        std::error_code ignored;
        fs::rename(old, out_, ignored);
        throw;
    }
    committed_ = true;
    leftover_.reset();
    std::error_code ignored;  // the new files are in place; a leftover old folder is only litter
    fs::remove_all(old, ignored);
}

}  // namespace browser
