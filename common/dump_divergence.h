#pragma once
// Two state dumps (--dump, state_dump.h) side by side: where do they first part ways?
// One comes from our stage, the other from the book's own JavaScript run on the same
// scene and keys by tools/book_runner (docs/book_runner.md). The answer names the step,
// the body and the field, and, where the difference is one we know and keep or fix on
// purpose, the docs/errata.md entry that explains it.

#include <array>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <istream>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace browser {

// The numeric columns of a dump, in file order after step, index, the id (when the dump
// has ids) and shape.
inline constexpr std::array<std::string_view, 6> kDumpFields{"cx", "cy", "angle", "vx", "vy", "angular_velocity"};

struct DumpRow {
    long step = 0;
    std::size_t index = 0;
    std::optional<std::uint64_t> id;  // in a dump with ids (5.4 on; state_dump.h)
    std::string shape;
    std::array<double, kDumpFields.size()> values{};
};

// A file that is not a dump as state_dump.h writes it: one line, "FILE:LINE: problem".
struct DumpError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// Reads a dump, checking its shape: the header, nine columns (ten with ids), steps
// that never go back, and each step's bodies numbered 0, 1, 2... Two dumps are compared
// body by body in index order, whether they have ids or not (a stage with ids against
// one without). `name` is what messages call it.
std::vector<DumpRow> parse_dump(std::istream& in, std::string_view name);
std::vector<DumpRow> read_dump(const std::filesystem::path& file);

// Two numbers agree when they differ by at most absolute + relative * the larger
// magnitude. The default allows for the last bits of sin and cos, which V8 and the C
// library round differently, and nothing a physics difference could hide in.
struct DumpTolerance {
    double absolute = 1e-9;
    double relative = 1e-9;
};
bool agree(double a, double b, DumpTolerance tolerance);

enum class DivergenceKind {
    value,       // a number differs beyond the tolerance
    shape,       // body `index` is a rectangle in one dump, a circle in the other
    extra_body,  // one dump has more bodies at this step
    steps_end,   // one dump has no rows for this step: its run did not update any more
};

struct DifferingBody {
    std::size_t index = 0;
    std::string shape;
    std::string_view field;  // the first field of kDumpFields that differs
};

struct Divergence {
    DivergenceKind kind = DivergenceKind::value;
    long step = 0;
    std::size_t index = 0;     // the body (value, shape, extra_body)
    std::string shape;         // its shape in the first dump that has it
    std::string_view field;    // the field (value)
    double a = 0, b = 0;       // the two numbers (value)
    bool a_is_longer = false;  // which dump has the extra body or the further steps
    // How many bodies each dump holds at this step, and at the step before (0 for step 0).
    std::size_t bodies_a = 0, bodies_b = 0, bodies_before_a = 0, bodies_before_b = 0;
    // Every body whose numbers differ at this step, in index order.
    std::vector<DifferingBody> differing;
};

std::optional<Divergence> first_divergence(const std::vector<DumpRow>& a, const std::vector<DumpRow>& b,
                                           DumpTolerance tolerance = {});

// An errata entry that explains a divergence: its heading in docs/errata.md, exactly as
// written after "### ", and what in the divergence points to it.
struct KnownDifference {
    std::string_view heading;
    std::string_view sign;
};

// The entry that explains `divergence` for the book project `stage` ("4.4", "5.1"), or
// nothing. It is the likely cause, told by which stage, shape and field, not a proof.
std::optional<KnownDifference> known_difference(const Divergence& divergence, std::string_view stage);
// Every entry the table knows, for the test that each heading is in docs/errata.md.
std::vector<KnownDifference> known_differences();

// The anchor GitHub gives a heading: lower case, spaces as hyphens, no punctuation
// ("Circle inertia (fixed, 4.1 on)" -> "circle-inertia-fixed-41-on").
std::string heading_anchor(std::string_view heading);

// The report's lines: where, what, the other bodies that differ at that step, and the
// errata entry when one is known. `name_a` and `name_b` name the two dumps.
std::string describe(const Divergence& divergence, std::string_view name_a, std::string_view name_b,
                     DumpTolerance tolerance, std::string_view stage);

}  // namespace browser
