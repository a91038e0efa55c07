#include "write_guard.h"

#include <sys/stat.h>

#include <algorithm>
#include <iterator>
#include <string>
#include <system_error>

#include "message_text.h"
#include "png_io.h"  // OutputRefused

namespace browser {

namespace fs = std::filesystem;

namespace {

// What `status` (from lstat) is, in the words of a refusal, or "" for what may be written.
std::string kind_refused(const struct stat& status, WriteTarget kind) {
    if (S_ISLNK(status.st_mode)) return "it is a symbolic link";
    if (S_ISFIFO(status.st_mode)) return "it is a FIFO";
    if (S_ISCHR(status.st_mode) || S_ISBLK(status.st_mode)) return "it is a device";
    if (S_ISSOCK(status.st_mode)) return "it is a socket";
    if (kind == WriteTarget::folder) return S_ISDIR(status.st_mode) ? "" : "it exists and is not a folder";
    if (S_ISDIR(status.st_mode)) return "it is a folder";
    if (!S_ISREG(status.st_mode)) return "it is not a regular file";
    if (status.st_nlink > 1) {
        return "it is a file with " + std::to_string(status.st_nlink) +
               " names (hard links), which a run never replaces";
    }
    return "";
}

}  // namespace

fs::path resolved(const fs::path& path) {
    std::error_code error;
    const fs::path absolute = fs::absolute(path, error);
    if (error) return path.lexically_normal();
    const fs::path full = fs::weakly_canonical(absolute, error);
    return error ? absolute.lexically_normal() : full;
}

bool is_within(const fs::path& inner, const fs::path& outer) {
    const fs::path folder = resolved(outer), file = resolved(inner);
    // A trailing separator leaves an empty last part; it names the same place.
    const auto parts_end = [](const fs::path& path) {
        auto end = path.end();
        if (end != path.begin() && std::prev(end)->empty()) --end;
        return end;
    };
    const auto folder_end = parts_end(folder), file_end = parts_end(file);
    return std::mismatch(folder.begin(), folder_end, file.begin(), file_end).first == folder_end;
}

void check_may_write(const fs::path& target, WriteTarget kind, std::span<const fs::path> inputs) {
    const std::string name = resolved(target).filename().string();
    if (name.size() > kLongestWrittenName) {
        throw OutputRefused("its name has " + std::to_string(name.size()) + " bytes, more than the " +
                            std::to_string(kLongestWrittenName) + " a run can write (the file system's 255 less " +
                            std::to_string(255 - kLongestWrittenName) + " for the partial file beside it)");
    }
    std::error_code error;
    const fs::path here = fs::current_path(error);
    if (!error && is_within(here, target)) {
        throw OutputRefused("it is the current folder or holds it, which a run never replaces; name a new folder");
    }
    for (const fs::path& input : inputs) {
        if (input.empty()) continue;
        const bool same_file = fs::equivalent(input, target, error);  // hard links too
        if (same_file || is_within(input, target)) {
            throw OutputRefused(std::string(same_file || kind == WriteTarget::file ? "it is " : "it holds ") +
                                in_quotes(input.string()) + ", which the run reads");
        }
    }
    struct stat status {};
    if (::lstat(target.c_str(), &status) != 0) return;  // nothing there yet (a missing folder is the writer's to say)
    if (const std::string refused = kind_refused(status, kind); !refused.empty()) throw OutputRefused(refused);
}

}  // namespace browser
