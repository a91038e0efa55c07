// The bench's scenes: the committed files are what the generators make, every stage
// reads them, they read back exactly, and they start as described.
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>

#include "measures.h"
#include "near.h"
#include "scene_json.h"
#include "scene_maker.h"
#include "scratch_folder.h"
#include "stages.h"

namespace {

using bench::SceneDescription;
using bench::Stage;

bool same(const SceneDescription& a, const SceneDescription& b) { return a.world == b.world && a.bodies == b.bodies; }

std::size_t moving(const SceneDescription& scene) {
    std::size_t count = 0;
    for (const auto& body : scene.bodies) count += body.mass > 0 ? 1 : 0;
    return count;
}

}  // namespace

TEST_CASE("scenes: bench/scenes/ holds exactly what `bench --write-scenes` makes") {
    for (const bench::scenes::NamedScene& named : bench::scenes::shipped()) {
        INFO(named.name);
        CHECK(same(bench::read_scene(std::filesystem::path(BENCH_SCENES_DIR) / (named.name + ".json")), named.scene));
    }
}

TEST_CASE("scenes: only the book's world keys, so every chapter 5 stage reads them") {
    for (const bench::scenes::NamedScene& named : bench::scenes::shipped()) {
        INFO(named.name);
        for (Stage stage : bench::kChapter5Stages) CHECK(bench::can_express(stage, named.scene.world));
    }
}

TEST_CASE("scene_json: every book key and body key reads back to the same value") {
    test::ScratchFolder folder("bench_scene_json");
    SceneDescription scene = bench::scenes::pair(bench::scenes::PairKind::rect_circle);
    scene.world.dt = 1.0 / 3;  // no short decimal form
    scene.world.correction_rate = 0.7;
    scene.world.positional_correction = false;
    scene.bodies[1].angle = 0.1;
    scene.bodies[1].velocity = {1.0 / 7, -2};
    scene.bodies[1].angular_velocity = -3.5;
    bench::write_scene(folder.path / "scene.json", scene);
    CHECK(same(bench::read_scene(folder.path / "scene.json"), scene));
    CHECK(folder.files() == std::vector<std::string>{"scene.json"});  // no .partial left
    // The bench writes bodies with its own type; every chapter 5 stage reads them with its
    // own keys (scene_io.cpp), and each gives back the very numbers.
    for (Stage stage : bench::kChapter5Stages) {
        INFO(bench::stage_name(stage));
        CHECK(same(bench::stage_engine(stage)->read_scene(bench::scene_json(scene), "bench"), scene));
    }
}

TEST_CASE("scene_json: every world key the bench writes is one the newest stage reads, in its words") {
    // Each of the bench's choices, written with every other knob set, read by 5.6.
    bench::WorldDescription world = bench::book_world();
    world.substeps = 2;
    world.rotation = false;
    world.friction = false;
    world.velocity_iterations = 4;
    world.warm_starting = false;
    world.restitution_threshold = 10;
    world.sleep = false;
    world.continuous = false;
    const std::vector<std::string> read = bench::stage_engine(Stage::s5_6)->world_keys();
    const auto check = [&](const bench::WorldDescription& w) {
        for (const bench::WorldEntry& entry : bench::world_entries(w)) {
            INFO(entry.key);
            CHECK(std::find(read.begin(), read.end(), entry.key) != read.end());
        }
        CHECK_NOTHROW(bench::stage_world(Stage::s5_6, {w, {}}));
    };
    for (auto phase : {bench::BroadPhase::bounding_circle, bench::BroadPhase::all_pairs, bench::BroadPhase::grid}) {
        for (auto integrator : {bench::Integrator::symplectic, bench::Integrator::explicit_euler}) {
            for (auto model : {bench::FrictionModel::book, bench::FrictionModel::coulomb}) {
                for (auto solver : {bench::Solver::book, bench::Solver::sequential_impulse}) {
                    for (auto method : {bench::PositionMethod::split_impulse, bench::PositionMethod::baumgarte,
                                        bench::PositionMethod::relax}) {
                        world.broad_phase = phase;
                        world.integrator = integrator;
                        world.friction_model = model;
                        world.solver = solver;
                        world.position_method = method;
                        check(world);
                    }
                }
            }
        }
    }
}

TEST_CASE("scene_json: a later stage's key is written only when set, and reaches that stage") {
    const bench::WorldDescription book = bench::book_world();
    CHECK_THAT(bench::scene_json({book, {}}), !Catch::Contains("substeps") && !Catch::Contains("broad_phase"));
    // Each knob, changed on its own, makes a world that 5.3 reads differently.
    const std::unique_ptr<bench::StageEngine> knobs = bench::stage_engine(Stage::s5_3);
    const bench::WorldDescription defaults = bench::resolved(Stage::s5_3, book);
    std::vector<bench::WorldDescription> changed(6, defaults);
    changed[0].broad_phase = bench::BroadPhase::all_pairs;
    changed[1].substeps = 4;
    changed[2].integrator = bench::Integrator::explicit_euler;
    changed[3].friction_model = bench::FrictionModel::coulomb;
    changed[4].rotation = false;
    changed[5].friction = false;
    for (const bench::WorldDescription& world : changed) {
        CHECK_FALSE(knobs->same_settings(world, defaults));
        CHECK(bench::resolved(Stage::s5_3, world) == world);
    }
}

TEST_CASE("scenes: the pyramids have rows (rows + 1) / 2 boxes, and no two shapes overlap at the start") {
    for (int rows : {10, 20}) {
        const SceneDescription scene = bench::scenes::pyramid(rows);
        CHECK(moving(scene) == static_cast<std::size_t>(rows * (rows + 1) / 2));
        CHECK(bench::penetration(bench::stage_world(Stage::s5_1, scene)->snapshot()).pairs == 0);
    }
}

TEST_CASE("scenes: the rains hold the shapes asked for in an open box, none overlapping at the start") {
    for (int shapes : {100, 400}) {
        const SceneDescription scene = bench::scenes::rain(shapes);
        CHECK(moving(scene) == static_cast<std::size_t>(shapes));
        CHECK(scene.bodies.size() == static_cast<std::size_t>(shapes) + 3);  // floor and two walls
        CHECK(bench::penetration(bench::stage_world(Stage::s5_1, scene)->snapshot()).pairs == 0);
    }
}

TEST_CASE("scenes: the gas is 60 discs at 150 px/s, elastic and frictionless, in a closed box without gravity") {
    const SceneDescription scene = bench::scenes::gas();
    CHECK(scene.world.gravity == lib::Vec2{0, 0});
    CHECK(scene.bodies.size() == 64);
    for (const auto& body : scene.bodies) {
        CHECK(body.restitution == 1.0);
        CHECK(body.friction == 0.0);
        if (body.mass > 0) CHECK(body.velocity.length() == Approx(150.0));
    }
    CHECK(bench::penetration(bench::stage_world(Stage::s5_1, scene)->snapshot()).pairs == 0);
}

TEST_CASE("scenes: the slope's disc touches the slope, and the wall's ball starts 1 px from the wall") {
    const bench::Snapshot slope = bench::stage_world(Stage::s5_1, bench::scenes::slope())->snapshot();
    // Touching to rounding: the disc's centre is worked out through a turn (sin, cos).
    CHECK_THAT(oracle::depth(slope[0].shape, slope[1].shape), test::near(0.0, 1e-9));
    const bench::Snapshot wall = bench::stage_world(Stage::s5_1, bench::scenes::thin_wall())->snapshot();
    CHECK(oracle::depth(wall[0].shape, wall[1].shape) == Approx(-1.0));
}

TEST_CASE("scenes: the scale scenes keep their density as they grow") {
    // sqrt(n) rounded up columns of 20 px, 20 px in from the canvas's edges: 50 shapes on
    // 8 x 8 cells, 2000 on 45 x 45.
    for (const auto& [shapes, columns] : std::vector<std::array<int, 2>>{{50, 8}, {2000, 45}}) {
        const SceneDescription scene = bench::scenes::scale(shapes);
        CHECK(moving(scene) == static_cast<std::size_t>(shapes));
        CHECK(scene.bodies.size() == static_cast<std::size_t>(shapes));
        CHECK(scene.world.width == columns * 20 + 40);
        CHECK(scene.world.width <= 4096);
    }
}
