// The settings a scene is run with: the scene on each stage, then each knob alone over
// its range, on the oldest stage that has it, nothing twice.
#include <catch2/catch.hpp>

#include "sweep.h"

namespace {

using bench::Stage;

std::vector<std::string> labels(const std::vector<bench::Setting>& settings) {
    std::vector<std::string> list;
    for (const bench::Setting& setting : settings) list.push_back(setting.label);
    return list;
}

std::vector<Stage> stages(const std::vector<bench::Setting>& settings) {
    std::vector<Stage> list;
    for (const bench::Setting& setting : settings) list.push_back(setting.stage);
    return list;
}

const std::vector<Stage> kAll{Stage::s5_1, Stage::s5_2, Stage::s5_3};

}  // namespace

TEST_CASE("one_at_a_time: the scene on each stage, then each knob's values on the oldest stage that has it") {
    const bench::WorldDescription base = bench::book_world();  // 15 passes, dt 1/60
    const auto settings =
        bench::one_at_a_time(base, kAll, {{bench::Knob::substeps}, {bench::Knob::relaxation_iterations}}, false);
    // Sub-steps 1 is 5.3's own default: the scene already runs it. The knobs come stage
    // by stage, whatever order the sweeps were listed in.
    CHECK(labels(settings) == std::vector<std::string>{"scene", "scene", "scene", "passes 1", "passes 2", "passes 4",
                                                       "passes 8", "passes 30", "substeps 2", "substeps 4",
                                                       "substeps 8"});
    CHECK(stages(settings) == std::vector<Stage>{Stage::s5_1, Stage::s5_2, Stage::s5_3, Stage::s5_1, Stage::s5_1,
                                                 Stage::s5_1, Stage::s5_1, Stage::s5_1, Stage::s5_3, Stage::s5_3,
                                                 Stage::s5_3});
    CHECK(settings[0].varied.empty());
    CHECK(settings[0].world == base);
    CHECK(settings[6].varied == "relaxation_iterations");
    CHECK(settings[6].world.relaxation_iterations == 8);
    CHECK_FALSE(settings[6].world.substeps);  // every other key as in the scene
    CHECK(settings[10].world.substeps == 8);
    CHECK(settings[10].world.relaxation_iterations == 15);
}

TEST_CASE("one_at_a_time: dt, broad phases, switches, without the book's stage") {
    const auto settings = bench::one_at_a_time(
        bench::book_world(), {Stage::s5_2, Stage::s5_3},
        {{bench::Knob::dt}, {bench::Knob::broad_phase}, {bench::Knob::rotation}, {bench::Knob::friction}}, false);
    // The grid is 5.2's own default; dt falls to 5.2, the oldest stage here.
    CHECK(labels(settings) == std::vector<std::string>{"scene", "scene", "dt 1/30", "dt 1/120", "dt 1/240",
                                                       "bounding_circle", "all_pairs", "rotation off", "friction off"});
    CHECK(stages(settings) == std::vector<Stage>{Stage::s5_2, Stage::s5_3, Stage::s5_2, Stage::s5_2, Stage::s5_2,
                                                 Stage::s5_2, Stage::s5_2, Stage::s5_3, Stage::s5_3});
    CHECK(settings[4].world.dt == 1.0 / 240);
    CHECK(settings[7].world.rotation == false);
    CHECK_FALSE(settings[7].world.friction);
}

TEST_CASE("one_at_a_time: a quick run keeps one other value of each knob, and so does Range::one") {
    const bench::WorldDescription base = bench::book_world();
    const auto quick =
        bench::one_at_a_time(base, kAll, {{bench::Knob::relaxation_iterations}, {bench::Knob::friction_model}}, true);
    CHECK(labels(quick) == std::vector<std::string>{"scene", "scene", "scene", "passes 1", "friction coulomb"});
    const auto light = bench::one_at_a_time(
        base, kAll, {{bench::Knob::substeps, bench::Range::one}, {bench::Knob::dt, bench::Range::one}}, false);
    CHECK(labels(light) == std::vector<std::string>{"scene", "scene", "scene", "dt 1/30", "substeps 2"});
}

TEST_CASE("one_at_a_time: a setting no stage of the study can express is not run") {
    const auto settings = bench::one_at_a_time(bench::book_world(), {Stage::s5_1},
                                               {{bench::Knob::substeps}, {bench::Knob::broad_phase}}, false);
    CHECK(labels(settings) == std::vector<std::string>{"scene"});
}

TEST_CASE("dt_label: steps per second") {
    CHECK(bench::dt_label(1.0 / 60) == "dt 1/60");
    CHECK(bench::dt_label(1.0 / 240) == "dt 1/240");
    CHECK(bench::dt_label(0.3) == "dt 0.300000");
}
