#include "output_folder.h"

#include <sys/stat.h>

#include <algorithm>
#include <fstream>
#include <set>
#include <system_error>
#include <utility>
#include <vector>

#include "message_text.h"
#include "png_io.h"  // OutputRefused
#include "write_guard.h"

namespace browser {
namespace {

namespace fs = std::filesystem;

// A plain file with one name: what a run writes. A link, a subfolder or a second name
// of someone's file is not, even under a listed name.
bool is_plain_file(const fs::path& path) {
    struct stat status {};
    return ::lstat(path.c_str(), &status) == 0 && S_ISREG(status.st_mode) && status.st_nlink == 1;
}

// The names in `folder`, sorted, so that a refusal always names the same first one.
std::vector<std::string> sorted_names(const fs::path& folder) {
    std::vector<std::string> names;
    for (const fs::directory_entry& entry : fs::directory_iterator(folder))
        names.push_back(entry.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
}

// A folder in a run's folder (compare_runs' left/ and right/, each a run of the stage
// program) is the run's when its manifest lists it and it is a run's folder in turn; so
// deep and no deeper.
constexpr int kDeepestWrittenFolder = 4;

// A folder (not a link to one) that holds a run's manifest.
bool is_run_folder(const fs::path& path) {
    struct stat status {};
    return ::lstat(path.c_str(), &status) == 0 && S_ISDIR(status.st_mode) && is_plain_file(path / kManifest);
}

// The first thing in `folder` that no run wrote, as a path inside it; "" when none.
std::string first_unwritten(const fs::path& folder, int depth) {
    const std::set<std::string> written = manifest_names(folder);
    for (const std::string& name : sorted_names(folder)) {
        const bool listed = name == kManifest || written.contains(name);
        if (listed && is_plain_file(folder / name)) continue;
        if (listed && name != kManifest && depth < kDeepestWrittenFolder && is_run_folder(folder / name)) {
            const std::string inner = first_unwritten(folder / name, depth + 1);
            if (inner.empty()) continue;
            return (fs::path(name) / inner).string();
        }
        return name;
    }
    return "";
}

void check_replaceable(const fs::path& out, std::span<const fs::path> inputs) {
    check_may_write(out, WriteTarget::folder, inputs);
    if (!fs::exists(fs::symlink_status(out))) return;
    if (const std::string name = first_unwritten(out, 1); !name.empty()) {
        throw OutputRefused("it holds " + in_quotes(name) +
                            ", which no run wrote (a run replaces only a folder "
                            "holding what its " +
                            kManifest + " lists); move it away or choose another --out");
    }
}

// Removes what `folder`'s manifest lists (a listed folder the same way), the manifest,
// and then the folder if that leaves it empty; anything else in it stays.
void remove_written(const fs::path& folder, int depth = 1) {
    std::error_code ignored;
    for (const std::string& name : manifest_names(folder)) {
        if (is_plain_file(folder / name)) fs::remove(folder / name, ignored);
        else if (depth < kDeepestWrittenFolder && is_run_folder(folder / name))
            remove_written(folder / name, depth + 1);
    }
    fs::remove(folder / kManifest, ignored);
    fs::remove(folder, ignored);  // only an empty folder goes
}

void write_manifest(const fs::path& folder) {
    std::vector<std::string> names = sorted_names(folder);
    std::ofstream out(folder / kManifest, std::ios::binary | std::ios::trunc);
    out << "# The files a run wrote here. The next run into this folder replaces only these;\n"
           "# anything else in the folder makes it refuse.\n";
    for (const std::string& name : names) out << name << '\n';
    out.close();
    if (!out)
        throw fs::filesystem_error("cannot write the manifest", folder / kManifest,
                                   std::make_error_code(std::errc::io_error));
}

// "-<process id>". Built by appending: g++ 12 gives a false -Wrestrict warning
// for "-" + std::to_string(...).
}  // namespace

// A manifest that is not a plain file (a FIFO would wait for ever) or is larger than any
// run writes lists nothing: the folder then holds a file no run wrote.
std::set<std::string> manifest_names(const fs::path& folder) {
    std::set<std::string> names;
    const fs::path manifest = folder / kManifest;
    if (!is_plain_file(manifest)) return names;
    std::error_code error;
    if (fs::file_size(manifest, error) > kLargestManifest || error) return names;
    std::ifstream in(manifest);
    for (std::string line; std::getline(in, line);) {
        if (!line.empty() && line.front() != '#') names.insert(line);
    }
    return names;
}

// "out/x/" and "out/x" name the same folder; without the trailing separator
// the staging folder would land inside it rather than beside it.
fs::path OutputFolder::normalized(const fs::path& given) {
    fs::path path = given.lexically_normal();
    if (!path.has_filename() && path.has_parent_path()) path = path.parent_path();
    return path;
}

OutputFolder::OutputFolder(const fs::path& out, std::span<const fs::path> inputs)
    : out_(normalized(out)), suffix_(process_suffix()) {
    // Before the run starts, a folder that cannot be read or made is one more refusal of --out.
    try {
        check_replaceable(out_, inputs);
        note_interruptions();
        fs::path staging = out_;
        staging += ".partial" + suffix_;
        if (out_.has_parent_path()) fs::create_directories(out_.parent_path());
        remove_stale_leftovers(out_, ".partial-");
        remove_stale_leftovers(out_, ".old-");
        fs::remove_all(staging);  // left over from a crashed run that had our process id
        leftover_.emplace(staging);
        fs::create_directory(staging);
        staging_ = std::move(staging);
    } catch (const fs::filesystem_error& error) {
        throw OutputRefused(error.code().message());
    }
}

OutputFolder::~OutputFolder() {
    if (committed_) return;
    std::error_code ignored;
    fs::remove_all(staging_, ignored);
}

void OutputFolder::commit() {
    write_manifest(staging_);
    if (!fs::exists(fs::symlink_status(out_))) {
        fs::rename(staging_, out_);
        committed_ = true;
        leftover_.reset();
        return;
    }
    // Checked again: something may have come into the folder during the run.
    try {
        check_replaceable(out_, {});
    } catch (const OutputRefused& refused) {
        throw FileError(refused.what());  // after the run: a failure to write (exit status 1), not a refusal
    }
    fs::path old = out_;
    old += ".old" + suffix_;
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
    remove_written(old);  // the new files are in place; what is left of the old folder is only litter
}

void OutputFolder::add_to_manifest(const fs::path& out, std::string_view name) {
    std::ofstream manifest(out / kManifest, std::ios::binary | std::ios::app);
    manifest << name << '\n';
    manifest.close();
    if (!manifest) {
        throw fs::filesystem_error("cannot add to the manifest", out / kManifest,
                                   std::make_error_code(std::errc::io_error));
    }
}

bool is_picture_name(std::string_view name) {
    if (name == kFinalPicture || name == kContactSheet || name == kAnimation || name == kUnfinishedAnimation)
        return true;
    constexpr std::string_view kPrefix = "frame_", kSuffix = ".png";
    if (!name.starts_with(kPrefix) || !name.ends_with(kSuffix) || name.size() <= kPrefix.size() + kSuffix.size()) {
        return false;
    }
    const std::string_view number = name.substr(kPrefix.size(), name.size() - kPrefix.size() - kSuffix.size());
    return number.find_first_not_of("0123456789") == std::string_view::npos;
}

}  // namespace browser
