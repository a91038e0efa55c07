// The book's SAT and 5.4's clipping for n-gons (polygon_sat.h), on pairs whose depth,
// normal and contact points are worked out by hand.

#include <catch2/catch.hpp>

#include <numbers>
#include <vector>

#include "convex_hull.h"
#include "near.h"
#include "polygon_sat.h"
#include "random_convex.h"

namespace sat_test {

using engine::ConvexPolygon;
using engine::Vec2;

ConvexPolygon polygon(const std::vector<Vec2>& points) {
    const auto result = engine::convexHull(points);
    REQUIRE(result.hull);
    return *result.hull;
}

ConvexPolygon box(Vec2 min, Vec2 max) { return polygon({min, {max.x, min.y}, max, {min.x, max.y}}); }

// A regular n-gon round `center`, a corner straight down (largest y) when `point_down`.
ConvexPolygon regular(int n, Vec2 center, double radius, double first_angle) {
    std::vector<Vec2> corners;
    for (int i = 0; i < n; ++i) {
        const double angle = first_angle + 2 * std::numbers::pi * i / n;
        corners.push_back(center + Vec2{radius * std::cos(angle), radius * std::sin(angle)});
    }
    return polygon(corners);
}

// The floor the pieces rest on: 200 px wide, its top face at y = 100.
ConvexPolygon theFloor() { return box({0, 100}, {200, 120}); }

TEST_CASE("polygon sat: apart, touching and overlapping boxes, as the book's rectangles", "[polygons]") {
    CHECK_FALSE(engine::satCollision(theFloor(), box({50, 80}, {70, 99})));
    // Touching is not colliding (a corner exactly on the face is not behind it).
    CHECK_FALSE(engine::satCollision(theFloor(), box({50, 80}, {70, 100})));
    const auto hit = engine::satCollision(theFloor(), box({50, 80}, {70, 100.5}));
    REQUIRE(hit);
    CHECK_THAT(hit->depth, test::near(0.5, 1e-13));
    // From the floor (A) up to the box (B): -y on the canvas.
    CHECK_THAT(hit->normal, test::near(Vec2{0, -1}, 1e-15));
}

TEST_CASE("polygon sat: a box resting flat gives two contact points at its bottom corners", "[polygons]") {
    // A 20 x 20 box sunk 0.5 px into the floor: its two bottom corners, each halfway
    // between the outlines (0.25 px below the floor's top), 0.5 px deep.
    const auto b = box({50, 80.5}, {70, 100.5});
    const auto hit = engine::satCollision(theFloor(), b);
    REQUIRE(hit);
    const auto manifold = engine::polygonManifold(theFloor(), b, *hit);
    REQUIRE(manifold.count == 2);
    std::vector<Vec2> at{manifold.points[0].position, manifold.points[1].position};
    std::sort(at.begin(), at.end(), [](Vec2 p, Vec2 q) { return p.x < q.x; });
    CHECK_THAT(at[0], test::near(Vec2{50, 100.25}, 1e-12));
    CHECK_THAT(at[1], test::near(Vec2{70, 100.25}, 1e-12));
    CHECK_THAT(manifold.points[0].depth, test::near(0.5, 1e-12));
    CHECK_THAT(manifold.points[1].depth, test::near(0.5, 1e-12));
}

TEST_CASE("polygon sat: a hexagon on a corner gives one point; on a side, two, clipped to the floor's face",
          "[polygons]") {
    SECTION("corner down: one point, the corner's depth") {
        // Radius 20, a corner straight down at y = 101: 1 px into the floor.
        const auto hexagon = regular(6, Vec2{100, 81}, 20, std::numbers::pi / 2);
        const auto hit = engine::satCollision(theFloor(), hexagon);
        REQUIRE(hit);
        CHECK_THAT(hit->depth, test::near(1.0, 1e-12));
        CHECK_THAT(hit->normal, test::near(Vec2{0, -1}, 1e-15));
        const auto manifold = engine::polygonManifold(theFloor(), hexagon, *hit);
        REQUIRE(manifold.count == 1);
        CHECK_THAT(manifold.points[0].position, test::near(Vec2{100, 100.5}, 1e-12));
        CHECK_THAT(manifold.points[0].depth, test::near(1.0, 1e-12));
    }
    SECTION("side down, hanging over the floor's end: the point past the end is cut back onto it") {
        // A side down at y = 100.4, from x = 190 to 210 (radius 20, side 20): the floor
        // ends at x = 200, so clipping keeps (190, ...) and cuts the other end at 200.
        const double apothem = 20 * std::cos(std::numbers::pi / 6);
        const auto hexagon = regular(6, Vec2{200, 100.4 - apothem}, 20, 0.0);
        const auto hit = engine::satCollision(theFloor(), hexagon);
        REQUIRE(hit);
        CHECK_THAT(hit->depth, test::near(0.4, 1e-12));
        const auto manifold = engine::polygonManifold(theFloor(), hexagon, *hit);
        REQUIRE(manifold.count == 2);
        std::vector<Vec2> at{manifold.points[0].position, manifold.points[1].position};
        std::sort(at.begin(), at.end(), [](Vec2 p, Vec2 q) { return p.x < q.x; });
        CHECK_THAT(at[0], test::near(Vec2{190, 100.2}, 1e-12));
        CHECK_THAT(at[1], test::near(Vec2{200, 100.2}, 1e-12));
        // The floor's top face and the hexagon's bottom face are equally deep (0.4 px
        // each), so either may be the reference; either way one end is cut at a side line.
        const auto featureOf = [](const engine::PolygonContact& point) { return point.key & 0xFu; };
        const auto cut = [&](std::uint32_t feature) {
            return feature == engine::kClippedAtStart || feature == engine::kClippedAtEnd;
        };
        CHECK((cut(featureOf(manifold.points[0])) || cut(featureOf(manifold.points[1]))));
    }
}

TEST_CASE("polygon sat: B's face is the reference when it is the shallower, and the normal still points A to B",
          "[polygons]") {
    // A triangle (A) pokes its corner 1 px up into a box (B) above it: the box's bottom
    // face is the axis, the normal from A towards B is -y.
    const auto triangle = polygon({{90, 130}, {110, 130}, {100, 99}});
    const auto above = box({60, 60}, {140, 100});
    const auto hit = engine::satCollision(triangle, above);
    REQUIRE(hit);
    CHECK(hit->reference_is_b);
    CHECK_THAT(hit->depth, test::near(1.0, 1e-12));
    CHECK_THAT(hit->normal, test::near(Vec2{0, -1}, 1e-15));
    const auto manifold = engine::polygonManifold(triangle, above, *hit);
    REQUIRE(manifold.count == 1);
    CHECK_THAT(manifold.points[0].position, test::near(Vec2{100, 99.5}, 1e-12));
}

TEST_CASE("polygon sat: random pairs, SAT's depth is the exact one and the contact points lie in both shapes",
          "[polygons]") {
    browser::Random random(3);
    int overlapping = 0;
    for (int trial = 0; trial < 2000; ++trial) {
        const std::vector<Vec2> shapes[2]{test::randomPolygon(random, 80, 40), test::randomPolygon(random, 80, 40)};
        const auto a = engine::makeConvexPolygon(shapes[0]);
        const auto b = engine::makeConvexPolygon(shapes[1]);
        const auto hit = engine::satCollision(a, b);
        const bool apart = test::bruteForceDistance(shapes[0], shapes[1]) > 0.0;
        REQUIRE(apart == !hit);
        if (!hit) continue;
        ++overlapping;
        REQUIRE_THAT(hit->depth, test::near(test::exactPenetration(shapes[0], shapes[1]).depth, 1e-12));
        const auto manifold = engine::polygonManifold(a, b, *hit);
        // Each point is an incident corner or a clipped end, moved halfway to the reference
        // face: within half its depth of the incident shape, and no deeper than the pair.
        const auto& incident = hit->reference_is_b ? shapes[0] : shapes[1];
        for (std::size_t i = 0; i < manifold.count; ++i) {
            const auto& point = manifold.points[i];
            REQUIRE(test::pointShapeDistance(point.position, incident) <= point.depth / 2 + 1e-9);
            REQUIRE(point.depth >= 0.0);
            REQUIRE(point.depth <= hit->depth + 1e-9);
        }
    }
    CHECK(overlapping > 400);
}

}  // namespace sat_test
