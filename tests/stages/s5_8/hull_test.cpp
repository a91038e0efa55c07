// The hull builder (convex_hull.h): the corners it keeps and their order, and each of its
// refusals, one line each.

#include <catch2/catch.hpp>

#include <algorithm>
#include <string>
#include <vector>

#include "convex_hull.h"
#include "near.h"
#include "random_convex.h"

namespace hull_test {

using engine::convexHull;
using engine::Vec2;

// A 40 x 20 rectangle round (100, 50), in rectangle.h's numbering: top-left, top-right,
// bottom-right, bottom-left (y grows downwards), which is counter-clockwise in the sense
// of the cross product.
const std::vector<Vec2> kRectangle{{80, 40}, {120, 40}, {120, 60}, {80, 60}};

std::vector<Vec2> cornersOf(const engine::HullResult& result) {
    REQUIRE(result.hull);
    const auto corners = result.hull->corners();
    return {corners.begin(), corners.end()};
}

TEST_CASE("hull: a rectangle's corners come back in rectangle.h's order, from either winding", "[polygons]") {
    CHECK(cornersOf(convexHull(kRectangle)) == kRectangle);
    std::vector<Vec2> clockwise(kRectangle.rbegin(), kRectangle.rend());
    CHECK(cornersOf(convexHull(clockwise)) == kRectangle);
    std::vector<Vec2> shuffled{kRectangle[2], kRectangle[0], kRectangle[3], kRectangle[1]};
    CHECK(cornersOf(convexHull(shuffled)) == kRectangle);
}

TEST_CASE("hull: a point inside, a point on a side and a point nearly on one are dropped", "[polygons]") {
    std::vector<Vec2> points = kRectangle;
    points.push_back({100, 50});      // the centre
    points.push_back({100, 40});      // the middle of the top side
    points.push_back({120, 50.004});  // 0.004 px off the right side's line... inside it
    points.push_back({120.004, 55});  // ... and 0.004 px outside it: within the tolerance
    CHECK(cornersOf(convexHull(points)) == kRectangle);
    // 0.006 px outside the side is more than the 0.005 px tolerance: a corner.
    points.back() = Vec2{120.006, 55};
    const std::vector<Vec2> five{{80, 40}, {120, 40}, {120.006, 55}, {120, 60}, {80, 60}};
    CHECK(cornersOf(convexHull(points)) == five);
}

TEST_CASE("hull: the normals point out of each face, unit long", "[polygons]") {
    const auto hull = convexHull(kRectangle).hull;
    REQUIRE(hull);
    // Face 0 is the top side (y = 40): out is up, -y on the canvas; then right, down, left.
    const std::vector<Vec2> out{{0, -1}, {1, 0}, {0, 1}, {-1, 0}};
    for (std::size_t i = 0; i < 4; ++i) CHECK_THAT(hull->normals[i], test::near(out[i], 1e-15));
}

// Random points: the hull holds every one (on or inside it), each corner is one of them,
// and it turns counter-clockwise at every corner by more than the tolerance allows.
TEST_CASE("hull: 2,000 random point sets give convex counter-clockwise hulls holding every point", "[polygons]") {
    browser::Random random(38);
    for (int trial = 0; trial < 2000; ++trial) {
        const std::size_t count = 3 + static_cast<std::size_t>(random.next() * 6);
        std::vector<Vec2> points;
        for (std::size_t i = 0; i < count; ++i) points.push_back({200 * random.next(), 200 * random.next()});
        const auto result = convexHull(points);
        if (!result.hull) continue;  // two points within the tolerance, or nearly a line: rare
        const auto corners = result.hull->corners();
        REQUIRE(corners.size() >= 3);
        for (std::size_t i = 0; i < corners.size(); ++i) {
            const Vec2 before = corners[(i + corners.size() - 1) % corners.size()];
            const Vec2 after = corners[(i + 1) % corners.size()];
            CHECK((corners[i] - before).cross(after - corners[i]) > 0.0);
            CHECK(std::find(points.begin(), points.end(), corners[i]) != points.end());
        }
        // Every point is on the hull or inside it, or at most the tolerance outside (a
        // dropped nearly-in-line corner).
        for (Vec2 p : points) {
            double outside = 0.0;
            for (std::size_t i = 0; i < corners.size(); ++i) {
                const Vec2 side = corners[(i + 1) % corners.size()] - corners[i];
                outside = std::max(outside, -side.cross(p - corners[i]) / side.length());
            }
            CHECK(outside <= engine::kHullTolerance);
        }
    }
}

// Each refusal: no hull, one line, naming what is wrong.
void requireRefused(const std::vector<Vec2>& points, const std::string& says) {
    const auto result = convexHull(points);
    INFO(result.refusal);
    CHECK_FALSE(result.hull);
    CHECK(result.refusal.find(says) != std::string::npos);
    CHECK(result.refusal.find('\n') == std::string::npos);
}

TEST_CASE("hull refuses: fewer than 3 vertices", "[polygons]") {
    requireRefused({{0, 0}, {10, 0}}, "at least 3 vertices (got 2)");
    requireRefused({}, "at least 3 vertices (got 0)");
}

TEST_CASE("hull refuses: fewer than 3 distinct vertices", "[polygons]") {
    requireRefused({{0, 0}, {10, 0}, {10, 0}}, "at least 3 distinct vertices, at least 0.005 px apart (got 2 of 3)");
    requireRefused({{0, 0}, {0.001, 0}, {0, 0.001}, {10, 0}}, "(got 2 of 4)");
}

TEST_CASE("hull refuses: duplicates closer than the tolerance", "[polygons]") {
    requireRefused({{0, 0}, {10, 0}, {0, 10}, {10, 0}}, "vertices 1 and 3 are closer than 0.005 px");
    requireRefused({{0, 0}, {10, 0}, {0, 10}, {10.004, 0}}, "vertices 1 and 3 are closer than 0.005 px");
    // 0.005 px apart is far enough.
    CHECK(convexHull(std::vector<Vec2>{{0, 0}, {10, 0}, {0, 10}, {10.005, 0.01}}).hull);
}

TEST_CASE("hull refuses: all vertices on one line", "[polygons]") {
    requireRefused({{0, 0}, {10, 10}, {20, 20}, {5, 5}}, "all vertices lie on one line, within 0.005 px");
    // Nearly: the third point 0.004 px off the line through the others.
    requireRefused({{0, 0}, {100, 0}, {50, 0.004}}, "all vertices lie on one line");
    CHECK(convexHull(std::vector<Vec2>{{0, 0}, {100, 0}, {50, 0.006}}).hull);
}

TEST_CASE("hull refuses: more than 8 vertices", "[polygons]") {
    std::vector<Vec2> nine;
    for (int i = 0; i < 9; ++i) nine.push_back(Vec2{10, 0}.rotate(Vec2{}, i * 0.6));
    requireRefused(nine, "at most 8 vertices (got 9)");
    nine.pop_back();
    CHECK(convexHull(nine).hull);
}

TEST_CASE("hull refuses: a coordinate that is not finite or beyond 1e5 px", "[polygons]") {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    requireRefused({{0, 0}, {10, 0}, {nan, 10}}, "vertex 2 must have coordinates in [-100000, 100000] px");
    requireRefused({{0, 0}, {inf, 0}, {0, 10}}, "vertex 1 must have coordinates");
    requireRefused({{0, -1e300}, {10, 0}, {0, 10}}, "vertex 0 must have coordinates");
    requireRefused({{0, 0}, {100000.5, 0}, {0, 10}}, "(got [100000.5, 0])");
    CHECK(convexHull(std::vector<Vec2>{{-1e5, -1e5}, {1e5, -1e5}, {0, 1e5}}).hull);
}

}  // namespace hull_test
