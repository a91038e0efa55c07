#pragma once
// A folder that a run writes completely or not at all. Everything goes into a fresh
// staging folder beside the real one ("<out>.partial-<process id>"); only commit()
// puts it in place of the old folder. A run that fails half way (an exception, a full
// disk) leaves the old folder as it was, and the staging folder is removed.
//
// Replacing a folder deletes it, so only a folder that an earlier run wrote (it holds
// the run's marker file, e.g. final.png) or an empty one may be replaced: a mistyped
// --out must not wipe someone's files.
//
// Interrupted by SIGINT or SIGTERM, the run removes the staging folder before it ends
// (interruption.h); a staging or old folder that a run killed outright left behind is
// removed by the next run into the same place, once its process is gone.

#include <filesystem>
#include <optional>
#include <string>

#include "interruption.h"

namespace browser {

class OutputFolder {
public:
    // Checks that `out` may be replaced and makes the staging folder. Throws
    // OutputRefused (png_io.h) with a one-line reason when it may not, or when the
    // staging folder cannot be made.
    OutputFolder(const std::filesystem::path& out, std::string marker);
    ~OutputFolder();  // removes the staging folder unless commit() has run
    OutputFolder(const OutputFolder&) = delete;
    OutputFolder& operator=(const OutputFolder&) = delete;

    // Where the run writes its files until commit().
    const std::filesystem::path& staging() const { return staging_; }
    // The folder as given, without a trailing separator ("out/s1_1/" is "out/s1_1").
    const std::filesystem::path& out() const { return out_; }
    static std::filesystem::path normalized(const std::filesystem::path& given);

    // Moves the staging folder to out(), keeping the old folder aside until the move
    // has worked. Throws std::filesystem::filesystem_error when it cannot.
    void commit();

private:
    std::filesystem::path out_;
    std::filesystem::path staging_;
    std::string suffix_;  // "-<process id>": two runs into one folder never share staging
    bool committed_ = false;
    std::optional<Leftover> leftover_;  // the staging folder, until commit()
};

}  // namespace browser
