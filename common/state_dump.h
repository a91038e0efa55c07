#pragma once
// State dumps (--dump FILE): the state of every body after every fixed update, as CSV,
// so that two runs can be compared number for number.
//
//   step,index,shape,cx,cy,angle,vx,vy,angular_velocity
//   0,0,rectangle,500,200,2.7999999999999998,0,0,0
//
// Step 0 is the scene as built, before any update; step k is the state after the k-th
// update. `index` is the body's place in the object list at that step. Numbers carry 17
// significant digits, which is what it takes for std::strtod to give back the very same
// double; a simulation that blew up shows as nan or inf, which strtod reads too.
//
// A dump grows row by row over a whole run, so it is written to "<path>.partial" and only
// finish() renames it to <path>. A run that stops with an error therefore never leaves a
// file that looks like a complete dump: the destructor removes the partial file (only a
// crash can leave one behind, under its telling name), and a dump an earlier run wrote
// to <path> stays as it was until the new one is complete.

#include <cstddef>
#include <filesystem>
#include <fstream>
#include <string_view>

#include "png_io.h"  // FileError
#include "vec2.h"

namespace browser {

class StateDump {
public:
    // Creates "<path>.partial" and writes the header line. Throws FileError, with a
    // one-line message naming `path`, when it cannot.
    explicit StateDump(std::filesystem::path path);
    // Removes the partial file unless finish() succeeded.
    ~StateDump();

    StateDump(const StateDump&) = delete;
    StateDump& operator=(const StateDump&) = delete;

    // `shape` is "rectangle" or "circle" (shape_name() in scene_file.h spells them);
    // anything else throws std::invalid_argument rather than write a row tools misread.
    // Throws FileError when the write fails, std::logic_error after finish().
    void row(long step, std::size_t index, std::string_view shape, Vec2 center, double angle, Vec2 velocity,
             double angular_velocity);

    // Completes the file and renames it to `path`. Throws FileError, and removes the
    // partial file, when any write failed or the rename is refused.
    void finish();

    const std::filesystem::path& path() const { return path_; }

private:
    [[noreturn]] void fail(const std::string& reason);

    std::filesystem::path path_;
    std::filesystem::path partial_;
    std::ofstream out_;
    bool finished_ = false;
};

}  // namespace browser
