// results.csv and the numbers in results.md.
#include <catch2/catch.hpp>

#include <sstream>

#include "markdown.h"
#include "report.h"
#include "stages.h"

namespace {

std::vector<std::string> lines_of(const std::string& text) {
    std::vector<std::string> lines;
    std::istringstream stream(text);
    for (std::string line; std::getline(stream, line);) lines.push_back(line);
    return lines;
}

std::vector<std::string> fields_of(const std::string& line) {
    std::vector<std::string> fields;
    std::istringstream stream(line);
    for (std::string field; std::getline(stream, field, ',');) fields.push_back(field);
    if (!line.empty() && line.back() == ',') fields.emplace_back();
    return fields;
}

}  // namespace

TEST_CASE("results_csv: the header, then one line per row with every column") {
    bench::Row plain;
    plain.world = bench::book_world();
    plain.study = "pyramid_10";
    plain.scene = "pyramid_10";
    plain.setting = "passes 8";
    plain.varied = "relaxation_iterations";
    plain.world.relaxation_iterations = 8;
    plain.cost_us = 250.0;
    plain.steps = 600;
    plain.metrics.top_drift = 0.5;
    bench::Row reference = plain;
    reference.stage = bench::Stage::box2d;
    reference.setting = "Box2D 2.4";
    bench::Row knobs = plain;
    knobs.stage = bench::Stage::s5_3;
    knobs.setting = "substeps 2";
    knobs.world.substeps = 2;
    knobs.world.broad_phase = bench::BroadPhase::grid;

    const std::vector<std::string> lines = lines_of(bench::results_csv({plain, reference, knobs}));
    REQUIRE(lines.size() == 4);
    CHECK(lines[0] == bench::csv_header());
    const std::vector<std::string> header = fields_of(lines[0]);
    CHECK(header.front() == "study");
    const auto column = [&](const std::string& name) {
        const auto at = std::find(header.begin(), header.end(), name);
        REQUIRE(at != header.end());
        return static_cast<std::size_t>(at - header.begin());
    };
    const std::vector<std::string> first = fields_of(lines[1]);
    const std::vector<std::string> second = fields_of(lines[2]);
    const std::vector<std::string> third = fields_of(lines[3]);
    REQUIRE(first.size() == header.size());
    REQUIRE(second.size() == header.size());
    REQUIRE(third.size() == header.size());
    CHECK(first[column("stage")] == "5.1");
    CHECK(first[column("relaxation_iterations")] == "8");
    CHECK(first[column("substeps")].empty());  // not a key of 5.1's
    CHECK(first[column("cost_us")] == "250");
    CHECK(first[column("steps_per_s")] == "4000");       // 1e6 / 250
    CHECK(first[column("ms_per_simulated_s")] == "15");  // 250 us x 60 steps
    CHECK(first[column("top_drift")] == "0.5");
    CHECK(first[column("energy_change")].empty());  // not measured here
    CHECK(second[column("stage")] == bench::stage_name(bench::Stage::box2d));
    CHECK(second[column("relaxation_iterations")].empty());  // not a Box2D knob
    CHECK(third[column("stage")] == "5.3");
    CHECK(third[column("substeps")] == "2");
    CHECK(third[column("broad_phase")] == "grid");
}

TEST_CASE("results_csv: a field with a comma is quoted") {
    bench::Row row;
    row.setting = "dt 1/60, substeps 2";
    row.cost_us = 1.0;
    CHECK_THAT(bench::results_csv({row}), Catch::Contains(",\"dt 1/60, substeps 2\","));
}

TEST_CASE("figure: three significant digits, no exponent for everyday sizes") {
    CHECK(bench::figure(1234.5) == "1230");
    CHECK(bench::figure(2.5) == "2.50");
    CHECK(bench::figure(0.000123) == "0.000123");
    CHECK(bench::figure(-0.0456) == "-0.0456");
    CHECK(bench::figure(1.5e-9) == "1.50e-09");
    CHECK(bench::figure(0.0) == "0");
    CHECK(bench::figure(std::optional<double>{}).empty());
    CHECK(bench::percent(0.0123) == "+1.23%");
    CHECK(bench::percent(-0.5) == "-50.0%");
}

TEST_CASE("MarkdownTable: a header line, a rule, a line per row") {
    bench::MarkdownTable table({"a", "b"});
    table.add({"1", "2"});
    CHECK(table.text() == "| a | b |\n| --- | --- |\n| 1 | 2 |\n\n");
    CHECK_THROWS_AS(table.add({"only one"}), std::invalid_argument);
}

TEST_CASE("a study's rows: one CSV line per setting, the scene's own on each stage first") {
    // The quick slide: its own world on 5.1, 5.2, 5.3, 5.5 and 5.6 (5.4 runs it as 5.3,
    // bit for bit, and 5.7 as 5.6, and neither has a row for it; 5.5 and 5.6 sleep and
    // sweep fast shapes unless told not to), then one other value of each knob it varies, on the
    // oldest stage that has it: passes and dt on 5.1; friction model, sub-steps,
    // integrator and rotation on 5.3; the sequential impulse solver on 5.4.
    const bench::StudyContext context{.quick = true, .repeats = 1, .scenes_dir = BENCH_SCENES_DIR};
    const bench::StudyResult result = bench::slide_study(context);
    const std::vector<std::string> lines = lines_of(bench::results_csv(result.rows));
    REQUIRE(lines.size() == 1 + 5 + 7);
    CHECK_THAT(lines.back(), Catch::StartsWith("slide,slide,5.4,sequential impulse,solver,2,"));
    CHECK(lines[0] == bench::csv_header());
    CHECK_THAT(lines[1], Catch::StartsWith("slide,slide,5.1,scene,,2,"));
    CHECK_THAT(lines[2], Catch::StartsWith("slide,slide,5.2,scene,,2,"));
    CHECK_THAT(lines[3], Catch::StartsWith("slide,slide,5.3,scene,,2,"));
    CHECK_THAT(lines[4], Catch::StartsWith("slide,slide,5.5,scene,,2,"));
    CHECK_THAT(lines[5], Catch::StartsWith("slide,slide,5.6,scene,,2,"));
    for (const bench::Row& row : result.rows) CHECK(row.metrics.slide_error);
    REQUIRE(result.figures.size() == 1);
    CHECK(result.figures[0].file == "cost_vs_error_slide.png");
    CHECK_THAT(result.markdown, Catch::StartsWith("## Friction: a sliding box"));
}
