// The chapter 5 stages in one program: each is its own engine, reads the keys its
// scene files may hold and refuses the others, and moves a scene as the others do where
// the book's engine is all it uses.
#include <catch2/catch.hpp>

#include <cmath>

#include "scene_maker.h"
#include "stages.h"

namespace {

using bench::Stage;
using bench::WorldDescription;

WorldDescription with(void (*change)(WorldDescription&)) {
    WorldDescription world = bench::book_world();
    change(world);
    return world;
}

bool same_positions(const bench::Snapshot& a, const bench::Snapshot& b) {
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i) {
        if (oracle::center(a[i].shape) != oracle::center(b[i].shape) || a[i].velocity != b[i].velocity) return false;
    }
    return true;
}

}  // namespace

TEST_CASE("stages: each row's stage by name") {
    CHECK(bench::stage_name(Stage::s5_1) == "5.1");
    CHECK(bench::stage_name(Stage::s5_2) == "5.2");
    CHECK(bench::stage_name(Stage::s5_3) == "5.3");
    CHECK(bench::stage_name(Stage::s5_6) == "5.6");
    CHECK(bench::stage_name(Stage::s5_7) == "5.7");
    CHECK_THROWS_AS(bench::stage_engine(Stage::box2d), std::invalid_argument);
}

TEST_CASE("stages: the book's world, as stage 5.1 keeps it") {
    const WorldDescription book = bench::book_world();
    CHECK(book.dt == 1.0 / 60);
    CHECK(book.relaxation_iterations == 15);
    CHECK(book.correction_rate == 0.8);
    CHECK_FALSE(book.broad_phase);
    CHECK_FALSE(book.substeps);
}

TEST_CASE("stages: what each stage can express is what its scene files may say") {
    const WorldDescription grid = with([](WorldDescription& w) { w.broad_phase = bench::BroadPhase::grid; });
    const WorldDescription substeps = with([](WorldDescription& w) { w.substeps = 2; });
    const WorldDescription coulomb =
        with([](WorldDescription& w) { w.friction_model = bench::FrictionModel::coulomb; });
    for (Stage stage : bench::kChapter5Stages) CHECK(bench::can_express(stage, bench::book_world()));
    CHECK_FALSE(bench::can_express(Stage::s5_1, grid));
    CHECK(bench::can_express(Stage::s5_2, grid));
    CHECK_FALSE(bench::can_express(Stage::s5_2, substeps));
    CHECK(bench::can_express(Stage::s5_3, substeps));
    CHECK(bench::can_express(Stage::s5_3, coulomb));
    const std::vector<Stage> all{bench::kChapter5Stages.begin(), bench::kChapter5Stages.end()};
    CHECK(bench::oldest_expressing(all, bench::book_world()) == Stage::s5_1);
    CHECK(bench::oldest_expressing(all, grid) == Stage::s5_2);
    CHECK(bench::oldest_expressing(all, coulomb) == Stage::s5_3);
    CHECK_FALSE(bench::oldest_expressing({Stage::s5_1, Stage::s5_2}, coulomb));
    const WorldDescription awake = with([](WorldDescription& w) { w.sleep = false; });
    const WorldDescription swept = with([](WorldDescription& w) { w.continuous = true; });
    CHECK_FALSE(bench::can_express(Stage::s5_4, awake));
    CHECK(bench::oldest_expressing(all, awake) == Stage::s5_5);
    CHECK_FALSE(bench::can_express(Stage::s5_5, swept));
    CHECK(bench::oldest_expressing(all, swept) == Stage::s5_6);
}

TEST_CASE("stages: a stage refuses a key it does not read, as its program does") {
    bench::SceneDescription scene = bench::scenes::pair(bench::scenes::PairKind::rect_rect);
    scene.world.broad_phase = bench::BroadPhase::grid;
    CHECK_THROWS_WITH(bench::stage_world(Stage::s5_1, scene),
                      Catch::StartsWith("stage 5.1: the bench's scene: world.broad_phase: unknown key; this stage's "
                                        "world takes width, height"));
    CHECK(bench::stage_world(Stage::s5_2, scene));
}

TEST_CASE("stages: resolved writes out each stage's own defaults, and only its keys") {
    const WorldDescription book = bench::book_world();
    CHECK(bench::resolved(Stage::s5_1, book) == book);
    const WorldDescription s5_2 = bench::resolved(Stage::s5_2, book);
    CHECK(s5_2.broad_phase == bench::BroadPhase::grid);
    CHECK_FALSE(s5_2.substeps);
    const WorldDescription s5_3 = bench::resolved(Stage::s5_3, book);
    CHECK(s5_3.broad_phase == bench::BroadPhase::grid);
    CHECK(s5_3.substeps == 1);
    CHECK(s5_3.integrator == bench::Integrator::symplectic);
    CHECK(s5_3.friction_model == bench::FrictionModel::book);
    CHECK(s5_3.rotation == true);
    CHECK(s5_3.friction == true);
    CHECK(bench::stage_engine(Stage::s5_3)->same_settings(book, s5_3));
    // Sleeping and continuous collision are on unless a scene turns them off.
    const WorldDescription s5_5 = bench::resolved(Stage::s5_5, book);
    CHECK(s5_5.sleep == true);
    CHECK_FALSE(s5_5.continuous);
    const WorldDescription s5_6 = bench::resolved(Stage::s5_6, book);
    CHECK(s5_6.sleep == true);
    CHECK(s5_6.continuous == true);
    CHECK_FALSE(s5_6.events);
    // No one reads 5.7's events unless the bench says so.
    const WorldDescription s5_7 = bench::resolved(Stage::s5_7, book);
    CHECK(s5_7.continuous == true);
    CHECK(s5_7.events == false);
}

TEST_CASE("stages: events are read on 5.7 alone, and reading them changes no shape's motion") {
    const WorldDescription read = with([](WorldDescription& w) { w.events = true; });
    const std::vector<Stage> all{bench::kChapter5Stages.begin(), bench::kChapter5Stages.end()};
    CHECK_FALSE(bench::can_express(Stage::s5_6, read));
    CHECK(bench::oldest_expressing(all, read) == Stage::s5_7);
    CHECK(bench::runs_scene_as_stage_before(Stage::s5_7));
    CHECK_FALSE(bench::runs_scene_as_stage_before(Stage::s5_6));
    bench::SceneDescription rain = bench::scenes::rain(100);
    rain.world.events = true;
    CHECK_THROWS_WITH(bench::stage_world(Stage::s5_6, rain),
                      "stage 5.6: the bench's scene: events read after every step: this stage tells none");
    // A rain of 100 for 3 s: the shapes land (begins, each fall faster than 10 px/s a
    // hit) and settle; every pair that ended had begun.
    constexpr long kSteps = 180;
    const auto heard = bench::stage_world(Stage::s5_7, rain);
    heard->run(kSteps);
    rain.world.events = false;
    const auto unheard = bench::stage_world(Stage::s5_7, rain);
    unheard->run(kSteps);
    CHECK(same_positions(heard->snapshot(), unheard->snapshot()));
    CHECK_FALSE(unheard->event_counts());
    REQUIRE(heard->event_counts());
    const bench::BenchWorld::EventCounts counts = *heard->event_counts();
    CHECK(counts.begins * kSteps >= 100);  // each of the 100 shapes lands on something
    CHECK(counts.ends <= counts.begins);
    CHECK(counts.hits > 0);
    CHECK(counts.hits <= counts.begins);
}

TEST_CASE("stages: the three engines move a rain alike, each in its own namespace") {
    // 5.2's and 5.3's grid finds the very pairs the book's bounding circles find, in the
    // same order, so the three stages, compiled into one program, must agree to the bit.
    const bench::SceneDescription rain = bench::scenes::rain(100);
    constexpr long kSteps = 60;
    std::vector<bench::Snapshot> after;
    for (Stage stage : bench::kChapter5Stages) {
        const auto world = bench::stage_world(stage, rain);
        world->run(kSteps);
        after.push_back(world->snapshot());
    }
    CHECK(same_positions(after[0], after[1]));
    CHECK(same_positions(after[0], after[2]));
    CHECK_FALSE(same_positions(after[0], bench::stage_world(Stage::s5_1, rain)->snapshot()));  // it did move
}

TEST_CASE("stages: with sleep and continuous collision off, 5.5 and 5.6 move a rain as the book does") {
    // Off, each runs a scene as the stage before it (their identity tests), and 5.4's
    // solver is the book's unless a scene says otherwise.
    bench::SceneDescription rain = bench::scenes::rain(100);
    constexpr long kSteps = 60;
    const auto book = bench::stage_world(Stage::s5_1, rain);
    book->run(kSteps);
    rain.world.sleep = false;
    const auto s5_5 = bench::stage_world(Stage::s5_5, rain);
    s5_5->run(kSteps);
    rain.world.continuous = false;
    const auto s5_6 = bench::stage_world(Stage::s5_6, rain);
    s5_6->run(kSteps);
    CHECK(same_positions(book->snapshot(), s5_5->snapshot()));
    CHECK(same_positions(book->snapshot(), s5_6->snapshot()));
}
