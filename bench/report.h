#pragma once
// results.csv and results.md.

#include <string>
#include <vector>

#include "row.h"
#include "study.h"

namespace bench {

// The header line of results.csv, without its line end.
std::string csv_header();
// The header and one line per row. A field holding a comma or a quote is quoted, a
// number has 6 significant digits, and a figure a row does not have is left empty.
std::string results_csv(const std::vector<Row>& rows);

// How the run went, for the top of results.md.
struct RunFacts {
    bool quick = false;
    int repeats = 0;
    double seconds = 0.0;  // wall-clock time of the whole run
    bool box2d = false;
};
std::string results_markdown(const RunFacts& facts, const std::vector<StudyResult>& studies);

}  // namespace bench
