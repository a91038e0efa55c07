#pragma once
// State dumps (--dump FILE): the state of every body after every fixed update, as CSV,
// so that two runs can be compared number for number.
//
//   step,index,shape,cx,cy,angle,vx,vy,angular_velocity
//   0,0,rectangle,500,200,2.7999999999999998,0,0,0
//
// Step 0 is the scene as built, before any update; step k is the state after the k-th
// update. `index` is the body's place in the object list at that step. A stage whose
// bodies have ids that never change gives each row its body's id too, beside the
// index, and the header says so:
//
//   step,index,id,shape,cx,cy,angle,vx,vy,angular_velocity
//   0,0,1,rectangle,500,200,2.7999999999999998,0,0,0
//
// The first row decides which of the two the dump is: the header is written with it
// (a run with no body at all gets the first one from finish()). Numbers carry 17
// significant digits, which is what it takes for std::strtod to give back the very same
// double; a simulation that blew up shows as nan or inf, which strtod reads too.
//
// The file is written as every output file of a run is (output_file.h): to a partial
// file first, renamed only by finish(), never replacing what the write guard refuses,
// and moved into the --out folder after the run when it is named inside it.

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>

#include "output_file.h"
#include "png_io.h"  // FileError, OutputRefused
#include "vec2.h"

namespace browser {

// The header line of a dump, without ids and with them.
inline constexpr std::string_view kDumpHeader = "step,index,shape,cx,cy,angle,vx,vy,angular_velocity";
inline constexpr std::string_view kDumpHeaderWithIds = "step,index,id,shape,cx,cy,angle,vx,vy,angular_velocity";

class StateDump {
public:
    // Creates the partial file (the header line waits for the first row). `out` is the
    // run's --out folder ("" for none), `inputs` the files the run reads. Throws
    // OutputRefused when <path> may not be written (output_file.h), FileError when the
    // partial file cannot be created; each one line naming `path`.
    explicit StateDump(std::filesystem::path path, const std::filesystem::path& out = {},
                       std::span<const std::filesystem::path> inputs = {});
    StateDump(const StateDump&) = delete;
    StateDump& operator=(const StateDump&) = delete;

    // `kind` is the body's kind as the stage's scene files spell it, a plain word
    // (lower-case letters, digits, '_'); anything else throws std::invalid_argument
    // rather than write a row tools misread. Throws FileError when the write fails,
    // std::logic_error after finish() or when the row has an id and the first row had
    // none, or the other way round.
    void row(long step, std::size_t index, std::string_view kind, lib::Vec2 center, double angle, lib::Vec2 velocity,
             double angular_velocity);
    // The same, with the body's id.
    void row(long step, std::size_t index, std::uint64_t id, std::string_view kind, lib::Vec2 center, double angle,
             lib::Vec2 velocity, double angular_velocity);

    // Completes the file and renames it to `path`. Throws FileError, and removes the
    // partial file, when any write failed or the rename is refused.
    void finish();

    const std::filesystem::path& path() const { return file_.path(); }

private:
    void write_row(long step, std::size_t index, std::optional<std::uint64_t> id, std::string_view kind,
                   lib::Vec2 center, double angle, lib::Vec2 velocity, double angular_velocity);

    OutputFile file_;
    std::optional<bool> with_ids_;  // the first row's kind, once it is written
};

// A step that made a number no double can be: the run stops, naming the body and the
// step, and writes nothing (exit status 3, docs/scene_format.md).
// Whether `text` is a plain word: lower-case letters, digits and '_', at least one.
bool is_plain_word(std::string_view text);

struct NonFiniteState : std::runtime_error {
    NonFiniteState(long step, std::size_t index, std::string_view kind);
};

}  // namespace browser
