#include "dump_divergence.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>

#include "message_text.h"
#include "state_dump.h"

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
using Steps = std::vector<std::vector<const DumpRow*>>;

Steps by_step(const std::vector<DumpRow>& rows) {
    Steps steps;
    for (const DumpRow& row : rows) {
        if (static_cast<std::size_t>(row.step) == steps.size()) steps.emplace_back();
        steps.back().push_back(&row);
    }
    return steps;
}

bool same_number(double a, double b, DumpTolerance tolerance) {
    if (std::isnan(a) || std::isnan(b)) return std::isnan(a) && std::isnan(b);
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

// Book projects as one number: "4.4" is 44. Nothing for a text of another form.
std::optional<int> stage_number(std::string_view stage) {
    if (stage.size() != 3 || stage[1] != '.') return std::nullopt;
    const auto chapter = read_number<int>(stage.substr(0, 1));
    const auto project = read_number<int>(stage.substr(2, 1));
    if (!chapter || !project) return std::nullopt;
    return *chapter * 10 + *project;
}

bool a_body_left(const Divergence& d) {
    return d.kind == DivergenceKind::extra_body || d.bodies_a < d.bodies_before_a || d.bodies_b < d.bodies_before_b;
}

// What the dumps can show of each errata entry, from the stage that has it on: the
// numbers of a circle (its inertia), a body gone from the list (the book's removal
// during the update loop), or a run that stops updating (the book's frozen page).
struct Entry {
    int from_stage;
    KnownDifference difference;
    bool (*fits)(const Divergence&);
};

const Entry kEntries[] = {
    {51,
     {"The selection survives the removal of the selected shape (fixed, 5.1)",
      "one run stops updating while the other goes on: the book's page freezes once the selected shape "
      "has left the canvas"},
     [](const Divergence& d) { return d.kind == DivergenceKind::steps_end; }},
    {51,
     {"Out-of-bounds removal no longer skips the next shape's step (5.1)",
      "a shape left the canvas in this step: in the book's run the shape after it misses this update"},
     a_body_left},
    {44,
     {"Circle inertia (fixed, 4.1 on)",
      "a circle's numbers differ: the book's circle keeps m r^2 / 12 where its inverse inertia belongs, "
      "which the angular impulse of 4.4 on uses"},
     [](const Divergence& d) {
         return d.kind == DivergenceKind::value &&
                std::any_of(d.differing.begin(), d.differing.end(),
                            [](const DifferingBody& body) { return body.shape == "circle"; });
     }},
};

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

std::vector<DumpRow> parse_dump(std::istream& in, std::string_view name) {
    std::vector<DumpRow> rows;
    std::string line;
    long line_number = 1;
    auto refuse = [&](const std::string& problem) -> DumpError {
        return DumpError(printable(name) + ":" + std::to_string(line_number) + ": " + problem);
    };
    const bool got_line = static_cast<bool>(std::getline(in, line));
    if (!got_line || (line != kDumpHeader && line != kDumpHeaderWithIds)) {
        throw refuse("not a state dump: the first line must be \"" + std::string(kDumpHeader) + "\" (or, with ids, \"" +
                     std::string(kDumpHeaderWithIds) + "\")");
    }
    // With ids, each row has one more field, after the index.
    const std::size_t id_fields = line == kDumpHeaderWithIds ? 1 : 0;
    const std::size_t fields = 3 + id_fields + kDumpFields.size();
    while (std::getline(in, line)) {
        ++line_number;
        const std::vector<std::string_view> parts = split_commas(line);
        if (parts.size() != fields) {
            throw refuse("a row has " + std::to_string(fields) + " fields, this has " + std::to_string(parts.size()));
        }
        DumpRow row;
        const auto step = read_number<long>(parts[0]);
        const auto index = read_number<std::size_t>(parts[1]);
        if (!step || !index) throw refuse("step and index must be whole numbers");
        row.step = *step;
        row.index = *index;
        if (id_fields == 1) {
            row.id = read_number<std::uint64_t>(parts[2]);
            if (!row.id) throw refuse("the id must be a whole number");
        }
        row.shape = parts[2 + id_fields];
        if (row.shape != "rectangle" && row.shape != "circle") throw refuse("the shape must be rectangle or circle");
        for (std::size_t f = 0; f < kDumpFields.size(); ++f) {
            const auto value = read_number<double>(parts[3 + id_fields + f]);
            if (!value) throw refuse(std::string(kDumpFields[f]) + " is not a number");
            row.values[f] = *value;
        }
        const bool next_body = !rows.empty() && row.step == rows.back().step && row.index == rows.back().index + 1;
        const bool next_step = row.index == 0 && row.step == (rows.empty() ? 0 : rows.back().step + 1);
        if (!next_body && !next_step) {
            throw refuse("rows must go step by step from step 0, each step's bodies numbered from 0");
        }
        rows.push_back(std::move(row));
    }
    return rows;
}

std::vector<DumpRow> read_dump(const std::filesystem::path& file) {
    std::error_code error;
    if (!std::filesystem::is_regular_file(file, error)) {
        throw DumpError(printable(file.string()) + ": not a regular file that can be read");
    }
    std::ifstream in(file);
    if (!in) throw DumpError(printable(file.string()) + ": cannot be read");
    return parse_dump(in, file.string());
}

bool agree(double a, double b, DumpTolerance tolerance) {
    return std::abs(a - b) <= tolerance.absolute + tolerance.relative * std::max(std::abs(a), std::abs(b));
}

std::optional<Divergence> first_divergence(const std::vector<DumpRow>& a, const std::vector<DumpRow>& b,
                                           DumpTolerance tolerance) {
    const Steps steps_a = by_step(a), steps_b = by_step(b);
    for (std::size_t step = 0; step < std::max(steps_a.size(), steps_b.size()); ++step) {
        Divergence d;
        d.step = static_cast<long>(step);
        d.bodies_a = step < steps_a.size() ? steps_a[step].size() : 0;
        d.bodies_b = step < steps_b.size() ? steps_b[step].size() : 0;
        d.bodies_before_a = step > 0 && step - 1 < steps_a.size() ? steps_a[step - 1].size() : 0;
        d.bodies_before_b = step > 0 && step - 1 < steps_b.size() ? steps_b[step - 1].size() : 0;
        if (step >= steps_a.size() || step >= steps_b.size()) {
            d.kind = DivergenceKind::steps_end;
            d.a_is_longer = step < steps_a.size();
            return d;
        }
        std::optional<Divergence> first;
        for (std::size_t i = 0; i < std::min(d.bodies_a, d.bodies_b); ++i) {
            const DumpRow& row_a = *steps_a[step][i];
            const DumpRow& row_b = *steps_b[step][i];
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
            d.shape = (d.a_is_longer ? steps_a : steps_b)[step][d.index]->shape;
            return d;
        }
    }
    return std::nullopt;
}

std::optional<KnownDifference> known_difference(const Divergence& divergence, std::string_view stage) {
    const std::optional<int> number = stage_number(stage);
    if (!number || divergence.step == 0) return std::nullopt;
    for (const Entry& entry : kEntries) {
        if (*number >= entry.from_stage && entry.fits(divergence)) return entry.difference;
    }
    return std::nullopt;
}

std::vector<KnownDifference> known_differences() {
    std::vector<KnownDifference> all;
    for (const Entry& entry : kEntries) all.push_back(entry.difference);
    return all;
}

std::string heading_anchor(std::string_view heading) {
    std::string anchor;
    for (const char c : heading) {
        if (c == ' ') {
            anchor += '-';
        } else if (std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_') {
            anchor += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
        }
    }
    return anchor;
}

std::string describe(const Divergence& divergence, std::string_view name_a, std::string_view name_b,
                     DumpTolerance tolerance, std::string_view stage) {
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
    if (stage.empty()) return text + "(give --stage X.Y to look the difference up in docs/errata.md)\n";
    if (const auto known = known_difference(divergence, stage)) {
        return text + "known difference: docs/errata.md#" + heading_anchor(known->heading) + " (\"" +
               std::string(known->heading) + "\"): " + std::string(known->sign) + "\n";
    }
    return text + "no entry of docs/errata.md explains this for " + std::string(stage) +
           ": a difference to look into\n";
}

}  // namespace browser
