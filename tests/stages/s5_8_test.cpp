// Stage 5.8: convex polygons (polygon.h). Their mass against closed forms; a box given as
// a polygon collides and stacks as the book's rectangle does, on both solvers (what it
// costs is build/polygons_bench's to say); a
// triangle slides down a slope at g (sin a - mu cos a); a fast polygon is stopped by
// continuous collision; a scene's corners that make no convex polygon are refused in one
// line. The geometry underneath (hull, GJK, EPA, SAT for n sides) has its own tests
// (tests/stages/s5_8/, s5_8.geometry); 5.7's stage tests run on this stage too
// (s5_8.s5_7_stage), and every scene of the library still moves to the bit as in 5.1
// (s5_8.identity).
#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <cmath>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include "boxes_as_polygons.h"
#include "circle.h"
#include "continuous.h"
#include "gjk_overlay.h"
#include "near.h"
#include "narrow_phase.h"
#include "overlay_draw.h"
#include "polygon.h"
#include "polygon_mass.h"
#include "random.h"
#include "random_convex.h"
#include "rectangle.h"
#include "scene_io.h"
#include "stage_program.h"
#include "world_fixture.h"

namespace s5_8_test {

using engine::Vec2;

namespace {

constexpr engine::PhysicalAttributes kStatic{.mass = 0.0};

using test::boxCorners;

}  // namespace

TEST_CASE("s5_8: a polygon's centre is its area's, and its inertia the closed form's: triangle, hexagon, box") {
    const double m = 3.0;
    SECTION("a 30-40-50 right triangle") {
        // Corners anywhere in the body's frame: the centre of area, (10, 40/3), goes on
        // the centre. I about it: m (a^2 + b^2 + c^2) / 36 = m 5000 / 36.
        const engine::Polygon triangle({100, 100}, std::vector<Vec2>{{0, 0}, {30, 0}, {0, 40}}, {.mass = m});
        CHECK_THAT(triangle.outline().vertices[0].x, test::near(100 - 10, 1e-12));
        CHECK_THAT(triangle.outline().vertices[0].y, test::near(100 - 40.0 / 3, 1e-12));
        CHECK_THAT(1 / triangle.invInertia(), test::near(m * 5000.0 / 36.0, 1e-9));
        CHECK_THAT(triangle.boundRadius(), test::near(std::hypot(10.0, 40.0 - 40.0 / 3), 1e-12));  // the corner (0, 40)
    }
    SECTION("a regular hexagon of radius 20, either winding") {
        std::vector<Vec2> corners;
        for (int k = 0; k < 6; ++k)
            corners.push_back(Vec2{std::cos(k * std::numbers::pi / 3), std::sin(k * std::numbers::pi / 3)} * 20.0);
        const engine::Polygon hexagon({0, 0}, corners, {.mass = m});
        std::vector<Vec2> backwards(corners.rbegin(), corners.rend());
        const engine::Polygon other_way({0, 0}, backwards, {.mass = m});
        // I = m R^2 (2 + cos(2 pi / n)) / 6 = 5/12 m R^2 for n = 6.
        CHECK_THAT(1 / hexagon.invInertia(), test::near(5.0 / 12.0 * m * 400.0, 1e-9));
        CHECK(hexagon.invInertia() == other_way.invInertia());
        CHECK(hexagon.outline().count == 6);
    }
    SECTION("a 30 x 20 box: the rectangle's I = m (w^2 + h^2) / 12 to a few units in the last place") {
        const engine::Polygon box({0, 0}, boxCorners(30, 20), {.mass = m});
        const engine::Rectangle rectangle({0, 0}, 30, 20, {.mass = m});
        CHECK_THAT(box.invInertia(), Catch::Matchers::WithinULP(rectangle.invInertia(), 4));
        CHECK(box.boundRadius() == rectangle.boundRadius());
    }
    SECTION("corners that make no polygon are refused, as a shape that cannot be built") {
        CHECK_THROWS_AS(engine::Polygon({0, 0}, std::vector<Vec2>{{0, 0}, {10, 0}, {20, 0}}), engine::InvalidShape);
        CHECK_THROWS_AS(engine::Polygon({0, 0}, std::vector<Vec2>{{0, 0}, {10, 0}}), engine::InvalidShape);
    }
}

TEST_CASE("s5_8: a box given as a polygon collides as the book's rectangle, with boxes and circles") {
    browser::Random random(58);
    int collided = 0;
    for (int trial = 0; trial < 2000; ++trial) {
        const double w = 10 + 40 * random.next(), h = 10 + 40 * random.next();
        const Vec2 at{100 + 60 * random.next(), 100 + 60 * random.next()};
        const double angle = 6.3 * random.next();
        engine::Rectangle rectangle(at, w, h);
        engine::Polygon polygon(at, boxCorners(w, h));
        rectangle.rotate(angle);
        polygon.rotate(angle);
        const Vec2 other_at{120 + 20 * random.next(), 120 + 20 * random.next()};
        engine::Rectangle other(other_at, 20 + 20 * random.next(), 10 + 20 * random.next());
        other.rotate(6.3 * random.next());
        const engine::Circle circle(other_at, 5 + 20 * random.next());
        for (const engine::RigidShape* against :
             {static_cast<const engine::RigidShape*>(&other), static_cast<const engine::RigidShape*>(&circle)}) {
            INFO("trial " << trial << (against == &circle ? ", a circle" : ", a rectangle"));
            const auto book = engine::narrowPhase(rectangle, *against);
            const auto ours = engine::narrowPhase(polygon, *against);
            const auto turned = engine::narrowPhase(*against, polygon);
            REQUIRE(book.has_value() == ours.has_value());
            REQUIRE(ours.has_value() == turned.has_value());
            if (!book) continue;
            ++collided;
            CHECK_THAT(ours->depth(), test::near(book->depth(), 1e-9));
            CHECK_THAT(ours->normal().x, test::near(book->normal().x, 1e-9));
            CHECK_THAT(ours->normal().y, test::near(book->normal().y, 1e-9));
            CHECK_THAT(turned->depth(), test::near(book->depth(), 1e-9));
            CHECK_THAT(turned->normal().x, test::near(-book->normal().x, 1e-9));
        }
    }
    CHECK(collided > 500);  // the pairs do overlap: the test can fail
}

namespace {

// The pyramid of 20 rows (5.4's pyramid.json, 210 boxes on a floor), its boxes given as
// rectangles or as polygons: how far its boxes moved from where they began in `steps`,
// on average.
struct PyramidRun {
    double drift = 0.0;
};

PyramidRun runPyramid(engine::SolverKind solver, bool as_polygons, int steps) {
    engine::Scene scene = engine::loadScene(std::filesystem::path(BENCH_SCENES_DIR) / ".." / ".." / "ch5_demo" /
                                            "5.8_convex_polygons" / "pyramid.json");
    scene.world.solver = solver;
    if (as_polygons) test::boxesAsPolygons(scene);
    browser::Window window(scene.world.dt * 1000.0);
    engine::Core core(window, scene.world);
    engine::buildScene(core, scene.bodies);
    std::vector<Vec2> start;
    for (std::size_t i = 0; i < core.objectCount(); ++i) start.push_back(core.object(i).center());
    for (int step = 0; step < steps; ++step) core.update();
    PyramidRun run;
    int moving = 0;
    for (std::size_t i = 0; i < core.objectCount(); ++i) {
        if (core.object(i).isStatic()) continue;
        run.drift += core.object(i).center().distance(start[i]);
        ++moving;
    }
    run.drift /= moving;
    return run;
}

}  // namespace

TEST_CASE("s5_8: a pyramid of boxes given as polygons stands as the rectangles' does") {
    for (const engine::SolverKind solver : {engine::SolverKind::book, engine::SolverKind::sequential_impulse}) {
        INFO("solver " << static_cast<int>(solver));
        const int steps = 300;  // 5 s
        const PyramidRun rectangles = runPyramid(solver, false, steps);
        const PyramidRun polygons = runPyramid(solver, true, steps);
        INFO("mean drift: rectangles " << rectangles.drift << " px, polygons " << polygons.drift << " px");
        // Within 10 % of the rectangles' drift, or of 0.1 px where that is less (a
        // standing pyramid's drift is its settling, a fraction of a pixel).
        CHECK(std::abs(polygons.drift - rectangles.drift) <= 0.1 * std::max(rectangles.drift, 1.0));
        // What they cost is the bench's to say (build/polygons_bench: the ratio of a
        // step, polygons against rectangles, at most 2): a test's timing is the load's.
    }
}

TEST_CASE("s5_8: a triangle slides down a slope at g (sin a - mu cos a), Coulomb's law on the solver") {
    // A 20-degree slope (0.35 rad), the triangle's flat face on it; friction 0.2 (the
    // slope's is 1; a pair takes the smaller). After it has slid for 2 s from rest its
    // speed along the slope is a t.
    const double slope = 0.35, mu = 0.2;
    engine::WorldSettings world = engine::kBookWorld;
    world.solver = engine::SolverKind::sequential_impulse;
    world.sleep = false;
    world.remove_out_of_bounds = false;
    test::WorldFixture page(world);
    page.core.add(engine::Rectangle({400, 300}, 760, 20, {.mass = 0, .friction = 1, .restitution = 0})).rotate(slope);
    const Vec2 along{std::cos(slope), std::sin(slope)};
    const Vec2 up{std::sin(slope), -std::cos(slope)};
    engine::Polygon& triangle = page.core.add(engine::Polygon(
        {400, 300}, std::vector<Vec2>{{-24, 8}, {24, 8}, {0, -16}}, {.mass = 1, .friction = mu, .restitution = 0}));
    triangle.rotate(slope);
    triangle.move(along * -250 + up * (10 + 8 - 0.05));  // its face 0.05 px into the slope's top
    page.steps(30);                                      // it settles on the slope
    const double v0 = triangle.velocity().dot(along);
    page.steps(120);
    const double g = world.gravity.y;
    const double expected = v0 + g * (std::sin(slope) - mu * std::cos(slope)) * 2.0;
    INFO("speed along the slope after 2 s: " << triangle.velocity().dot(along) << " px/s, closed form " << expected);
    CHECK(std::abs(triangle.velocity().dot(along) - expected) < 0.02 * expected);
    CHECK(std::abs(triangle.angularVelocity()) < 1e-3);  // it slides, it does not tip
}

TEST_CASE("s5_8: a fast triangle is stopped at a 2 px wall with continuous collision, and passes it without") {
    for (const bool continuous : {true, false}) {
        INFO("continuous " << continuous);
        engine::WorldSettings world = engine::kBookWorld;
        world.gravity = {0, 0};
        world.continuous = continuous;
        world.remove_out_of_bounds = false;
        test::WorldFixture page(world);
        page.core.add(engine::Rectangle({400, 225}, 2, 400, kStatic));
        engine::Polygon& shot =
            page.core.add(engine::Polygon({100, 225}, std::vector<Vec2>{{-6, -5}, {6, 0}, {-6, 5}}));
        shot.setVelocity({2400, 0});  // 40 px a step, against a wall 2 px thick and a shot 12 px long
        page.steps(30);
        if (continuous) {
            CHECK(shot.center().x < 400);
        } else {
            CHECK(shot.center().x > 400);
        }
    }
}

// Continuous collision's gap (continuous.h): GJK for two outlines with corners of which
// one is a polygon's, 5.6's per-kind functions for a circle or two rectangles (README.md
// says why: their cost, and 5.7's bits). Both agree with the brute-force distance.
TEST_CASE("s5_8: the sweep's gap is GJK's for a pair with a polygon and the per-kind one otherwise, both exact") {
    browser::Random random(3858);
    // The sweep's outline of any shape (polygon.h has a rectangle's ConvexPolygon by that name).
    const auto outline = [](const engine::RigidShape& shape) { return engine::outlineOf(shape); };
    int pairs_with_polygon = 0;
    for (int k = 0; k < 600; ++k) {
        const Vec2 at{200 * random.next(), 200 * random.next()};
        const engine::Polygon polygon(at, test::randomConvex(random, 3 + k % 6, Vec2{}, 5 + 30 * random.next()));
        const engine::Rectangle box({100, 100}, 5 + 40 * random.next(), 2 + 40 * random.next());
        const engine::Circle circle({100 + 60 * random.next(), 100}, 3 + 20 * random.next());
        const engine::Outline p = outline(polygon), r = outline(box), c = outline(circle);
        const std::vector<Vec2> p_core(p.corners.begin(), p.corners.begin() + static_cast<long>(p.count));
        std::vector<Vec2> r_core(r.corners.begin(), r.corners.begin() + 4);
        if (test::orientation(r_core[0], r_core[1], r_core[2]) < 0) std::reverse(r_core.begin(), r_core.end());
        std::vector<Vec2> p_ccw = p_core;
        if (test::orientation(p_ccw[0], p_ccw[1], p_ccw[2]) < 0) std::reverse(p_ccw.begin(), p_ccw.end());
        // A polygon and a rectangle: GJK's answer, to the bit, and the distance's to 1e-9 px.
        CHECK(engine::gap(p, r) == engine::gjkGap(p, r));
        CHECK_THAT(engine::gap(p, r), test::near(test::bruteForceDistance(p_ccw, r_core), 1e-9));
        // Two rectangles and a circle with either: the per-kind functions', to the bit.
        const engine::Outline r2 = outline(engine::Rectangle(at, 10, 4));
        CHECK(engine::gap(r, r2) == engine::perKindGap(r, r2));
        CHECK(engine::gap(c, p) == engine::perKindGap(c, p));
        CHECK(engine::gap(c, r) == engine::perKindGap(c, r));
        CHECK_THAT(std::max(engine::gap(c, p), 0.0),
                   test::near(std::max(test::pointShapeDistance(circle.center(), p_ccw) - circle.radius(), 0.0), 1e-9));
        pairs_with_polygon += engine::gap(p, r) > 0.0 ? 1 : 0;
    }
    CHECK(pairs_with_polygon > 200);  // most are apart: the distances are measured, not only 0
}

TEST_CASE("s5_8: corners that make no convex polygon are refused in one line, and nothing is written") {
    const test::ScratchFolder folder("s5_8-refused");
    const std::string out = " --frames 1 --out " + test::quoted(folder.path / "out");
    const auto refuses = [&](const std::string& name, const std::string& vertices, const std::string& says) {
        folder.write(name, R"({"bodies": [{"shape": "polygon", "center": [100, 100], "vertices": )" + vertices + "}]}");
        test::checkRefused(folder, "--scene " + test::quoted(folder.path / name) + out, says);
    };
    refuses("line.json", "[[0, 0], [10, 0], [20, 0]]", "bodies[0].vertices");
    refuses("same.json", "[[0, 0], [10, 0], [10, 0.001], [0, 10]]", "bodies[0].vertices");
    refuses("two.json", "[[0, 0], [10, 0]]", "must be an array of 3 to 8 points");
    refuses("nine.json", "[[0,0],[1,0],[2,1],[3,3],[3,5],[2,7],[0,8],[-1,6],[-1,2]]",
            "must be an array of 3 to 8 points");
    refuses("far.json", "[[0, 0], [1e6, 0], [0, 10]]", "bodies[0].vertices[1][0]");
    refuses("word.json", "[[0, 0], [10, \"x\"], [0, 10]]", "bodies[0].vertices[1][1]");
    refuses("flat.json", "[0, 0, 10, 0, 0, 10]", "bodies[0].vertices[0]");
}

// The overlay's diagram (gjk_overlay.h) by hand: two 40 px boxes side by side, 30 px
// apart, have A - B the 80 px square of every corner difference, centred on the
// difference of their centres (-70, 0), and the closest points are the facing sides'.
TEST_CASE("s5_8: the overlay's GJK diagram picks the nearest shape and prints the distance worked out by hand") {
    test::WorldFixture page(test::world(false));
    engine::RigidShape& a = page.core.add(engine::Polygon({100, 100}, boxCorners(40, 40)));
    page.core.add(engine::Polygon({170, 100}, boxCorners(40, 40)));  // 30 px to the right
    page.core.add(engine::Polygon({100, 200}, boxCorners(40, 40)));  // 60 px below
    page.core.add(engine::Circle({400, 100}, 10));                   // 200 px from the second box
    REQUIRE(page.core.selectedIndex() == 0);
    std::optional<engine::GjkDiagram> diagram = engine::gjkDiagram(page.core);
    REQUIRE(diagram);
    CHECK(diagram->first == 0);
    CHECK(diagram->second == 1);
    CHECK(browser::overlay::fixed(diagram->gjk.distance, 2) == "30.00");
    CHECK(diagram->gjk.point_a.x == Approx(120.0));
    CHECK(diagram->gjk.point_b.x == Approx(150.0));
    CHECK(diagram->radius == 0.0);
    std::vector<Vec2> corners = diagram->difference;
    REQUIRE(corners.size() == 4);
    std::sort(corners.begin(), corners.end(), [](Vec2 p, Vec2 q) { return p.x < q.x || (p.x == q.x && p.y < q.y); });
    const std::vector<Vec2> square{{-110, -40}, {-110, 40}, {-30, -40}, {-30, 40}};
    for (std::size_t i = 0; i < 4; ++i) {
        CHECK(corners[i].x == Approx(square[i].x));
        CHECK(corners[i].y == Approx(square[i].y));
    }
    // The circle selected: its nearest is the box on the right, 400 - 10 - 190 = 200 px
    // away, and A - B is the circle's centre less the box's corners, rounded by the radius.
    page.core.select(3);
    diagram = engine::gjkDiagram(page.core);
    REQUIRE(diagram);
    CHECK(diagram->second == 1);
    CHECK(browser::overlay::fixed(diagram->gjk.distance, 2) == "200.00");
    CHECK(diagram->radius == 10.0);
    CHECK(diagram->difference.size() == 4);
    // Moved to touch, the distance is 0: the origin lies in A - B.
    a.move({30, 0});
    page.core.select(0);
    CHECK(engine::gjkDiagram(page.core)->gjk.distance == 0.0);
}

// GJK's walk in the diagram's panels (gjk.h's GjkStep), by hand, for the two boxes 30 px
// apart of the test above. A's corners are (80, 80), (120, 80), (120, 120), (80, 120), B's
// the same 70 px to the right, and GJK starts from the first of each: w1 = (80, 80) -
// (150, 80) = (-70, 0).
//   Pass 1: the simplex is w1, nearest the origin itself; it looks along (70, 0). A's
//   farthest corner that way is (120, 80) (the first of two at x = 120), B's farthest
//   the other way (150, 80): w2 = (-30, 0), 40 px nearer, kept.
//   Pass 2: the segment w1 w2 has the origin beyond w2 (w2 . (w2 - w1) = -1200 < 0), so
//   it is cut to w2, which looks along (30, 0) and finds w2 again: no nearer, the end.
// Three panels, then: two passes and the answer; A - B's box with the origin, x from -110
// to 0 and y from -40 to 40, fits the 120 x 82 px below a panel's label at 82 / 80.
TEST_CASE("s5_8: the diagram's panels are GJK's passes, worked out by hand for two boxes apart") {
    test::WorldFixture page(test::world(false));
    page.core.add(engine::Polygon({100, 100}, boxCorners(40, 40)));
    page.core.add(engine::Polygon({170, 100}, boxCorners(40, 40)));
    const std::optional<engine::GjkDiagram> diagram = engine::gjkDiagram(page.core);
    REQUIRE(diagram);
    REQUIRE(diagram->steps.size() == 2);
    CHECK(diagram->gjk.iterations == 2);
    const engine::GjkStep& first = diagram->steps[0];
    CHECK(first.simplex.count == 1);
    CHECK(first.simplex.vertices[0].w == Vec2{-70, 0});
    CHECK(first.nearest == Vec2{-70, 0});
    CHECK(first.direction == Vec2{70, 0});
    CHECK(first.queried);
    CHECK(first.support.w == Vec2{-30, 0});
    CHECK(first.kept);
    CHECK_FALSE(first.holds_origin);
    const engine::GjkStep& second = diagram->steps[1];
    CHECK(second.simplex.count == 1);
    CHECK(second.simplex.vertices[0].w == Vec2{-30, 0});
    CHECK(second.direction == Vec2{30, 0});
    CHECK(second.queried);
    CHECK(second.support.w == Vec2{-30, 0});
    CHECK_FALSE(second.kept);
    CHECK_FALSE(diagram->epa.has_value());
    CHECK(diagram->depth == 0.0);
    // The trace is a record, not a second answer: the call without it says the same.
    const auto proxyOf = [&](std::size_t i) {
        return engine::makeProxy(static_cast<const engine::Polygon&>(page.core.object(i)).outline().corners());
    };
    const engine::DistanceResult untraced = engine::gjkDistance(proxyOf(0), proxyOf(1));
    CHECK(untraced.distance == diagram->gjk.distance);
    CHECK(untraced.iterations == diagram->gjk.iterations);
}

// The same boxes 30 px apart centre to centre overlap by 10 px: A - B is the 80 px square
// x from -70 to 10, and its side nearest the origin, x = 10, is the depth.
//   GJK: w1 = (80, 80) - (110, 80) = (-30, 0) looks along (30, 0) and finds (10, 0);
//   the segment from (-30, 0) to (10, 0) runs through the origin (weights 1/4 and 3/4),
//   so pass 2 holds it: "inside", no query.
//   EPA starts from that segment, adds the support point square to it, (10, 40), and
//   pushes out the side nearest the origin three times: along (0, -1), finding (-70, -40)
//   (the start (-30, 0) drops off, on the new side); along (1, -2) / sqrt 5 from the side
//   4.47 px off, finding (10, -40) ((10, 0) drops off); then along (1, 0), from the side
//   x = 10, where A - B reaches no farther: depth 10, normal (1, 0), on the triangle
//   (-70, -40), (10, -40), (10, 40), all three corners of A - B.
TEST_CASE("s5_8: the diagram of two overlapping boxes ends on EPA's triangle, 10 px deep, worked out by hand") {
    test::WorldFixture page(test::world(false));
    page.core.add(engine::Polygon({100, 100}, boxCorners(40, 40)));
    page.core.add(engine::Polygon({130, 100}, boxCorners(40, 40)));
    const std::optional<engine::GjkDiagram> diagram = engine::gjkDiagram(page.core);
    REQUIRE(diagram);
    REQUIRE(diagram->steps.size() == 2);
    CHECK(diagram->steps[0].support.w == Vec2{10, 0});
    CHECK(diagram->steps[0].kept);
    const engine::GjkStep& inside = diagram->steps[1];
    CHECK(inside.holds_origin);
    CHECK_FALSE(inside.queried);
    CHECK(inside.simplex.count == 2);
    CHECK(inside.simplex.vertices[0].weight == 0.25);
    CHECK(inside.simplex.vertices[1].weight == 0.75);
    CHECK(inside.nearest == Vec2{0, 0});
    CHECK(diagram->gjk.distance == 0.0);
    REQUIRE(diagram->epa);
    CHECK(diagram->epa->depth == 10.0);
    CHECK(diagram->epa->normal == Vec2{1, 0});
    CHECK(diagram->epa->iterations == 3);
    CHECK(diagram->depth == 10.0);
    std::vector<Vec2> triangle = diagram->epa_polygon;
    std::sort(triangle.begin(), triangle.end(), [](Vec2 p, Vec2 q) { return p.x < q.x || (p.x == q.x && p.y < q.y); });
    CHECK(triangle == std::vector<Vec2>{{-70, -40}, {10, -40}, {10, 40}});
}

// Two circles of radius 10 whose centres are 15 px apart: their cores (the centres) are
// apart, so EPA has nothing to say, and the depth is the radii less the gap, 20 - 15.
TEST_CASE("s5_8: the diagram of two overlapping circles gives the radii less the centres' gap as the depth") {
    test::WorldFixture page(test::world(false));
    page.core.add(engine::Circle({100, 100}, 10));
    page.core.add(engine::Circle({115, 100}, 10));
    const std::optional<engine::GjkDiagram> diagram = engine::gjkDiagram(page.core);
    REQUIRE(diagram);
    CHECK(diagram->gjk.distance == 0.0);
    CHECK_FALSE(diagram->epa.has_value());
    CHECK(diagram->radius == 20.0);
    CHECK(diagram->depth == Approx(5.0).margin(1e-12));
    CHECK(diagram->difference.size() == 1);
}

// The panels' row: right-aligned along the top, 8 px in, 6 px apart, 136 x 108 px. Five
// (four passes and the answer) fit one row of the demo's 800 px canvas; a sixth starts a
// second row under the first. The row ends 116 px down, above the top end of the demo's
// long slide (my_game.h: 400 x 20 at (500, 200), turned 2.8 rad), whose highest corner is
// 200 - 200 sin 2.8 - 10 cos 2.8 = 123.6 px down.
TEST_CASE("s5_8: the diagram's panels sit in a row along the top, clear of the long slide's top end") {
    const std::vector<Vec2> four = engine::gjkPanelCorners(4, 800);
    REQUIRE(four.size() == 4);
    CHECK(four[0] == Vec2{800 - 8 - (4 * 142 - 6), 8});
    CHECK(four[3] == Vec2{800 - 8 - 136, 8});
    const std::vector<Vec2> five = engine::gjkPanelCorners(5, 800);
    CHECK(five[0] == Vec2{800 - 8 - (5 * 142 - 6), 8});
    const std::vector<Vec2> six = engine::gjkPanelCorners(6, 800);
    CHECK(six[4].y == 8);
    CHECK(six[5] == Vec2{six[0].x, 8 + 108 + 6});
    engine::Rectangle slide({500, 200}, 400, 20, kStatic);
    slide.rotate(2.8);
    double highest = 1e9;
    for (const Vec2 corner : slide.vertices()) highest = std::min(highest, corner.y);
    CHECK(highest == Approx(123.6).margin(0.05));
    CHECK(engine::kGjkPanelMargin + engine::kGjkPanelHeight < highest);
    // A canvas too narrow for one panel still gets every panel, one a row.
    const std::vector<Vec2> narrow = engine::gjkPanelCorners(2, 100);
    CHECK(narrow[1].x == narrow[0].x);
    CHECK(narrow[1].y > narrow[0].y);
}

// The same row in the corner of the canvas where it covers the least area of the shapes'
// boxes: the top right first, then the top left, the bottom right, the bottom left. Two panels on an
// 800 x 450 canvas make a block 2 x 136 + 6 = 278 px wide and 108 px tall: from x = 800 -
// 8 - 278 = 514 on the right, from 8 on the left; from y = 8 at the top, from 450 - 8 -
// 108 = 334 at the bottom.
TEST_CASE("s5_8: the panels go to the corner of the canvas the shapes leave emptiest") {
    using Box = engine::CanvasBox;
    const auto first = [](const std::vector<Box>& occupied) {
        return engine::gjkPanelCorners(2, 800, 450, occupied).front();
    };
    const Box top_right{{600, 40}, {620, 60}}, top_left{{100, 40}, {120, 60}};
    const Box bottom_right{{700, 400}, {720, 420}}, bottom_left{{50, 400}, {70, 420}};
    CHECK(first({}) == Vec2{514, 8});
    CHECK(first({top_right}) == Vec2{8, 8});
    CHECK(first({top_right, top_left}) == Vec2{514, 334});
    CHECK(first({top_right, top_left, bottom_right}) == Vec2{8, 334});
    CHECK(first({top_right, top_left, bottom_right, bottom_left}) == Vec2{514, 8});  // a tie: the top right
    CHECK(first({top_right, bottom_right, bottom_left, Box{{10, 10}, {20, 20}}, top_left}) == Vec2{514, 8});
    // Area, not count: two 20 px boxes in the top right cover less than a 40 px one in
    // each other corner (800 against 1600 px^2).
    const Box big_top_left{{100, 40}, {140, 80}}, big_bottom_right{{700, 380}, {740, 420}},
        big_bottom_left{{50, 380}, {90, 420}};
    CHECK(first({top_right, Box{{640, 40}, {660, 60}}, big_top_left, big_bottom_right, big_bottom_left}) ==
          Vec2{514, 8});
    // A box that ends where the block starts is not under it.
    CHECK(first({Box{{300, 40}, {514, 60}}}) == Vec2{514, 8});
    // The second panel keeps its place beside the first.
    CHECK(engine::gjkPanelCorners(2, 800, 450, {top_right})[1] == Vec2{8 + 142, 8});
    // A shape's box: a circle's centre and radius, a rectangle's corners.
    test::WorldFixture page(test::world(false));
    page.core.add(engine::Circle({100, 50}, 10));
    page.core.add(engine::Rectangle({300, 200}, 40, 20));
    const std::vector<Box> boxes = engine::shapeBoxes(page.core);
    REQUIRE(boxes.size() == 2);
    CHECK(boxes[0].low == Vec2{90, 40});
    CHECK(boxes[0].high == Vec2{110, 60});
    CHECK(boxes[1].low == Vec2{280, 190});
    CHECK(boxes[1].high == Vec2{320, 210});
}

// The slash key (user_control.h): one new body, a convex polygon of 3 to 8 corners, at
// the selected object's centre, drawn from the page's seeded random numbers: the corners
// polygon.h's randomCorners draws from a generator in the same state, every one of them
// kept by the hull, counter-clockwise, the centre of area on the selected centre. Over
// 500 seeds, every corner count from 3 to 8 turns up.
TEST_CASE("s5_8: the slash key drops one random convex polygon of 3 to 8 corners at the selected object") {
    std::vector<int> counts(9, 0);
    for (std::uint64_t seed = 1; seed <= 500; ++seed) {
        INFO("seed " << seed);
        test::WorldFixture page(test::world(false), seed);
        page.core.add(engine::Rectangle({300, 200}, 100, 20, kStatic));
        page.core.add(engine::Circle({120, 80}, 15));
        page.press(browser::Key::Digit1);
        browser::Random same(seed);
        const std::vector<Vec2> expected = engine::randomCorners(same);
        page.press(browser::Key::Slash);
        REQUIRE(page.core.objectCount() == 3);
        const engine::RigidShape& dropped = page.core.object(2);
        REQUIRE(dropped.type() == engine::ShapeType::Polygon);
        CHECK(dropped.center() == Vec2{120, 80});
        const engine::ConvexPolygon& body = static_cast<const engine::Polygon&>(dropped).bodyOutline();
        REQUIRE(body.count >= 3);
        REQUIRE(body.count <= 8);
        CHECK(body.count == expected.size());
        ++counts[body.count];
        for (std::size_t i = 0; i < body.count; ++i) {
            const double turn = (body.corner(i + 1) - body.corner(i)).cross(body.corner(i + 2) - body.corner(i + 1));
            CHECK(turn > 0.0);
        }
        const engine::PolygonMass mass = engine::polygonMass(body.corners());
        CHECK(mass.centroid.length() < 1e-9);
        // Its velocity is drawn after its attributes, within F's and G's +-150 px/s.
        CHECK(std::abs(dropped.velocity().x) <= engine::UserControl::kSpawnSpeed);
        CHECK(std::abs(dropped.velocity().y) <= engine::UserControl::kSpawnSpeed);
    }
    for (int corners = 3; corners <= 8; ++corners) CHECK(counts[static_cast<std::size_t>(corners)] > 0);
}

TEST_CASE("s5_8: the slash key drops the same polygon from the same seed, and another from the next press") {
    const auto dropTwice = [](std::uint64_t seed) {
        test::WorldFixture page(test::world(false), seed);
        page.core.add(engine::Circle({200, 200}, 15));
        page.press(browser::Key::Slash, 2);
        std::vector<Vec2> corners;
        for (std::size_t i = 1; i <= 2; ++i) {
            for (const Vec2 corner : static_cast<const engine::Polygon&>(page.core.object(i)).outline().corners())
                corners.push_back(corner);
        }
        return corners;
    };
    const std::vector<Vec2> run = dropTwice(7);
    CHECK(run == dropTwice(7));
    CHECK(run != dropTwice(8));
}

#if BROWSER_HAS_SDL
// Played live (SDL's dummy driver; the --live-events test hook presses "/" as a keyboard
// does), the key is recorded as "slash", and the command the session prints replays the
// recorded script to the same state dump, byte for byte: the live session's dump and
// the replay's, one polygon more after each press.
TEST_CASE("s5_8: the slash key played live is recorded, and the printed command replays it to the same dump") {
    test::ScratchFolder folder("s5_8-slash-live");
    folder.write("events.txt", "/@2 Down@3 /@4 Escape@8\n");
    const std::string before =
        "cd " + test::quoted(folder.path) + " && SDL_VIDEODRIVER=dummy SDL_RENDER_DRIVER=software ";
    const test::ProgramRun live =
        test::runStageProgram(folder, "--live --record session.keys --live-events events.txt --dump live.csv", before);
    INFO(live.error_text);
    REQUIRE(live.status == 0);
    CHECK(test::readText(folder.path / "session.keys") == "slash@2 down@3 slash@4\n");
    const std::filesystem::path kept = folder.path / "live_kept.csv";
    std::filesystem::copy_file(folder.path / "live.csv", kept);
    // The printed command's second line, run as printed (it writes live.csv again).
    const std::string printed = test::readText(folder.path / "stdout.txt");
    const std::size_t start = printed.find("\n  ");
    REQUIRE(start != std::string::npos);
    const std::string command = printed.substr(start + 3, printed.find('\n', start + 3) - start - 3);
    REQUIRE(command.rfind(std::string(STAGE_PROGRAM) + " ", 0) == 0);
    const test::ProgramRun replay =
        test::runStageProgram(folder, command.substr(std::string(STAGE_PROGRAM).size() + 1) + " --out out",
                              "cd " + test::quoted(folder.path) + " && ");
    INFO(replay.error_text);
    REQUIRE(replay.status == 0);
    CHECK(test::readText(folder.path / "live.csv") == test::readText(kept));
    // One polygon more after each press: the demo's five, then six, then seven.
    const std::vector<test::DumpRow> rows = test::readDump(kept);
    REQUIRE_FALSE(rows.empty());
    const auto polygonsAt = [&](long step) {
        return std::count_if(rows.begin(), rows.end(),
                             [&](const test::DumpRow& row) { return row.step == step && row.shape == "polygon"; });
    };
    CHECK(polygonsAt(rows.front().step) == 5);
    CHECK(polygonsAt(rows.back().step) == 7);
}
#endif

// With one shape there is no pair to draw.
TEST_CASE("s5_8: the overlay's GJK diagram has no pair in a world of one shape") {
    test::WorldFixture page(test::world(false));
    page.core.add(engine::Circle({100, 100}, 10));
    CHECK_FALSE(engine::gjkDiagram(page.core).has_value());
}

}  // namespace s5_8_test
