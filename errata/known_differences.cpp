#include "known_differences.h"

#include <algorithm>
#include <cctype>

namespace errata {

using browser::DifferingBody;
using browser::Divergence;
using browser::DivergenceKind;

namespace {

// Book projects as one number: "4.4" is 44. Nothing for a text of another form.
std::optional<int> stage_number(std::string_view stage) {
    const auto digit = [](char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; };
    if (stage.size() != 3 || !digit(stage[0]) || stage[1] != '.' || !digit(stage[2])) return std::nullopt;
    return (stage[0] - '0') * 10 + (stage[2] - '0');
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

}  // namespace

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

std::string explanation(const Divergence& divergence, std::string_view stage) {
    if (stage.empty()) return "(give --stage X.Y to look the difference up in docs/errata.md)\n";
    if (const auto known = known_difference(divergence, stage)) {
        return "known difference: docs/errata.md#" + heading_anchor(known->heading) + " (\"" +
               std::string(known->heading) + "\"): " + std::string(known->sign) + "\n";
    }
    return "no entry of docs/errata.md explains this for " + std::string(stage) + ": a difference to look into\n";
}

}  // namespace errata
