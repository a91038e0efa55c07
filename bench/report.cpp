#include "report.h"

#include <cstdio>
#include <functional>
#include <thread>

#include "box2d_world.h"
#include "markdown.h"

namespace bench {
namespace {

std::string number(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.6g", value);
    return text;
}
std::string number(const std::optional<double>& value) { return value ? number(*value) : ""; }

std::string field(const std::string& text) {
    if (text.find_first_of(",\"\n") == std::string::npos) return text;
    std::string quoted = "\"";
    for (char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
    return quoted + "\"";
}

struct CsvColumn {
    const char* header;
    std::function<std::string(const Row&)> value;
};

// A key's value as the row ran it, "" where its engine does not read the key (Box2D
// has none of them but dt; 5.1 none beyond the book's).
std::string whole(const std::optional<int>& value) { return value ? std::to_string(*value) : ""; }
std::string on_off(const std::optional<bool>& value) { return value ? (*value ? "on" : "off") : ""; }
template <class Choice>
std::string chosen(const std::optional<Choice>& value) {
    return value ? std::string(spelling(*value)) : "";
}
bool is_box2d(const Row& row) { return row.stage == Stage::box2d; }

const std::vector<CsvColumn>& columns() {
    static const std::vector<CsvColumn> list{
        {"study", [](const Row& r) { return r.study; }},
        {"scene", [](const Row& r) { return r.scene; }},
        {"stage", [](const Row& r) { return stage_name(r.stage); }},
        {"setting", [](const Row& r) { return r.setting; }},
        {"varied", [](const Row& r) { return r.varied; }},
        {"bodies", [](const Row& r) { return std::to_string(r.bodies); }},
        {"dt", [](const Row& r) { return number(r.world.dt); }},
        {"relaxation_iterations",
         [](const Row& r) { return is_box2d(r) ? "" : std::to_string(r.world.relaxation_iterations); }},
        {"correction_rate", [](const Row& r) { return is_box2d(r) ? "" : number(r.world.correction_rate); }},
        {"broad_phase", [](const Row& r) { return chosen(r.world.broad_phase); }},
        {"substeps", [](const Row& r) { return whole(r.world.substeps); }},
        {"integrator", [](const Row& r) { return chosen(r.world.integrator); }},
        {"friction_model", [](const Row& r) { return chosen(r.world.friction_model); }},
        {"rotation", [](const Row& r) { return on_off(r.world.rotation); }},
        {"friction", [](const Row& r) { return on_off(r.world.friction); }},
        {"solver", [](const Row& r) { return chosen(r.world.solver); }},
        {"velocity_iterations", [](const Row& r) { return whole(r.world.velocity_iterations); }},
        {"warm_starting", [](const Row& r) { return on_off(r.world.warm_starting); }},
        {"position_method", [](const Row& r) { return chosen(r.world.position_method); }},
        {"restitution_threshold", [](const Row& r) { return number(r.world.restitution_threshold); }},
        {"sleep", [](const Row& r) { return on_off(r.world.sleep); }},
        {"continuous", [](const Row& r) { return on_off(r.world.continuous); }},
        {"events", [](const Row& r) { return on_off(r.world.events); }},
        {"steps", [](const Row& r) { return std::to_string(r.steps); }},
        {"repeats", [](const Row& r) { return std::to_string(r.repeats); }},
        {"cost_us", [](const Row& r) { return number(r.cost_us); }},
        {"steps_per_s", [](const Row& r) { return number(r.steps_per_second()); }},
        {"ms_per_simulated_s", [](const Row& r) { return number(r.ms_per_simulated_second()); }},
        {"candidate_pairs", [](const Row& r) { return number(r.candidate_pairs); }},
        {"narrow_tests", [](const Row& r) { return number(r.narrow_tests); }},
        {"skipped_tests", [](const Row& r) { return number(r.skipped_tests); }},
        {"passes", [](const Row& r) { return number(r.passes); }},
        {"begins", [](const Row& r) { return r.events ? number(r.events->begins) : ""; }},
        {"ends", [](const Row& r) { return r.events ? number(r.events->ends) : ""; }},
        {"hits", [](const Row& r) { return r.events ? number(r.events->hits) : ""; }},
        {"penetration_max", [](const Row& r) { return number(r.metrics.penetration_max); }},
        {"penetration_mean", [](const Row& r) { return number(r.metrics.penetration_mean); }},
        {"top_drift", [](const Row& r) { return number(r.metrics.top_drift); }},
        {"energy_change", [](const Row& r) { return number(r.metrics.energy_change); }},
        {"trajectory_error", [](const Row& r) { return number(r.metrics.trajectory_error); }},
        {"slide_error", [](const Row& r) { return number(r.metrics.slide_error); }},
        {"roll_error", [](const Row& r) { return number(r.metrics.roll_error); }},
        {"tunnel_speed", [](const Row& r) { return number(r.metrics.tunnel_speed); }},
        {"ns_per_pair", [](const Row& r) { return number(r.metrics.ns_per_pair); }},
    };
    return list;
}

}  // namespace

std::string csv_header() {
    std::string line;
    for (const CsvColumn& column : columns()) {
        if (!line.empty()) line += ',';
        line += column.header;
    }
    return line;
}

std::string results_csv(const std::vector<Row>& rows) {
    std::string text = csv_header() + "\n";
    for (const Row& row : rows) {
        std::string line;
        for (const CsvColumn& column : columns()) {
            if (&column != &columns().front()) line += ',';
            line += field(column.value(row));
        }
        text += line + "\n";
    }
    return text;
}

std::string results_markdown(const RunFacts& facts, const std::vector<StudyResult>& studies) {
    std::string text = "# What each stage's engine and knobs cost and buy: the bench\n\n";
    text += "Written by `bench`";
    text += facts.quick ? " **--quick** (short runs and few settings: a smoke test, not figures to quote)" : "";
    text += " in " + figure(facts.seconds) + " s on " + std::to_string(std::thread::hardware_concurrency()) +
            " cores; each cost is the median of " + std::to_string(facts.repeats) +
            (facts.repeats == 1 ? " timed run" : " timed runs") +
            " per setting, each on a fresh world, errors from the first. Every row names the engine that made it: "
            "stage 5.1 (the book's), 5.2 (+ the broad phase, its grid by default), 5.3 (+ the knobs), "
            "5.4 (+ a contact solver), 5.5 (+ sleeping, on by default), 5.6 (+ continuous collision, on by default), "
            "5.7 (+ collision events, kept only while read: its rows are the speed study's) or Box2D; a setting runs "
            "on the oldest stage that can express it. "
            "Everything runs on one core, one setting after another. To keep the whole run within a few minutes, each "
            "scene runs only as long "
            "as its figure needs (stated per section): the pyramids 10 s of simulated time, the rains 6 s, the gas "
            "10,000 steps, and the big scenes try fewer knobs. Costs are the processor time of the thread that steps "
            "the engine (CLOCK_THREAD_CPUTIME_ID), not wall-clock time: the time a run waits for a core on a shared "
            "machine is left out, but caches and memory are still shared, so compare rows of one run, not runs of "
            "different days. Definitions and targets: bench/README.md.\n\n";
    text += facts.box2d ? "Box2D reference: " + box2d_version() + ", " + std::to_string(kBox2dVelocityIterations) +
                              " velocity and " + std::to_string(kBox2dPositionIterations) +
                              " position iterations, continuous collision off, sleeping off.\n\n"
                        : std::string(kNoBox2d) + ".\n\n";
    std::string key;
    for (const StudyResult& study : studies) {
        for (const std::string& line : study.key_figures) key += "- " + line + "\n";
    }
    if (!key.empty()) text += "## Key figures\n\n" + key + "\n";
    for (const StudyResult& study : studies) text += study.markdown;
    return text;
}

}  // namespace bench
