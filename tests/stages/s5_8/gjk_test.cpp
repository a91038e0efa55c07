// GJK's distance and closest points (gjk.h) against brute force on random pairs, and
// the cases where distance codes fail: Box2D's test_distance.c at 30 px to the metre
// (the bench's scale, where Box2D's 0.005 m linear slop is our 0.15 px slop), kissing
// and exactly touching shapes, and simplices that lie flat.

#include <catch2/catch.hpp>

#include <vector>

#include "gjk.h"
#include "near.h"
#include "random_convex.h"

namespace gjk_test {

using engine::ConvexProxy;
using engine::gjkDistance;
using engine::makeProxy;
using engine::Vec2;

constexpr double kPxPerMetre = 30.0;
constexpr double kLinearSlopPx = 0.005 * kPxPerMetre;  // Box2D's B2_LINEAR_SLOP, 0.15 px

// How near the reported closest points lie to their shapes' rounded outlines.
double offOutline(Vec2 p, const test::RandomShape& shape) {
    return std::abs(test::pointShapeDistance(p, shape.points) - shape.radius);
}

TEST_CASE("gjk: 10,000 random pairs, distance within 1e-9 px of brute force, closest points on the shapes",
          "[polygons]") {
    browser::Random random(2010);  // the year of Catto's talk
    int apart = 0;
    for (int trial = 0; trial < 10000; ++trial) {
        test::RandomShape shapes[2];
        for (auto& shape : shapes) {
            const std::size_t count = 1 + static_cast<std::size_t>(random.next() * 8);
            const Vec2 center{100 * random.next(), 100 * random.next()};
            shape.points = test::randomConvex(random, count, center, 5 + 60 * random.next());
            // A quarter are rounded (a point with a radius is a circle).
            shape.radius = random.next() < 0.25 || count == 1 ? 20 * random.next() : 0.0;
        }
        const ConvexProxy a = makeProxy(shapes[0].points, shapes[0].radius);
        const ConvexProxy b = makeProxy(shapes[1].points, shapes[1].radius);
        const auto result = gjkDistance(a, b);
        const double cores = test::bruteForceDistance(shapes[0].points, shapes[1].points);
        const double expected = std::max(0.0, cores - shapes[0].radius - shapes[1].radius);
        INFO("trial " << trial);
        REQUIRE_THAT(result.distance, test::near(expected, 1e-9));
        if (expected > 1e-9) {
            ++apart;
            REQUIRE_THAT(result.point_b.distance(result.point_a), test::near(result.distance, 1e-9));
            REQUIRE(offOutline(result.point_a, shapes[0]) <= 1e-9);
            REQUIRE(offOutline(result.point_b, shapes[1]) <= 1e-9);
            REQUIRE_THAT(result.normal, test::near((result.point_b - result.point_a).normalize(), 1e-9));
        }
    }
    // Both kinds were tried: a sweep of only overlaps would prove little.
    CHECK(apart > 3000);
    CHECK(apart < 7000);
}

TEST_CASE("gjk: Box2D's square against a segment, at 30 px to the metre", "[polygons]") {
    // A 2 m square round the origin and a segment 1 m beyond its right side.
    const std::vector<Vec2> square{{-30, -30}, {30, -30}, {30, 30}, {-30, 30}};
    const std::vector<Vec2> segment{{60, -30}, {60, 30}};
    const auto result = gjkDistance(makeProxy(square), makeProxy(segment));
    CHECK_THAT(result.distance, test::near(30.0, 1e-12));
    CHECK_THAT(result.normal, test::near(Vec2{1, 0}, 1e-15));
    CHECK_THAT(result.point_a.x, test::near(30.0, 1e-12));
    CHECK_THAT(result.point_b.x, test::near(60.0, 1e-12));
}

TEST_CASE("gjk: Box2D's thin plank against a point one slop off its end (the short-edge case)", "[polygons]") {
    // A plank 1 m long and 3.2 mm thick, a point a linear slop off the middle of its
    // short end. The nearest feature is the 0.096 px end face. Box2D's absolute test on a
    // search direction of size 2 d e^2 calls it an overlap below an edge of 3.5 mm;
    // a test relative to the shapes' size does not.
    for (const double half_thickness : {0.0016, 0.0002, 1e-6}) {
        const double t = half_thickness * kPxPerMetre;
        const std::vector<Vec2> plank{{-15, -t}, {15, -t}, {15, t}, {-15, t}};
        const std::vector<Vec2> point{{15 + kLinearSlopPx, 0}};
        const auto result = gjkDistance(makeProxy(plank), makeProxy(point));
        INFO("half thickness " << t << " px");
        CHECK_THAT(result.distance, test::near(kLinearSlopPx, 1e-12));
        CHECK_THAT(result.normal, test::near(Vec2{1, 0}, 1e-15));
    }
}

TEST_CASE("gjk: kissing contact, exactly touching, and just apart", "[polygons]") {
    const std::vector<Vec2> box{{0, 0}, {10, 0}, {10, 10}, {0, 10}};
    SECTION("face on face: touching is distance 0, a gap of 1e-9 px is 1e-9 px") {
        const std::vector<Vec2> touching{{10, 2}, {20, 2}, {20, 8}, {10, 8}};
        CHECK(gjkDistance(makeProxy(box), makeProxy(touching)).distance == 0.0);
        const std::vector<Vec2> apart{{10 + 1e-9, 2}, {20, 2}, {20, 8}, {10 + 1e-9, 8}};
        CHECK_THAT(gjkDistance(makeProxy(box), makeProxy(apart)).distance, test::near(1e-9, 1e-15));
    }
    SECTION("corner on corner, corner on face") {
        const std::vector<Vec2> corner_touch{{10, 10}, {20, 10}, {20, 20}, {10, 20}};
        CHECK(gjkDistance(makeProxy(box), makeProxy(corner_touch)).distance == 0.0);
        // A diamond whose left corner, (10, 5), lies on the box's right side.
        const std::vector<Vec2> diamond{{15, 0}, {20, 5}, {15, 10}, {10, 5}};
        CHECK(gjkDistance(makeProxy(box), makeProxy(diamond)).distance == 0.0);
        const std::vector<Vec2> diamond_apart{{15.5, 0}, {20.5, 5}, {15.5, 10}, {10.5, 5}};
        CHECK_THAT(gjkDistance(makeProxy(box), makeProxy(diamond_apart)).distance, test::near(0.5, 1e-14));
    }
    SECTION("a circle resting on a box: distance 0; lifted 1e-9 px: 1e-9 px") {
        const std::vector<Vec2> center{{5, -4}};
        CHECK(gjkDistance(makeProxy(box), makeProxy(center, 4.0)).distance == 0.0);
        const std::vector<Vec2> lifted{{5, -4 - 1e-9}};
        const auto result = gjkDistance(makeProxy(box), makeProxy(lifted, 4.0));
        CHECK_THAT(result.distance, test::near(1e-9, 1e-14));
        CHECK_THAT(result.point_b, test::near(Vec2{5, -1e-9}, 1e-14));
        CHECK_THAT(result.normal, test::near(Vec2{0, -1}, 1e-15));
    }
    SECTION("two circles: |c1 - c2| - r1 - r2") {
        const std::vector<Vec2> c1{{0, 0}};
        const std::vector<Vec2> c2{{30, 40}};
        CHECK_THAT(gjkDistance(makeProxy(c1, 10), makeProxy(c2, 15)).distance, test::near(25.0, 1e-13));
        CHECK(gjkDistance(makeProxy(c1, 20), makeProxy(c2, 30)).distance == 0.0);
    }
}

TEST_CASE("gjk: simplices that lie flat: a point inside an edge, collinear support points", "[polygons]") {
    const std::vector<Vec2> box{{0, 0}, {10, 0}, {10, 10}, {0, 10}};
    SECTION("a point inside an edge: touching, distance 0, no NaN") {
        const std::vector<Vec2> on_edge{{10, 4}};
        const auto result = gjkDistance(makeProxy(box), makeProxy(on_edge));
        CHECK(result.distance == 0.0);
        CHECK(std::isfinite(result.point_a.x));
        CHECK(std::isfinite(result.point_a.y));
    }
    SECTION("a point on an edge's line, beyond its end: the corner is nearest") {
        const std::vector<Vec2> beyond{{10, 13}};
        const auto result = gjkDistance(makeProxy(box), makeProxy(beyond));
        CHECK_THAT(result.distance, test::near(3.0, 1e-13));
        CHECK_THAT(result.point_a, test::near(Vec2{10, 10}, 1e-13));
    }
    SECTION("three collinear points as the starting simplex (a cache that lies flat)") {
        // A is three points on one line (a segment with a point in its middle); the cache
        // starts GJK on all three against B's only point: a triangle with no inside.
        const std::vector<Vec2> line{{0, 0}, {5, 0}, {10, 0}};
        const std::vector<Vec2> point{{4, 5}};
        engine::SimplexCache flat;
        flat.count = 3;
        flat.index_a = {0, 1, 2};
        flat.index_b = {0, 0, 0};
        const auto result = gjkDistance(makeProxy(line), makeProxy(point), flat);
        CHECK_THAT(result.distance, test::near(5.0, 1e-13));
        CHECK_THAT(result.point_a, test::near(Vec2{4, 0}, 1e-13));
    }
    SECTION("segments crossing at a point, and lying on one line") {
        const std::vector<Vec2> s1{{0, 0}, {10, 10}};
        const std::vector<Vec2> s2{{0, 10}, {10, 0}};
        CHECK(gjkDistance(makeProxy(s1), makeProxy(s2)).distance == 0.0);
        const std::vector<Vec2> s3{{12, 12}, {20, 20}};
        CHECK_THAT(gjkDistance(makeProxy(s1), makeProxy(s3)).distance, test::near(std::sqrt(8.0), 1e-13));
        const std::vector<Vec2> s4{{5, 5}, {20, 20}};
        CHECK(gjkDistance(makeProxy(s1), makeProxy(s4)).distance == 0.0);
    }
}

TEST_CASE("gjk: started from the last call's simplex, the same answer in fewer queries", "[polygons]") {
    browser::Random random(7);
    const auto hexagon = test::randomConvex(random, 6, Vec2{0, 0}, 30);
    const auto octagon = test::randomConvex(random, 8, Vec2{90, 10}, 30);
    const ConvexProxy a = makeProxy(hexagon);
    engine::SimplexCache cache;
    int cold = 0;
    int warm = 0;
    for (int step = 0; step < 60; ++step) {
        // B slides past A, 0.5 px a step, as a body moves between two steps.
        std::vector<Vec2> moved;
        for (Vec2 p : octagon) moved.push_back(p + Vec2{0, -15 + 0.5 * step});
        const ConvexProxy b = makeProxy(moved);
        const auto fresh = gjkDistance(a, b);
        const auto cached = gjkDistance(a, b, cache);
        cache = cached.cache;
        CHECK_THAT(cached.distance, test::near(fresh.distance, 1e-12));
        cold += fresh.iterations;
        warm += cached.iterations;
    }
    CHECK(warm < cold);
}

}  // namespace gjk_test
