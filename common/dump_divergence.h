#pragma once
// Two state dumps (--dump, state_dump.h) side by side: where do they first part ways?
// One comes from our stage, the other from the book's own JavaScript run on the same
// scene and keys by tools/book_runner (docs/book_runner.md). The answer names the step,
// the body and the field; which of the known differences from the book explains it is
// the errata's to say (errata/known_differences.h).

#include <array>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <istream>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "input_file.h"

namespace browser {

// The numeric columns of a dump, in file order after step, index and shape.
inline constexpr std::array<std::string_view, 6> kDumpFields{"cx", "cy", "angle", "vx", "vy", "angular_velocity"};

struct DumpRow {
    long step = 0;
    std::size_t index = 0;
    std::optional<std::uint64_t> id;  // in a dump with ids (state_dump.h)
    std::string shape;
    std::array<double, kDumpFields.size()> values{};
};

// A file that is not a dump as state_dump.h writes it: one line, "FILE:LINE: problem".
struct DumpError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// A dump read step by step, checking its shape: a header naming the columns (step,
// index, shape and kDumpFields, in any order; a body's id, "id", when the dump has ids;
// a column it does not know is read past), every row with as many fields, steps that
// never go back, each step's bodies numbered 0, 1, 2... Two dumps are compared body by
// body in index order, whether they have ids or not (a stage with ids against one
// without). Memory holds one step, and a step at most kMostRowsInStep bodies. `name`
// is what messages call it.
inline constexpr std::size_t kMostRowsInStep = 1'000'000;
class DumpReader {
public:
    // `next_line` gives the next line without its '\n', false at the end.
    DumpReader(std::function<bool(std::string&)> next_line, std::string_view name);
    // The next step's rows, in index order; false when there are no more steps.
    bool next_step(std::vector<DumpRow>& rows);

private:
    DumpError refuse(const std::string& problem) const;
    std::optional<DumpRow> read_row();

    std::function<bool(std::string&)> next_line_;
    std::string name_;
    long line_number_ = 1;
    std::size_t columns_ = 0, step_at_ = 0, index_at_ = 0, shape_at_ = 0;
    std::optional<std::size_t> id_at_;  // a dump with ids (state_dump.h)
    std::array<std::size_t, kDumpFields.size()> field_at_{};
    struct Last {
        long step;
        std::size_t index;
    };
    std::optional<Last> last_;
    std::optional<DumpRow> ahead_;  // the first row of the next step, read already
};

// A dump file read as above (input_file.h: a regular file only, lines of at most
// kLongestDumpLine bytes). Refusals of the file are DumpErrors too.
inline constexpr std::size_t kLongestDumpLine = 4096;
struct DumpFile {
    explicit DumpFile(const std::filesystem::path& file);
    std::unique_ptr<LineReader> lines;
    DumpReader reader;

private:
    static std::unique_ptr<LineReader> open(const std::filesystem::path& file);
};

// A whole dump in memory, for tests and small dumps.
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
    shape,       // body `index` is of one kind in one dump, of another in the other
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
// The same for two dump files, read side by side one step at a time: memory holds a
// step of each, however long the runs were. Throws DumpError for a file that is no dump.
std::optional<Divergence> first_divergence(const std::filesystem::path& a, const std::filesystem::path& b,
                                           DumpTolerance tolerance = {});

// The report's lines: where, what, and the other bodies that differ at that step; for a
// divergence at step 0, that the two runs did not start alike. `name_a` and `name_b`
// name the two dumps.
std::string describe(const Divergence& divergence, std::string_view name_a, std::string_view name_b,
                     DumpTolerance tolerance);

}  // namespace browser
