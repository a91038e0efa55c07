// The error measures against overlaps and energies worked out by hand.
#include <catch2/catch.hpp>

#include <cmath>

#include "measures.h"
#include "stages.h"

namespace {

using bench::BodyState;
using lib::Vec2;

BodyState box(Vec2 center, double width, double height, bool fixed = false, double angle = 0.0) {
    return {.shape = oracle::Box{center, width, height, angle}, .is_static = fixed, .mass = fixed ? 0.0 : 1.0};
}
BodyState disc(Vec2 center, double radius, bool fixed = false) {
    return {.shape = oracle::Disc{center, radius}, .is_static = fixed, .mass = fixed ? 0.0 : 1.0};
}

bench::BodyDescription body_box(Vec2 center, double width, double height, double mass, double angle = 0.0) {
    return {.shape = bench::Shape::rectangle,
            .center = center,
            .width = width,
            .height = height,
            .mass = mass,
            .angle = angle};
}

}  // namespace

TEST_CASE("penetration: two overlapping boxes overlap by the smaller of the two shadows' overlaps") {
    // A spans x 80..120, y 90..110; B spans x 110..150, y 95..115: 10 px in x, 15 px in y.
    // The shortest way apart is 10 px along x.
    const bench::Penetration found = bench::penetration({box({100, 100}, 40, 20), box({130, 105}, 40, 20)});
    CHECK(found.pairs == 1);
    CHECK(found.max == Approx(10.0));
    CHECK(found.mean == Approx(10.0));
}

TEST_CASE("penetration: the deepest pair and the mean over the overlapping pairs") {
    // The disc's centre is 8 px below the box's bottom side (y 110): 10 - 8 = 2 px deep.
    // The last box is far from everything and adds no pair.
    const bench::Penetration found = bench::penetration(
        {box({100, 100}, 40, 20), box({130, 105}, 40, 20), disc({100, 118}, 10), box({500, 500}, 10, 10)});
    CHECK(found.pairs == 2);
    CHECK(found.max == Approx(10.0));
    CHECK(found.mean == Approx((10.0 + 2.0) / 2));
}

TEST_CASE("penetration: touching is not overlapping, and two static bodies do not count") {
    CHECK(bench::penetration({disc({0, 0}, 5), disc({10, 0}, 5)}).pairs == 0);
    const bench::Penetration walls = bench::penetration({box({0, 0}, 20, 20, true), box({10, 0}, 20, 20, true)});
    CHECK(walls.pairs == 0);
    CHECK(walls.max == 0.0);
    CHECK(walls.mean == 0.0);
}

TEST_CASE("penetration: every stage's shapes seen through the snapshot, a box turned on its corner") {
    // A 20 px square turned by 45 degrees stands on its corner, which is half a diagonal,
    // 10 sqrt(2) px, below its centre at y = 100: at 114.14, 4.14 px into a floor whose top
    // is at y = 110. Along the square's own sides the floor is far wider, so the corner
    // is the shortest way out.
    bench::SceneDescription scene{.world = bench::book_world()};
    scene.world.movement = false;
    scene.bodies = {body_box({100, 120}, 200, 20, 0.0), body_box({100, 100}, 20, 20, 1.0, std::acos(-1.0) / 4)};
    for (bench::Stage stage : bench::kChapter5Stages) {
        INFO("stage " << bench::stage_name(stage));
        const bench::Penetration found = bench::penetration(bench::stage_world(stage, scene)->snapshot());
        CHECK(found.pairs == 1);
        CHECK(found.max == Approx(10 * std::sqrt(2.0) - 10));
    }
}

TEST_CASE("kinetic_energy: 1/2 m v^2 + 1/2 I w^2, with a box's I = m (w^2 + h^2) / 12") {
    // Mass 2 at (3, 4) px/s: 1/2 2 25 = 25. I = 2 (900 + 1600) / 12 = 416.67, spinning
    // at 2 rad/s: 1/2 416.67 4 = 833.33. A static body adds nothing.
    bench::SceneDescription scene{.world = bench::book_world()};
    scene.bodies = {body_box({100, 100}, 30, 40, 2.0), body_box({300, 300}, 10, 10, 0.0)};
    scene.bodies[0].velocity = {3, 4};
    scene.bodies[0].angular_velocity = 2;
    const bench::Snapshot bodies = bench::stage_world(bench::Stage::s5_1, scene)->snapshot();
    CHECK(bench::kinetic_energy(bodies) == Approx(25.0 + 2500.0 / 3));
}

TEST_CASE("top_body: the moving body highest on the screen") {
    CHECK(bench::top_body({box({0, 50}, 10, 10, true), box({0, 80}, 10, 10), disc({0, 60}, 5), box({0, 90}, 10, 10)}) ==
          2);
    CHECK_THROWS_AS(bench::top_body({box({0, 50}, 10, 10, true)}), std::invalid_argument);
}
