// The piles of the study of 5.5's sleeping (bench/sleep_piles.h): what a recipe makes, and
// the copy of issue 35's pile that stage 5.5 keeps for its tests.
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "scene_json.h"
#include "sleep_piles.h"

namespace sleep_piles_test {

using bench::piles::Kinds;
using bench::piles::PileRecipe;

TEST_CASE("sleep piles: across x layers shapes of the recipe's kinds and sizes, inside the box, none overlapping") {
    for (const Kinds kinds : {Kinds::circles, Kinds::squares, Kinds::mixed}) {
        const PileRecipe recipe{.smallest = 4.0, .largest = 40.0, .layers = 3, .kinds = kinds};
        const bench::SceneDescription scene = bench::piles::pile(recipe);
        INFO(bench::piles::describe(recipe));
        REQUIRE(scene.bodies.size() == 3 + 120u);  // a floor, two walls, 40 x 3 shapes
        // The floor is 40 mean sizes (22 px) wide inside the walls: 880 px.
        CHECK(scene.bodies[0].width == 40.0 * 22.0 + 2 * 20.0);
        int circles = 0;
        for (std::size_t i = 3; i < scene.bodies.size(); ++i) {
            const bench::BodyDescription& body = scene.bodies[i];
            const double size = body.shape == bench::Shape::circle ? 2 * body.radius : body.width;
            CHECK(size >= 4.0);
            CHECK(size <= 40.0);
            CHECK(body.friction == 0.5);
            CHECK(body.restitution == 0.2);
            circles += body.shape == bench::Shape::circle ? 1 : 0;
            // Each in its own lattice cell of 1.45 x 40 px (circles: 40 + 2): their
            // bounding circles, at most 40 / sqrt(2) = 28.3 px across a square, are apart.
            const double reach = body.shape == bench::Shape::circle ? body.radius : size / std::sqrt(2.0);
            CHECK(body.center.x - reach > 40.0);
            CHECK(body.center.x + reach < scene.world.width - 40.0);
            CHECK(body.center.y + reach < scene.world.height - 40.0);
            for (std::size_t j = 3; j < i; ++j) {
                const bench::BodyDescription& other = scene.bodies[j];
                const double other_reach =
                    other.shape == bench::Shape::circle ? other.radius : other.width / std::sqrt(2.0);
                CHECK(body.center.distance(other.center) > reach + other_reach);
            }
        }
        if (kinds == Kinds::circles) CHECK(circles == 120);
        if (kinds == Kinds::squares) CHECK(circles == 0);
        if (kinds == Kinds::mixed) CHECK((circles > 40 && circles < 80));
    }
}

TEST_CASE("sleep piles: stage 5.5's pile.json is issue 35's pile, as `sleep_sweep --write-pile` writes it") {
    const std::filesystem::path file =
        std::filesystem::path(BENCH_SCENES_DIR) / ".." / ".." / "ch5_demo" / "5.5_sleeping" / "pile.json";
    std::ifstream in(file);
    REQUIRE(in);
    std::ostringstream text;
    text << in.rdbuf();
    CHECK(text.str() == bench::scene_json(bench::piles::issuePile()));
    CHECK(bench::piles::issuePile().bodies.size() == 403u);
}

}  // namespace sleep_piles_test
