// The bench's scenes: the committed files are what the generators make, they read
// back exactly, and they start as described.
#include <catch2/catch.hpp>

#include <array>
#include <cmath>

#include "core.h"
#include "measures.h"
#include "scene_maker.h"
#include "scene_writer.h"
#include "scratch_folder.h"

namespace {

browser::SceneDescription load(const std::filesystem::path& file) {
    return browser::load_scene(file, engine::kBookWorld, browser::WorldKeys::with_knobs);
}

bool same(const browser::SceneDescription& a, const browser::SceneDescription& b) {
    return a.world == b.world && a.bodies == b.bodies;
}

std::size_t moving(const browser::SceneDescription& scene) {
    std::size_t count = 0;
    for (const auto& body : scene.bodies) count += body.mass > 0 ? 1 : 0;
    return count;
}

}  // namespace

TEST_CASE("scenes: bench/scenes/ holds exactly what `bench --write-scenes` makes") {
    for (const bench::scenes::NamedScene& named : bench::scenes::shipped()) {
        INFO(named.name);
        CHECK(same(load(std::filesystem::path(BENCH_SCENES_DIR) / (named.name + ".json")), named.scene));
    }
}

TEST_CASE("scene_json: every world key and body key reads back to the same value") {
    test::ScratchFolder folder("bench_scene_json");
    browser::SceneDescription scene = bench::scenes::pair(bench::scenes::PairKind::rect_circle);
    scene.world.substeps = 4;
    scene.world.integrator = browser::Integrator::explicit_euler;
    scene.world.broad_phase = browser::BroadPhase::all_pairs;
    scene.world.friction_model = browser::FrictionModel::coulomb;
    scene.world.rotation = false;
    scene.world.friction = false;
    scene.world.dt = 1.0 / 3;  // no short decimal form
    scene.bodies[1].angle = 0.1;
    scene.bodies[1].velocity = {1.0 / 7, -2};
    scene.bodies[1].angular_velocity = -3.5;
    bench::write_scene(folder.path / "scene.json", scene);
    CHECK(same(load(folder.path / "scene.json"), scene));
    CHECK(folder.files() == std::vector<std::string>{"scene.json"});  // no .partial left
}

TEST_CASE("scenes: the pyramids have rows (rows + 1) / 2 boxes, and no two shapes overlap at the start") {
    for (int rows : {10, 20}) {
        const browser::SceneDescription scene = bench::scenes::pyramid(rows);
        CHECK(moving(scene) == static_cast<std::size_t>(rows * (rows + 1) / 2));
        CHECK(bench::penetration(bench::engine_world(scene)->snapshot()).pairs == 0);
    }
}

TEST_CASE("scenes: the rains hold the shapes asked for in an open box, none overlapping at the start") {
    for (int shapes : {100, 400}) {
        const browser::SceneDescription scene = bench::scenes::rain(shapes);
        CHECK(moving(scene) == static_cast<std::size_t>(shapes));
        CHECK(scene.bodies.size() == static_cast<std::size_t>(shapes) + 3);  // floor and two walls
        CHECK(bench::penetration(bench::engine_world(scene)->snapshot()).pairs == 0);
    }
}

TEST_CASE("scenes: the gas is 60 discs at 150 px/s, elastic and frictionless, in a closed box without gravity") {
    const browser::SceneDescription scene = bench::scenes::gas();
    CHECK(scene.world.gravity == browser::Vec2{0, 0});
    CHECK(scene.bodies.size() == 64);
    for (const auto& body : scene.bodies) {
        CHECK(body.restitution == 1.0);
        CHECK(body.friction == 0.0);
        if (body.mass > 0) CHECK(body.velocity.length() == Approx(150.0));
    }
    CHECK(bench::penetration(bench::engine_world(scene)->snapshot()).pairs == 0);
}

TEST_CASE("scenes: the slope's disc touches the slope, and the wall's ball starts 1 px from the wall") {
    const bench::Snapshot slope = bench::engine_world(bench::scenes::slope())->snapshot();
    CHECK(oracle::depth(slope[0].shape, slope[1].shape) == Approx(0.0).margin(1e-9));
    const bench::Snapshot wall = bench::engine_world(bench::scenes::thin_wall())->snapshot();
    CHECK(oracle::depth(wall[0].shape, wall[1].shape) == Approx(-1.0));
}

TEST_CASE("scenes: the scale scenes keep their density as they grow") {
    // sqrt(n) rounded up columns of 20 px, 20 px in from the canvas's edges: 50 shapes on
    // 8 x 8 cells, 2000 on 45 x 45.
    for (const auto& [shapes, columns] : std::vector<std::array<int, 2>>{{50, 8}, {2000, 45}}) {
        const browser::SceneDescription scene = bench::scenes::scale(shapes);
        CHECK(moving(scene) == static_cast<std::size_t>(shapes));
        CHECK(scene.bodies.size() == static_cast<std::size_t>(shapes));
        CHECK(scene.world.width == columns * 20 + 40);
        CHECK(scene.world.width <= 4096);
    }
}
