// The settings a scene is run with: each knob alone over its range, nothing twice.
#include <catch2/catch.hpp>

#include "sweep.h"

namespace {

std::vector<std::string> labels(const std::vector<bench::Setting>& settings) {
    std::vector<std::string> list;
    for (const bench::Setting& setting : settings) list.push_back(setting.label);
    return list;
}

}  // namespace

TEST_CASE("one_at_a_time: the scene first, then each value of each knob that differs from it") {
    browser::WorldSettings base;  // 15 passes, dt 1/60, one sub-step
    const auto settings = bench::one_at_a_time(base, {{bench::Knob::relaxation_iterations}, {bench::Knob::substeps}}, false);
    CHECK(labels(settings) == std::vector<std::string>{"scene", "passes 1", "passes 2", "passes 4", "passes 8",
                                                       "passes 30", "substeps 2", "substeps 4", "substeps 8"});
    CHECK(settings[0].varied.empty());
    CHECK(settings[0].world == base);
    CHECK(settings[4].varied == "relaxation_iterations");
    CHECK(settings[4].world.relaxation_iterations == 8);
    CHECK(settings[4].world.substeps == 1);  // every other knob as in the scene
    CHECK(settings[8].world.substeps == 8);
    CHECK(settings[8].world.relaxation_iterations == 15);
}

TEST_CASE("one_at_a_time: dt, broad phases, switches") {
    browser::WorldSettings base;
    base.broad_phase = browser::BroadPhase::grid;
    const auto settings = bench::one_at_a_time(
        base, {{bench::Knob::dt}, {bench::Knob::broad_phase}, {bench::Knob::rotation}, {bench::Knob::friction}}, false);
    CHECK(labels(settings) == std::vector<std::string>{"scene", "dt 1/30", "dt 1/120", "dt 1/240", "bounding_circle",
                                                       "all_pairs", "rotation off", "friction off"});
    CHECK(settings[3].world.dt == 1.0 / 240);
    CHECK_FALSE(settings[6].world.rotation);
    CHECK(settings[6].world.friction);
}

TEST_CASE("one_at_a_time: a quick run keeps one other value of each knob, and so does Range::one") {
    const browser::WorldSettings base;
    const auto quick =
        bench::one_at_a_time(base, {{bench::Knob::relaxation_iterations}, {bench::Knob::friction_model}}, true);
    CHECK(labels(quick) == std::vector<std::string>{"scene", "passes 1", "friction coulomb"});
    const auto light = bench::one_at_a_time(
        base, {{bench::Knob::substeps, bench::Range::one}, {bench::Knob::dt, bench::Range::one}}, false);
    CHECK(labels(light) == std::vector<std::string>{"scene", "substeps 2", "dt 1/30"});
}

TEST_CASE("dt_label: steps per second") {
    CHECK(bench::dt_label(1.0 / 60) == "dt 1/60");
    CHECK(bench::dt_label(1.0 / 240) == "dt 1/240");
    CHECK(bench::dt_label(0.3) == "dt 0.300000");
}
