#pragma once
// A file a run writes line by line beside its pictures: the state dump (--dump FILE,
// state_dump.h), and any file a stage names with an option of its own (the collision events'
// FILE). Each one is written under the same discipline, which this class holds once.
//
// Such a file grows over a whole run, so it is written to "<path>.partial-<pid>" and
// only finish() renames it to <path>. A run that stops with an error therefore never
// leaves a file that looks complete: the destructor removes the partial file (and so
// does an interruption, interruption.h; only a crash can leave one behind, under its
// telling name, which the next run writing <path> removes once that process is gone),
// and what an earlier run wrote to <path> stays as it was until the new file is complete.
//
// <path> must pass write_guard.h's rule (a plain regular file with one name or nothing
// yet, never a link, a FIFO, a device or a folder, nor a file the run reads): anything
// else is refused (OutputRefused), never replaced. Nor may it be the --out folder or
// hold it. A file inside the run's --out folder goes directly into it, under a name
// none of the run's pictures has; it is written beside that folder, moved into it by
// finish() after the run has put its new folder in place of the old one, and added to
// the folder's manifest (output_folder.h), so the next run may replace it.

#include <filesystem>
#include <fstream>
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "interruption.h"

namespace browser {

class OutputFile {
public:
    // Creates the partial file. `what` names the file in messages ("state dump": "cannot
    // write state dump <path>: ..."); `out` is the run's --out folder ("" for none),
    // `inputs` the files the run reads. Throws OutputRefused when <path> may not be
    // written (see above), FileError when the partial file cannot be created; each one
    // line naming `path`.
    OutputFile(std::filesystem::path path, std::string_view what, const std::filesystem::path& out = {},
               std::span<const std::filesystem::path> inputs = {});
    // Removes the partial file unless finish() succeeded.
    ~OutputFile();

    OutputFile(const OutputFile&) = delete;
    OutputFile& operator=(const OutputFile&) = delete;

    // Appends `text` as it is. Throws FileError when the write fails, std::logic_error
    // after finish().
    void write(std::string_view text);

    // Completes the file and renames it to `path`. Throws FileError, and removes the
    // partial file, when any write failed or the rename is refused.
    void finish();
    bool finished() const { return finished_; }

    const std::filesystem::path& path() const { return path_; }

private:
    [[noreturn]] void fail(const std::string& reason);

    std::filesystem::path path_;
    std::string what_;
    std::filesystem::path partial_;
    std::optional<Leftover> leftover_;  // partial_, should the run be interrupted
    std::filesystem::path out_folder_;  // the run's --out folder, "" for none
    bool inside_out_ = false;           // path_ is inside the --out folder
    std::ofstream out_;
    bool finished_ = false;
};

}  // namespace browser
