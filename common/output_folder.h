#pragma once
// A folder that a run writes completely or not at all. Everything goes into a fresh
// staging folder beside the real one ("<out>.partial-<process id>"); only commit()
// puts it in place of the old folder. A run that fails half way (an exception, a full
// disk) leaves the old folder as it was, and the staging folder is removed.
//
// Replacing a folder deletes what it holds, so a run deletes only what it can prove a
// run wrote: each run leaves a manifest in its folder (kManifest, one file name a line),
// and a folder may be replaced only when it is empty or holds nothing but its manifest
// and the regular files the manifest names. Anything else in it (a reader's notes, a
// scene file, a subfolder) makes the run refuse, naming that file, and the old folder
// is then removed file by file from its manifest, never wholesale. The folder must also
// pass write_guard.h's rule (not the current folder or one holding it under any name,
// not a link, not holding a file the run reads).
//
// Interrupted by SIGINT or SIGTERM, the run removes the staging folder before it ends
// (interruption.h); a staging folder that a run killed outright left behind is removed
// by the next run into the same place, once its process is gone.

#include <filesystem>
#include <cstdint>
#include <optional>
#include <set>
#include <span>
#include <string>
#include <string_view>

#include "interruption.h"

namespace browser {

// The manifest a run leaves in its folder: "# ..." comment lines, then one name a line.
inline constexpr const char* kManifest = ".manifest";

// The files a run writes into its folder.
inline constexpr const char* kFinalPicture = "final.png";
inline constexpr const char* kContactSheet = "contact_sheet.png";
inline constexpr const char* kAnimation = "animation.gif";
inline constexpr const char* kUnfinishedAnimation = "animation.gif.partial";  // until its last frame is in

// The names `folder`'s manifest lists: none when it has none, or one that is not a plain
// file of at most kLargestManifest bytes.
inline constexpr std::uintmax_t kLargestManifest = 16u << 20;
std::set<std::string> manifest_names(const std::filesystem::path& folder);

// The names a run gives the files of its folder (final.png, frame_NNNN.png,
// contact_sheet.png, animation.gif and its partial file).
bool is_picture_name(std::string_view name);

class OutputFolder {
public:
    // Checks that `out` may be replaced and makes the staging folder. `inputs` are the
    // files the run reads. Throws OutputRefused (png_io.h) with a one-line reason when
    // it may not, or when the staging folder cannot be made.
    explicit OutputFolder(const std::filesystem::path& out, std::span<const std::filesystem::path> inputs = {});
    ~OutputFolder();  // removes the staging folder unless commit() has run
    OutputFolder(const OutputFolder&) = delete;
    OutputFolder& operator=(const OutputFolder&) = delete;

    // Where the run writes its files until commit().
    const std::filesystem::path& staging() const { return staging_; }
    // The folder as given, without a trailing separator ("out/x/" is "out/x").
    const std::filesystem::path& out() const { return out_; }
    static std::filesystem::path normalized(const std::filesystem::path& given);

    // Writes the manifest of what the staging folder holds and moves it to out(),
    // keeping the old folder aside until the move has worked, then removing the old
    // folder's manifest files. Throws std::filesystem::filesystem_error when it cannot, and
    // FileError when something not listed came into the old folder during the run.
    void commit();

    // Adds `name`, a file just put into the committed folder `out`, to its manifest, so
    // that the next run may replace it (a state dump written inside --out).
    static void add_to_manifest(const std::filesystem::path& out, std::string_view name);

private:
    std::filesystem::path out_;
    std::filesystem::path staging_;
    std::string suffix_;  // "-<process id>": two runs into one folder never share staging
    bool committed_ = false;
    std::optional<Leftover> leftover_;  // the staging folder, until commit()
};

}  // namespace browser
