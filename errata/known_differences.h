#pragma once
// The differences from the book we know of and keep, or fix, on purpose (docs/errata.md
// tells each one), as first_divergence looks them up: which book project has each one,
// and what a divergence between our state dump and the book's shows of it. The browser
// compares two dumps (common/dump_divergence.h); which project ran them, and what the
// book does there, is only known here.

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "dump_divergence.h"

namespace errata {

// An errata entry that explains a divergence: its heading in docs/errata.md, exactly as
// written after "### ", and what in the divergence points to it.
struct KnownDifference {
    std::string_view heading;
    std::string_view sign;
};

// The entry that explains `divergence` for the book project `stage` ("4.4", "5.1"), or
// nothing. It is the likely cause, told by which stage, shape and field, not a proof.
std::optional<KnownDifference> known_difference(const browser::Divergence& divergence, std::string_view stage);
// Every entry the table knows, for the test that each heading is in docs/errata.md.
std::vector<KnownDifference> known_differences();

// The anchor GitHub gives a heading: lower case, spaces as hyphens, no punctuation
// ("Circle inertia (fixed, 4.1 on)" -> "circle-inertia-fixed-41-on").
std::string heading_anchor(std::string_view heading);

// The report's last line, for a divergence after step 0: the known difference that
// explains it for `stage`, that none does, or ("" for `stage`) how to ask.
std::string explanation(const browser::Divergence& divergence, std::string_view stage);

}  // namespace errata
