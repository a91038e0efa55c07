// EPA's depth and normal (epa.h) against SAT's on random overlapping polygons, and on
// the starts that break EPA elsewhere: the origin on a side of GJK's last simplex,
// collinear support points, shapes that only touch.

#include <catch2/catch.hpp>

#include <vector>

#include "convex_hull.h"
#include "epa.h"
#include "near.h"
#include "polygon_sat.h"
#include "random_convex.h"

namespace epa_test {

using engine::epaPenetration;
using engine::makeProxy;
using engine::Vec2;

// The tolerance EPA's depth is held to: epa.h's stop is 1e-12 of the shapes' size,
// about 1e-10 px for these, so 1e-9 px leaves room for the round-off of the sums.
constexpr double kDepthTolerance = 1e-9;
// Its normal, each coordinate: where two faces are as deep as each other to within
// round-off, either normal is right, and the test then asks that EPA's be as deep.
constexpr double kNormalTolerance = 1e-9;

TEST_CASE("epa: 10,000 random overlapping polygon pairs, depth within 1e-9 px of SAT's, and the same normal",
          "[polygons]") {
    browser::Random random(395);  // fcl's issue number, for the degenerate start
    int pairs = 0;
    int ties = 0;
    while (pairs < 10000) {
        const std::vector<Vec2> shapes[2]{test::randomPolygon(random, 60, 60), test::randomPolygon(random, 60, 60)};
        const auto a = engine::makeConvexPolygon(shapes[0]);
        const auto b = engine::makeConvexPolygon(shapes[1]);
        const auto sat = engine::satCollision(a, b);
        if (!sat) continue;
        ++pairs;
        const auto exact = test::exactPenetration(shapes[0], shapes[1]);
        const auto epa = epaPenetration(makeProxy(shapes[0]), makeProxy(shapes[1]));
        INFO("pair " << pairs);
        REQUIRE(epa);
        REQUIRE(epa->converged);
        // SAT's own answer is the exact one (worked out again by random_convex.h).
        REQUIRE_THAT(sat->depth, test::near(exact.depth, 1e-12));
        REQUIRE_THAT(epa->depth, test::near(sat->depth, kDepthTolerance));
        const bool same_normal = std::abs(epa->normal.x - sat->normal.x) <= kNormalTolerance &&
                                 std::abs(epa->normal.y - sat->normal.y) <= kNormalTolerance;
        if (!same_normal) {
            // A tie: EPA's normal must part the shapes by the same depth as SAT's.
            ++ties;
            double deepest_a = -INFINITY;
            double deepest_b = INFINITY;
            for (Vec2 p : shapes[0]) deepest_a = std::max(deepest_a, p.dot(epa->normal));
            for (Vec2 p : shapes[1]) deepest_b = std::min(deepest_b, p.dot(epa->normal));
            REQUIRE_THAT(deepest_a - deepest_b, test::near(sat->depth, kDepthTolerance));
        }
        // The witnesses: B's point moved by the depth along the normal is A's.
        REQUIRE_THAT(epa->point_b + epa->normal * epa->depth, test::near(epa->point_a, 1e-9));
    }
    CHECK(ties < 10);
}

// Two equal w x w squares, B moved by `offset` from A: the depth is known by hand.
std::vector<Vec2> square(double w, Vec2 offset) {
    std::vector<Vec2> corners{{0, 0}, {w, 0}, {w, w}, {0, w}};
    for (Vec2& p : corners) p = p + offset;
    return corners;
}
std::optional<engine::EpaPenetration> squares(double w, Vec2 offset) {
    return epaPenetration(makeProxy(square(w, Vec2{})), makeProxy(square(w, offset)));
}
// The simplex GJK ends on, which EPA starts from: fewer than 3 points is a degenerate start.
std::size_t gjkEnd(double w, Vec2 offset) {
    return engine::gjkDistance(makeProxy(square(w, Vec2{})), makeProxy(square(w, offset))).simplex.count;
}

TEST_CASE("epa: degenerate starts: the origin on a side, collinear support points, shapes that only touch",
          "[polygons]") {
    SECTION("squares slid along an axis: depth w - |dx|, normal along the axis") {
        // Symmetric pairs: GJK's support points lie on a line through the origin, and it
        // ends on a segment with the origin on it, which EPA must make a triangle.
        for (double dx : {-9.0, -5.0, -1.0, 0.5, 3.0, 7.5}) {
            CHECK(gjkEnd(10, Vec2{dx, 0}) == 2);
            const auto p = squares(10, Vec2{dx, 0});
            REQUIRE(p);
            CHECK(p->converged);
            CHECK_THAT(p->depth, test::near(10 - std::abs(dx), 1e-12));
            CHECK_THAT(p->normal, test::near(Vec2{dx > 0 ? 1.0 : -1.0, 0}, 1e-15));
        }
    }
    SECTION("one square on the other: depth w along an axis (GJK ends on one point, the origin)") {
        CHECK(gjkEnd(10, Vec2{0, 0}) == 1);
        const auto p = squares(10, Vec2{0, 0});
        REQUIRE(p);
        CHECK_THAT(p->depth, test::near(10.0, 1e-12));
        CHECK_THAT(std::abs(p->normal.x) + std::abs(p->normal.y), test::near(1.0, 1e-15));
    }
    SECTION("slid along the diagonal: depth w - d along either axis") {
        CHECK(gjkEnd(10, Vec2{4, 4}) == 2);
        const auto p = squares(10, Vec2{4, 4});
        REQUIRE(p);
        CHECK_THAT(p->depth, test::near(6.0, 1e-12));
        CHECK_THAT(std::abs(p->normal.x) + std::abs(p->normal.y), test::near(1.0, 1e-15));
    }
    SECTION("touching face to face, corner to corner: depth 0 (GJK and EPA agree at a kissing contact)") {
        const auto face = squares(10, Vec2{10, 3});
        REQUIRE(face);
        CHECK(face->depth == 0.0);
        CHECK_THAT(face->normal, test::near(Vec2{1, 0}, 1e-15));
        const auto corner = squares(10, Vec2{10, 10});
        REQUIRE(corner);
        CHECK(corner->depth == 0.0);
        CHECK_FALSE(squares(10, Vec2{10 + 1e-9, 3}));
        const auto barely = squares(10, Vec2{10 - 1e-9, 3});
        REQUIRE(barely);
        CHECK_THAT(barely->depth, test::near(1e-9, 1e-14));
    }
    SECTION("A - B with no area (a point on a segment): depth 0, not converged, no NaN") {
        const std::vector<Vec2> segment{{0, 0}, {10, 0}};
        const std::vector<Vec2> point{{4, 0}};
        const auto p = epaPenetration(makeProxy(segment), makeProxy(point));
        REQUIRE(p);
        CHECK(p->depth == 0.0);
        CHECK_FALSE(p->converged);
        CHECK(std::isfinite(p->point_a.x));
    }
    SECTION("a triangle's corner through a box's side: depth and normal by hand") {
        const std::vector<Vec2> box{{0, 0}, {20, 0}, {20, 10}, {0, 10}};
        // The triangle's lowest corner 2 px into the box's top side (y = 0, y grows down).
        const std::vector<Vec2> triangle{{5, -10}, {10, 2}, {0, -8}};
        const auto hull = engine::convexHull(triangle).hull;
        REQUIRE(hull);
        const auto p = epaPenetration(makeProxy(box), makeProxy(hull->corners()));
        REQUIRE(p);
        CHECK_THAT(p->depth, test::near(2.0, 1e-12));
        CHECK_THAT(p->normal, test::near(Vec2{0, -1}, 1e-15));
        CHECK_THAT(p->point_b, test::near(Vec2{10, 2}, 1e-12));
    }
}

}  // namespace epa_test
