#pragma once
// The one rule for every place a program of this project writes: --out, --dump,
// --record, and compare_png's --diff and --diff-dir. A program replaces only what it can
// prove it wrote, and never lets a name lead its writing somewhere else. So before
// anything is written, the place named is checked here:
//  - its name, with its links, "." and ".." resolved (realpath), must not be the current
//    folder or one that holds it, nor be or hold a file the run reads (its scene file,
//    its key events);
//  - what is there now must be nothing yet, or a plain regular file with one name (for
//    a file) or a folder (for a folder: output_folder.h then checks what it holds). A
//    symbolic link, a FIFO, a device or a socket is never replaced: renaming over one
//    would destroy it, and opening one would write elsewhere or wait for ever. A file
//    with other hard links is someone's file under a second name.
//  - its name must leave room for the suffix of the partial file written beside it
//    (".partial-<process id>"), so that a long name is refused before the run rather
//    than failing at its end.

#include <filesystem>
#include <span>

namespace browser {

enum class WriteTarget { file, folder };

// The longest name (the last part of a path) a run writes, in bytes: a file system's 255
// less what the partial file adds to it.
inline constexpr std::size_t kLongestWrittenName = 255 - 24;

// Throws OutputRefused (png_io.h) with the reason, one line starting "it ...", when
// `target` may not be written or replaced; `inputs` are the files the run reads.
void check_may_write(const std::filesystem::path& target, WriteTarget kind,
                     std::span<const std::filesystem::path> inputs = {});

// `path` with its links, "." and ".." resolved as far as it exists, the rest appended
// as it is: what the name leads to, whatever the current folder or links spell it as.
std::filesystem::path resolved(const std::filesystem::path& path);

// Whether `inner` is `outer` or lies inside it, both resolved.
bool is_within(const std::filesystem::path& inner, const std::filesystem::path& outer);

}  // namespace browser
