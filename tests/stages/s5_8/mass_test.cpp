// Area, centroid and moment of inertia per unit mass (polygon_mass.h) against closed
// forms worked out by integration, independently of the fan the code sums.

#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>
#include <vector>

#include "near.h"
#include "polygon_mass.h"

namespace mass_test {

using engine::polygonMass;
using engine::Vec2;

TEST_CASE("polygon mass: a triangle's area, centroid and (a^2 + b^2 + c^2) / 36", "[polygons]") {
    // A 3-4-5 right triangle, counter-clockwise: area 6, centroid the corners' average,
    // polar moment per unit mass about the centroid (a^2 + b^2 + c^2) / 36 = 50 / 36.
    const std::vector<Vec2> triangle{{10, 20}, {13, 20}, {10, 24}};
    const auto mass = polygonMass(triangle);
    CHECK_THAT(mass.area, test::near(6.0, 1e-13));
    CHECK_THAT(mass.centroid, test::near(Vec2{11, 64.0 / 3}, 1e-13));
    CHECK_THAT(mass.inertia_per_mass, test::near(50.0 / 36, 1e-13));
}

TEST_CASE("polygon mass: a house-shaped pentagon, whose centroid is not its corners' average", "[polygons]") {
    // A 2 x 2 square with a triangle of height 1 on one side: the fan's reference point
    // (the corners' average, y = 7/5) is not the centroid, so the parallel axis rule is
    // used. Worked out from the two pieces: area 4 + 1; centroid y (4 x 1 + 1 x 7/3) / 5 =
    // 19/15; moment about it (square: 4 x 8/12 + 4 (4/15)^2; triangle: 1 x (4 + 2 + 2)/36 +
    // 1 x (16/15)^2) = 970/225, per unit mass 194/225.
    const std::vector<Vec2> house{{0, 0}, {2, 0}, {2, 2}, {1, 3}, {0, 2}};
    const auto mass = polygonMass(house);
    CHECK_THAT(mass.area, test::near(5.0, 1e-14));
    CHECK_THAT(mass.centroid, test::near(Vec2{1, 19.0 / 15}, 1e-14));
    CHECK_THAT(mass.inertia_per_mass, test::near(194.0 / 225, 1e-14));
}

TEST_CASE("polygon mass: regular n-gons, 3 to 8 sides, against R^2 (2 + cos(2 pi / n)) / 6", "[polygons]") {
    // For n sides on a circle of radius R: area n R^2 sin(2 pi / n) / 2; centroid the
    // circle's centre; moment per unit mass R^2 (2 + cos(2 pi / n)) / 6, which is the
    // square's (side^2 / 6) at n = 4 and tends to the disc's R^2 / 2.
    const double radius = 25.0;
    const Vec2 center{-40, 70};
    for (int n = 3; n <= 8; ++n) {
        std::vector<Vec2> corners;
        for (int i = 0; i < n; ++i) {
            const double angle = 2 * std::numbers::pi * i / n + 0.3;
            corners.push_back(center + Vec2{radius * std::cos(angle), radius * std::sin(angle)});
        }
        const double step = 2 * std::numbers::pi / n;
        const auto mass = polygonMass(corners);
        INFO(n << " sides");
        CHECK_THAT(mass.area, test::near(n * radius * radius * std::sin(step) / 2, 1e-11));
        CHECK_THAT(mass.centroid, test::near(center, 1e-12));
        CHECK_THAT(mass.inertia_per_mass, test::near(radius * radius * (2 + std::cos(step)) / 6, 1e-11));
    }
}

TEST_CASE("polygon mass: a rectangle given as a 4-gon has the rectangle's inertia, m (w^2 + h^2) / 12", "[polygons]") {
    // rectangle.cpp's rule: I = m (w^2 + h^2) / 12. The same mass times the polygon's
    // inertia per unit mass must give it for sizes the scenes accept, to within the last
    // bit: the fan sums four triangles where the rectangle's formula has one product, so
    // the two round differently, by 0 to 0.9 of a unit in the last place (measured);
    // 4e-16 of the value is two such units.
    for (const auto& [w, h] : std::vector<std::pair<double, double>>{{40, 20}, {0.01, 0.01}, {1e5, 3}, {7.3, 910.1}}) {
        const Vec2 c{0, 0};  // the body frame, where the stage builds a polygon
        const std::vector<Vec2> corners{c + Vec2{-w / 2, -h / 2}, c + Vec2{w / 2, -h / 2}, c + Vec2{w / 2, h / 2},
                                        c + Vec2{-w / 2, h / 2}};
        const auto mass = polygonMass(corners);
        const double m = 3.5;
        const double rectangle = m * (w * w + h * h) / 12;
        INFO(w << " x " << h);
        CHECK_THAT(mass.area, test::near(w * h, 1e-15 * w * h));
        CHECK_THAT(mass.centroid, test::near(c, 1e-12));
        CHECK_THAT(m * mass.inertia_per_mass, test::near(rectangle, 4e-16 * rectangle));
    }
}

TEST_CASE("polygon mass: the same polygon moved, or listed from another corner, has the same mass", "[polygons]") {
    const std::vector<Vec2> pentagon{{0, 0}, {30, -5}, {42, 18}, {20, 35}, {-6, 22}};
    const auto here = polygonMass(pentagon);
    // Listed from each corner in turn: the fan's reference point, the corners' average,
    // is the same, and so is every triangle.
    for (std::size_t shift = 1; shift < pentagon.size(); ++shift) {
        std::vector<Vec2> turned;
        for (std::size_t i = 0; i < pentagon.size(); ++i) turned.push_back(pentagon[(i + shift) % pentagon.size()]);
        const auto listed = polygonMass(turned);
        CHECK_THAT(listed.area, test::near(here.area, 1e-12));
        CHECK_THAT(listed.centroid, test::near(here.centroid, 1e-13));
        CHECK_THAT(listed.inertia_per_mass, test::near(here.inertia_per_mass, 1e-12));
    }
    // Moved 1e5 px along each axis: the area and the moment are the polygon's own, and
    // the centroid moves with it, to the round-off of coordinates of 1e5 (about 1e-11 px).
    const Vec2 far{1e5, -1e5};
    std::vector<Vec2> moved;
    for (Vec2 p : pentagon) moved.push_back(p + far);
    const auto there = polygonMass(moved);
    CHECK_THAT(there.area, test::near(here.area, 1e-9));
    CHECK_THAT(there.centroid, test::near(here.centroid + far, 1e-10));
    CHECK_THAT(there.inertia_per_mass, test::near(here.inertia_per_mass, 1e-9));
}

}  // namespace mass_test
