// Stage 4.1: shapes move under gravity, but collisions are only found, not answered;
// the book's scene is static.
#include <catch2/catch.hpp>

#include "book_scene.h"
#include "circle.h"
#include "my_game.h"
#include "world_fixture.h"

using engine::Vec2;

TEST_CASE("s4_1: the cursor and the borders are static and stay put with movement on") {
    test::WorldFixture page(test::world(true));
    test::buildBookScene(page.core, page.random);
    REQUIRE(page.core.objectCount() == engine::UserControl::kKeptOnReset);
    std::vector<Vec2> before;
    for (std::size_t i = 0; i < page.core.objectCount(); ++i) before.push_back(page.core.object(i).center());
    page.steps(60);
    for (std::size_t i = 0; i < page.core.objectCount(); ++i) {
        CHECK(page.core.object(i).isStatic());
        CHECK(page.core.object(i).center() == before[i]);
    }
}

TEST_CASE("s4_1: colliding shapes are reported and pass through each other untouched") {
    test::WorldFixture page(test::world(true, {0, 0}));
    const test::ApproachingCircles pair(page);
    engine::Circle& left = pair.left;
    engine::Circle& right = pair.right;
    bool reported = false;
    for (int step = 0; step < 30; ++step) {  // 0.5 s: they meet after 1/12 s and cross
        page.steps(1);
        reported = reported || !page.core.physics().collisions().empty();
    }
    CHECK(reported);
    CHECK(left.velocity() == Vec2{60, 0});
    CHECK(right.velocity() == Vec2{-60, 0});
    CHECK(left.center().x == Approx(130));
    CHECK(right.center().x == Approx(100));
}
