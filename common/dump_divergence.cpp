#include "dump_divergence.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>
#include <utility>

#include "message_text.h"
#include "png_io.h"      // FileError
#include "state_dump.h"  // is_plain_word

namespace browser {

namespace {

std::vector<std::string_view> split_commas(std::string_view line) {
    std::vector<std::string_view> parts;
    std::size_t start = 0;
    for (std::size_t comma = line.find(','); comma != std::string_view::npos; comma = line.find(',', start)) {
        parts.push_back(line.substr(start, comma - start));
        start = comma + 1;
    }
    parts.push_back(line.substr(start));
    return parts;
}

template <typename Number>
std::optional<Number> read_number(std::string_view text) {
    Number value{};
    const char* end = text.data() + text.size();
    const auto [stop, error] = std::from_chars(text.data(), end, value);
    if (text.empty() || error != std::errc{} || stop != end) return std::nullopt;
    return value;
}

// A dump's rows grouped by step: steps[k] holds step k's rows, in index order.
std::vector<std::vector<DumpRow>> by_step(const std::vector<DumpRow>& rows) {
    std::vector<std::vector<DumpRow>> steps;
    for (const DumpRow& row : rows) {
        if (static_cast<std::size_t>(row.step) == steps.size()) steps.emplace_back();
        steps.back().push_back(row);
    }
    return steps;
}

// nan is the same as nan (both runs blew up alike), an infinity the same as itself (the
// book's code overflowed alike, tools/book_runner writes inf); neither is the same as
// any number, however large the tolerance.
bool same_number(double a, double b, DumpTolerance tolerance) {
    if (std::isnan(a) || std::isnan(b)) return std::isnan(a) && std::isnan(b);
    if (std::isinf(a) || std::isinf(b)) return a == b;
    return agree(a, b, tolerance);
}

std::optional<std::string_view> first_differing_field(const DumpRow& a, const DumpRow& b, DumpTolerance tolerance) {
    for (std::size_t f = 0; f < kDumpFields.size(); ++f) {
        if (!same_number(a.values[f], b.values[f], tolerance)) return kDumpFields[f];
    }
    return std::nullopt;
}

std::size_t field_index(std::string_view field) {
    return static_cast<std::size_t>(std::find(kDumpFields.begin(), kDumpFields.end(), field) - kDumpFields.begin());
}

std::string number_text(double value) {
    std::ostringstream text;
    text.precision(17);
    text << value;
    return text.str();
}

std::string short_number(double value) {
    std::ostringstream text;
    text.precision(3);
    text << value;
    return text.str();
}

std::string where(const Divergence& d) {
    return "step " + std::to_string(d.step) + ", body " + std::to_string(d.index) + " (" + d.shape + ")";
}

std::string what_differs(const Divergence& d, std::string_view name_a, std::string_view name_b,
                         DumpTolerance tolerance) {
    const std::string longer(d.a_is_longer ? name_a : name_b), shorter(d.a_is_longer ? name_b : name_a);
    switch (d.kind) {
        case DivergenceKind::value:
            return where(d) + ": " + std::string(d.field) + " is " + number_text(d.a) + " in " + std::string(name_a) +
                   " and " + number_text(d.b) + " in " + std::string(name_b) + " (they differ by " +
                   short_number(std::abs(d.a - d.b)) + "; the tolerance is " + short_number(tolerance.absolute) +
                   " + " + short_number(tolerance.relative) + " of the larger)";
        case DivergenceKind::shape:
            return "step " + std::to_string(d.step) + ", body " + std::to_string(d.index) + ": a " + d.shape + " in " +
                   std::string(name_a) + ", not in " + std::string(name_b);
        case DivergenceKind::extra_body:
            return where(d) + " is in " + longer + " only (" + std::to_string(d.bodies_a) + " bodies in " +
                   std::string(name_a) + ", " + std::to_string(d.bodies_b) + " in " + std::string(name_b) + ")";
        case DivergenceKind::steps_end:
            return "step " + std::to_string(d.step) + ": " + longer + " goes on, " + shorter + " has no more steps";
    }
    return {};
}

}  // namespace

DumpReader::DumpReader(std::function<bool(std::string&)> next_line, std::string_view name)
    : next_line_(std::move(next_line)), name_(name) {
    std::string header;
    if (!next_line_(header)) throw refuse("not a state dump: it is empty");
    // The columns by name: the ones compared must be there, and a body's id may be
    // (state_dump.h); others may come anywhere, and are read past.
    const std::vector<std::string_view> names = split_commas(header);
    columns_ = names.size();
    const auto find = [&](std::string_view wanted) -> std::optional<std::size_t> {
        for (std::size_t c = 0; c < names.size(); ++c) {
            if (names[c] == wanted) return c;
        }
        return std::nullopt;
    };
    const auto step = find("step"), index = find("index"), shape = find("shape");
    bool whole = step && index && shape;
    for (std::size_t f = 0; f < kDumpFields.size() && whole; ++f) {
        const auto at = find(kDumpFields[f]);
        whole = at.has_value();
        if (at) field_at_[f] = *at;
    }
    if (!whole) {
        throw refuse("not a state dump: the first line must name the columns \"" + std::string(kDumpHeader) + "\"");
    }
    step_at_ = *step;
    index_at_ = *index;
    shape_at_ = *shape;
    id_at_ = find("id");
}

DumpError DumpReader::refuse(const std::string& problem) const {
    return DumpError(printable(name_) + ":" + std::to_string(line_number_) + ": " + problem);
}

std::optional<DumpRow> DumpReader::read_row() {
    std::string line;
    if (!next_line_(line)) return std::nullopt;
    ++line_number_;
    const std::vector<std::string_view> parts = split_commas(line);
    if (parts.size() != columns_) {
        throw refuse("a row has " + std::to_string(columns_) + " fields, this has " + std::to_string(parts.size()));
    }
    DumpRow row;
    const auto step = read_number<long>(parts[step_at_]);
    const auto index = read_number<std::size_t>(parts[index_at_]);
    if (!step || !index) throw refuse("step and index must be whole numbers");
    row.step = *step;
    row.index = *index;
    if (id_at_) {
        row.id = read_number<std::uint64_t>(parts[*id_at_]);
        if (!row.id) throw refuse("the id must be a whole number");
    }
    row.shape = parts[shape_at_];
    if (!is_plain_word(row.shape)) throw refuse("the shape must be a plain word (lower-case letters, digits, _)");
    for (std::size_t f = 0; f < kDumpFields.size(); ++f) {
        const auto value = read_number<double>(parts[field_at_[f]]);
        if (!value) throw refuse(std::string(kDumpFields[f]) + " is not a number");
        row.values[f] = *value;
    }
    const bool next_body = last_ && row.step == last_->step && row.index == last_->index + 1;
    const bool next_step = row.index == 0 && row.step == (last_ ? last_->step + 1 : 0);
    if (!next_body && !next_step)
        throw refuse("rows must go step by step from step 0, each step's bodies numbered from 0");
    last_ = Last{row.step, row.index};
    return row;
}

bool DumpReader::next_step(std::vector<DumpRow>& rows) {
    rows.clear();
    if (!ahead_) ahead_ = read_row();
    if (!ahead_) return false;
    const long step = ahead_->step;
    while (ahead_ && ahead_->step == step) {
        if (rows.size() == kMostRowsInStep) {
            throw refuse("more than " + std::to_string(kMostRowsInStep) + " bodies in one step, more than any run has");
        }
        rows.push_back(std::move(*ahead_));
        ahead_ = read_row();
    }
    return true;
}

std::vector<DumpRow> parse_dump(std::istream& in, std::string_view name) {
    DumpReader reader([&in](std::string& line) { return static_cast<bool>(std::getline(in, line)); }, name);
    std::vector<DumpRow> rows, step;
    while (reader.next_step(step)) rows.insert(rows.end(), step.begin(), step.end());
    return rows;
}

std::vector<DumpRow> read_dump(const std::filesystem::path& file) {
    std::vector<DumpRow> rows, step;
    DumpFile dump(file);
    while (dump.reader.next_step(step)) rows.insert(rows.end(), step.begin(), step.end());
    return rows;
}

DumpFile::DumpFile(const std::filesystem::path& file)
    : lines(open(file)),
      reader(
          [this](std::string& line) {
              try {
                  return lines->next(line);
              } catch (const FileError& error) {
                  throw DumpError(error.what());  // a line too long, a read that failed
              }
          },
          file.string()) {}

std::unique_ptr<LineReader> DumpFile::open(const std::filesystem::path& file) {
    try {
        return std::make_unique<LineReader>(file, kLongestDumpLine);
    } catch (const FileError& error) {
        throw DumpError(error.what());
    }
}

bool agree(double a, double b, DumpTolerance tolerance) {
    return std::abs(a - b) <= tolerance.absolute + tolerance.relative * std::max(std::abs(a), std::abs(b));
}

namespace {

// One step of each dump: its rows, or nothing when that dump has no more steps; and how
// many bodies each had at the step before.
struct StepOf {
    const std::vector<DumpRow>* rows;
    std::size_t bodies_before;
};

std::optional<Divergence> divergence_at(long step, StepOf a, StepOf b, DumpTolerance tolerance) {
    Divergence d;
    d.step = step;
    d.bodies_a = a.rows ? a.rows->size() : 0;
    d.bodies_b = b.rows ? b.rows->size() : 0;
    d.bodies_before_a = a.bodies_before;
    d.bodies_before_b = b.bodies_before;
    if (!a.rows || !b.rows) {
        d.kind = DivergenceKind::steps_end;
        d.a_is_longer = a.rows != nullptr;
        return d;
    }
    std::optional<Divergence> first;
    for (std::size_t i = 0; i < std::min(d.bodies_a, d.bodies_b); ++i) {
        const DumpRow& row_a = (*a.rows)[i];
        const DumpRow& row_b = (*b.rows)[i];
        const auto field = first_differing_field(row_a, row_b, tolerance);
        if (row_a.shape == row_b.shape && !field) continue;
        d.differing.push_back({i, row_a.shape, field.value_or("shape")});
        if (first) continue;
        first = d;
        first->index = i;
        first->shape = row_a.shape;
        if (row_a.shape != row_b.shape) {
            first->kind = DivergenceKind::shape;
        } else {
            first->kind = DivergenceKind::value;
            first->field = *field;
            first->a = row_a.values[field_index(*field)];
            first->b = row_b.values[field_index(*field)];
        }
    }
    if (first) {
        first->differing = d.differing;
        return first;
    }
    if (d.bodies_a != d.bodies_b) {
        d.kind = DivergenceKind::extra_body;
        d.index = std::min(d.bodies_a, d.bodies_b);
        d.a_is_longer = d.bodies_a > d.bodies_b;
        d.shape = (d.a_is_longer ? *a.rows : *b.rows)[d.index].shape;
        return d;
    }
    return std::nullopt;
}

}  // namespace

std::optional<Divergence> first_divergence(const std::vector<DumpRow>& a, const std::vector<DumpRow>& b,
                                           DumpTolerance tolerance) {
    const auto steps_a = by_step(a), steps_b = by_step(b);
    const auto step_of = [](const std::vector<std::vector<DumpRow>>& steps, std::size_t step) {
        return StepOf{step < steps.size() ? &steps[step] : nullptr,
                      step > 0 && step - 1 < steps.size() ? steps[step - 1].size() : 0};
    };
    for (std::size_t step = 0; step < std::max(steps_a.size(), steps_b.size()); ++step) {
        if (auto found =
                divergence_at(static_cast<long>(step), step_of(steps_a, step), step_of(steps_b, step), tolerance))
            return found;
    }
    return std::nullopt;
}

std::optional<Divergence> first_divergence(const std::filesystem::path& a, const std::filesystem::path& b,
                                           DumpTolerance tolerance) {
    DumpFile dump_a(a), dump_b(b);
    std::vector<DumpRow> rows_a, rows_b;
    std::size_t before_a = 0, before_b = 0;
    for (long step = 0;; ++step) {
        const bool has_a = dump_a.reader.next_step(rows_a), has_b = dump_b.reader.next_step(rows_b);
        if (!has_a && !has_b) return std::nullopt;
        if (auto found = divergence_at(step, {has_a ? &rows_a : nullptr, before_a},
                                       {has_b ? &rows_b : nullptr, before_b}, tolerance))
            return found;
        before_a = rows_a.size();
        before_b = rows_b.size();
    }
}

std::string describe(const Divergence& divergence, std::string_view name_a, std::string_view name_b,
                     DumpTolerance tolerance) {
    std::string text = "first divergence: " + what_differs(divergence, name_a, name_b, tolerance) + "\n";
    if (divergence.differing.size() > 1) {
        text += "at that step these differ too:";
        for (std::size_t i = 1; i < divergence.differing.size() && i <= 8; ++i) {
            const DifferingBody& body = divergence.differing[i];
            text += " body " + std::to_string(body.index) + " (" + body.shape + ", " + std::string(body.field) + ")";
        }
        if (divergence.differing.size() > 9)
            text += " and " + std::to_string(divergence.differing.size() - 9) + " more";
        text += "\n";
    }
    if (divergence.step == 0) {
        return text + "the two runs did not start from the same world: build both from the same scene file\n";
    }
    return text;
}

}  // namespace browser
