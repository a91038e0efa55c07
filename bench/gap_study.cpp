// Continuous collision's gap on 5.8 (ch5_demo/5.8_convex_polygons/README.md, "Continuous
// collision's gap: GJK where a polygon is"), one run:
//   - queries: what one gap query costs, 5.6's per-kind functions (engine::perKindGap) against
//     GJK (engine::gjkGap), for every pair of kinds (circle, rectangle, polygons of 3, 6
//     and 8 corners), 2,000 random pairs each, half overlapping or close, timed over 50
//     passes; and the largest difference of their answers (px).
//   - the time of impact: 2,000 random motions of every kind at every kind, each shape's
//     outline pulled in by kImpactDepth; t from engine::timeOfImpact (the sweep's own,
//     with the gap the engine uses) against the exact first touch, found by brute force
//     (tests/stages/s5_8/random_convex.h) and bisection; the error in px along the
//     fastest point's path.
//   - tunnelling: 1,000 shots at 20,000 px/s at a 2 px static wall for each kind
//     (circles, rectangles, triangles, slivers 1.5 px thick, random polygons), random
//     size, angle and spin, within 45 degrees of straight, on both solvers: through when,
//     ten steps later, the centre is past the wall; and the cost of those steps.
//   - a step: 5.8's thin.json and shots.json (5.6's scenes: rectangles and circles) and
//     the same with their rectangles given as polygons, continuous on, us a step
//     (processor time, the fastest of 5 rounds of 200 fresh worlds x 30 steps).
//
//   build/gap_study
//
// Which gap the engine's sweep uses is continuous.cpp's measuredByGjk: the README's
// other columns are this program with it returning false, and true, for every pair.
// Linked with stage 5.8's engine alone.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <numbers>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "boxes_as_polygons.h"
#include "browser.h"
#include "circle.h"
#include "continuous.h"
#include "core.h"
#include "polygon.h"
#include "random_convex.h"
#include "rectangle.h"
#include "scene_io.h"
#include "thread_clock.h"

namespace {

using engine::Vec2;

double uniform(browser::Random& random, double low, double high) { return low + (high - low) * random.next(); }

// A kind of shape: 0 a circle, 1 a rectangle, n >= 3 a polygon of n corners, 2 a sliver
// (a 6-gon 1.5 px thick).
constexpr int kCircle = 0, kRectangle = 1, kSliver = 2;

std::string kindName(int kind) {
    if (kind == kCircle) return "circle";
    if (kind == kRectangle) return "rectangle";
    if (kind == kSliver) return "sliver";
    return std::to_string(kind) + "-gon";
}

using AnyShape = std::variant<engine::Circle, engine::Rectangle, engine::Polygon>;

// A shape of the kind, about `size` px across, at `center`, turned by `angle`.
AnyShape makeShape(browser::Random& random, int kind, Vec2 center, double size, double angle) {
    const auto turned = [angle](auto shape) -> AnyShape {
        shape.rotate(angle);
        return shape;
    };
    if (kind == kCircle) return turned(engine::Circle(center, size / 2));
    if (kind == kRectangle) return turned(engine::Rectangle(center, size, uniform(random, 0.2, 1.0) * size));
    if (kind == kSliver) {
        const double l = size / 2, t = 0.75;
        const std::vector<Vec2> corners{{-l, 0}, {-l / 2, -t}, {l / 2, -t}, {l, 0}, {l / 2, t}, {-l / 2, t}};
        return turned(engine::Polygon(center, corners));
    }
    return turned(
        engine::Polygon(center, test::randomConvex(random, static_cast<std::size_t>(kind), Vec2{}, size / 2)));
}

engine::Outline outlineOf(const AnyShape& shape) {
    return std::visit([](const auto& s) { return engine::outlineOf(static_cast<const engine::RigidShape&>(s)); },
                      shape);
}

// ---- queries -------------------------------------------------------------------

template <class Each>
double nsPerCall(std::size_t count, int passes, Each run) {
    const double start = bench::thread_cpu_seconds();
    for (int pass = 0; pass < passes; ++pass) {
        for (std::size_t i = 0; i < count; ++i) run(i);
    }
    return (bench::thread_cpu_seconds() - start) * 1e9 / (static_cast<double>(count) * passes);
}

void queryTable() {
    constexpr std::size_t kPairs = 2000;
    constexpr int kPasses = 50;
    const std::pair<int, int> kinds[] = {{kCircle, kCircle},
                                         {kCircle, kRectangle},
                                         {kRectangle, kRectangle},
                                         {kCircle, 8},
                                         {kRectangle, 3},
                                         {kRectangle, 6},
                                         {kRectangle, 8},
                                         {3, 3},
                                         {6, 6},
                                         {8, 8}};
    std::printf(
        "| pair | per-kind ns | GJK ns | GJK / per-kind | largest difference px | apart, not equal to the bit |\n"
        "|---|---|---|---|---|---|\n");
    browser::Random random(58);
    double sink = 0.0;
    for (const auto& [first, second] : kinds) {
        std::vector<engine::Outline> a, b;
        for (std::size_t i = 0; i < kPairs; ++i) {
            const double size_a = uniform(random, 6, 60), size_b = uniform(random, 6, 60);
            const auto shape_a = makeShape(random, first, Vec2{}, size_a, uniform(random, -3.2, 3.2));
            // B somewhere around A: from overlapping to a few sizes away, as a sweep's
            // advances see it on its way in.
            const double heading = uniform(random, -std::numbers::pi, std::numbers::pi);
            const double away = (size_a + size_b) / 2 * uniform(random, 0.3, 2.0);
            const auto shape_b = makeShape(random, second, Vec2{std::cos(heading), std::sin(heading)} * away, size_b,
                                           uniform(random, -3.2, 3.2));
            a.push_back(outlineOf(shape_a));
            b.push_back(outlineOf(shape_b));
        }
        double largest = 0.0;
        int apart = 0, unequal = 0;  // pairs apart, and those of them whose answers differ in any bit
        for (std::size_t i = 0; i < kPairs; ++i) {
            const double old = std::max(engine::perKindGap(a[i], b[i]), 0.0);
            const double gjk = engine::gjkGap(a[i], b[i]);
            largest = std::max(largest, std::abs(old - gjk));
            apart += old > 0.0 ? 1 : 0;
            unequal += old > 0.0 && old != gjk ? 1 : 0;
        }
        // Taken in turns, twice, the faster of each kept: a busy moment hits both alike.
        double per_kind = 1e300, gjk = 1e300;
        for (int round = 0; round < 2; ++round) {
            per_kind = std::min(
                per_kind, nsPerCall(kPairs, kPasses, [&](std::size_t i) { sink += engine::perKindGap(a[i], b[i]); }));
            gjk = std::min(gjk, nsPerCall(kPairs, kPasses, [&](std::size_t i) { sink += engine::gjkGap(a[i], b[i]); }));
        }
        std::printf("| %s - %s | %.0f | %.0f | %.2f | %.1e | %d of %d |\n", kindName(first).c_str(),
                    kindName(second).c_str(), per_kind, gjk, gjk / per_kind, largest, unequal, apart);
    }
    if (sink == 0.125) std::printf(" ");
}

// ---- the time of impact ------------------------------------------------------------

// An outline's core as brute force sees it: its corners counter-clockwise, or its centre.
std::vector<Vec2> coreOf(const engine::Outline& outline) {
    if (outline.is_point) return {outline.center};
    std::vector<Vec2> corners(outline.corners.begin(), outline.corners.begin() + static_cast<long>(outline.count));
    double area = 0.0;
    for (std::size_t i = 0; i < corners.size(); ++i) area += corners[i].cross(corners[(i + 1) % corners.size()]);
    if (area < 0.0) std::reverse(corners.begin(), corners.end());
    return corners;
}

double exactGap(const engine::Outline& a, const engine::Outline& b) {
    return test::bruteForceDistance(coreOf(a), coreOf(b)) - a.radius - b.radius;
}

struct ImpactTally {
    int motions = 0, hits = 0, misses = 0, near_only = 0, short_stops = 0;
    double least_gap = 1e300, most_gap = -1e300, lost_mean = 0.0, lost_most = 0.0;
    void add(const ImpactTally& other) {
        motions += other.motions;
        hits += other.hits;
        misses += other.misses;
        near_only += other.near_only;
        short_stops += other.short_stops;
        least_gap = std::min(least_gap, other.least_gap);
        most_gap = std::max(most_gap, other.most_gap);
        lost_mean += other.lost_mean;
        lost_most = std::max(lost_most, other.lost_most);
    }
    void print(const std::string& name) const {
        std::printf("| %s | %d | %d | %.4f / %.4f | %.3f / %.3f | %d | %d | %d |\n", name.c_str(), motions, hits,
                    least_gap, most_gap, hits > 0 ? lost_mean / hits : 0.0, lost_most, misses, near_only, short_stops);
    }
};

// Random motions of each kind at each kind: where engine::timeOfImpact stops the
// pulled-in outline against where it first touches the obstacle, found by brute force.
void impactTable() {
    const int kinds[] = {kCircle, kRectangle, 3, 6, 8};
    constexpr int kMotions = 400;  // per kind of mover, 80 at each kind of obstacle
    const double depth = engine::kImpactDepth;
    browser::Random random(59);
    ImpactTally all;
    std::printf(
        "\n| mover | motions | hits | gap at the stop px, least / most | motion lost px, mean / most | missed | "
        "stopped within the tolerance, never touching | stopped short after kMaxAdvances "
        "|\n|---|---|---|---|---|---|---|---|\n");
    for (const int mover : kinds) {
        ImpactTally tally;
        for (const int against : kinds) {
            for (int k = 0; k < kMotions / 5; ++k) {
                const double size = uniform(random, 8, 40);
                const AnyShape obstacle =
                    makeShape(random, against, Vec2{}, uniform(random, 8, 80), uniform(random, -3.2, 3.2));
                const double heading = uniform(random, -std::numbers::pi, std::numbers::pi);
                const Vec2 toward{std::cos(heading), std::sin(heading)};
                const Vec2 from = toward * -(size + 60 + uniform(random, 0, 40));
                const AnyShape shape = makeShape(random, mover, from, size, uniform(random, -3.2, 3.2));
                const Vec2 aim = Vec2{uniform(random, -20, 20), uniform(random, -20, 20)} - from;
                const engine::StepMotion motion{.start = outlineOf(shape),
                                                .offset = aim * uniform(random, 1.0, 2.5),
                                                .turn = mover == kCircle ? 0.0 : uniform(random, -1.5, 1.5)};
                const engine::Outline wall = outlineOf(obstacle);
                const std::optional<double> t = engine::timeOfImpact(motion, wall, depth);
                // The exact first touch of the pulled-in outline: the first of 4,000
                // samples at which it touches, then bisection back to the sample before.
                const engine::Outline inner = engine::shrunk(motion.start, depth);
                const auto at = [&](double s) {
                    return exactGap(engine::moved(inner, motion.offset * s, motion.turn * s), wall);
                };
                std::optional<double> exact;
                double nearest = 1e300;
                constexpr int kSamples = 4000;
                for (int i = 0; i <= kSamples && !exact; ++i) {
                    const double s = static_cast<double>(i) / kSamples;
                    const double left = at(s);
                    nearest = std::min(nearest, left);
                    if (left > 0.0) continue;
                    double low = std::max(0.0, s - 1.0 / kSamples), high = s;
                    for (int halving = 0; halving < 60 && i > 0; ++halving) {
                        const double middle = (low + high) / 2;
                        (at(middle) > 0.0 ? low : high) = middle;
                    }
                    exact = high;
                }
                ++tally.motions;
                if (!t) {
                    tally.misses += exact ? 1 : 0;
                    continue;
                }
                const double left = at(*t);
                if (left > 0.25 * depth + 1e-9) {
                    ++tally.short_stops;  // kMaxAdvances spent on a grazing path: short of it, never in it
                    continue;
                }
                tally.least_gap = std::min(tally.least_gap, left);
                tally.most_gap = std::max(tally.most_gap, left);
                if (!exact) {
                    ++tally.near_only;  // it passed within the tolerance: the sweep stops it there
                    continue;
                }
                ++tally.hits;
                const double lost = (*exact - *t) * motion.offset.length();
                tally.lost_mean += lost;
                tally.lost_most = std::max(tally.lost_most, lost);
            }
        }
        all.add(tally);
        tally.print(kindName(mover));
    }
    all.print("every kind");
    std::printf("(by design the sweep stops a pulled-in outline 0 to %.3f px from the obstacle)\n", 0.25 * depth);
}

// ---- tunnelling -----------------------------------------------------------------

constexpr double kShotSpeed = 20000.0;  // px/s
constexpr double kWallX = 400.0;

engine::WorldSettings shootingWorld(engine::SolverKind solver) {
    engine::WorldSettings world = engine::kBookWorld;
    world.gravity = {0, 0};
    world.remove_out_of_bounds = false;
    world.sleep = false;
    world.solver = solver;
    world.continuous = true;
    return world;
}

void tunnellingTable() {
    constexpr int kShots = 1000;
    const int kinds[] = {kCircle, kRectangle, 3, kSliver, 8};
    std::printf(
        "\n| shots at 20,000 px/s, a 2 px wall | book's passes: through | us a step | sequential impulse: "
        "through | us a step |\n|---|---|---|---|---|\n");
    for (const int kind : kinds) {
        std::printf("| 1,000 %ss |", kindName(kind).c_str());
        for (const engine::SolverKind solver : {engine::SolverKind::book, engine::SolverKind::sequential_impulse}) {
            browser::Random random(56 + kind);
            int through = 0;
            double seconds = 0.0;
            for (int i = 0; i < kShots; ++i) {
                const engine::WorldSettings world = shootingWorld(solver);
                browser::Window window(world.dt * 1000.0);
                engine::Core core(window, world);
                core.add(engine::Rectangle({kWallX, 225}, 2, 8000, {.mass = 0}));
                const double size = uniform(random, 8, 40);
                const AnyShape shot = makeShape(random, kind, {100, 225}, size, uniform(random, -3.2, 3.2));
                engine::RigidShape& shape =
                    std::visit([&core](const auto& s) -> engine::RigidShape& { return core.add(s); }, shot);
                const double heading = uniform(random, -std::numbers::pi / 4, std::numbers::pi / 4);
                shape.setVelocity(Vec2{std::cos(heading), std::sin(heading)} * kShotSpeed);
                shape.setAngularVelocity(kind == kCircle ? 0.0 : uniform(random, -30, 30));
                const double start = bench::thread_cpu_seconds();
                for (int step = 0; step < 10; ++step) core.update();
                seconds += bench::thread_cpu_seconds() - start;
                through += shape.center().x > kWallX ? 1 : 0;
            }
            std::printf(" %d | %.2f |", through, seconds * 1e6 / (kShots * 10));
        }
        std::printf("\n");
    }
}

// ---- a step of the scenes ----------------------------------------------------------

double usPerStep(const engine::Scene& scene) {
    constexpr int kWorlds = 200, kSteps = 30, kRounds = 5;
    double best = 1e300;
    for (int round = 0; round < kRounds; ++round) {
        double seconds = 0.0;
        for (int w = 0; w < kWorlds; ++w) {
            browser::Window window(scene.world.dt * 1000.0);
            engine::Core core(window, scene.world);
            engine::buildScene(core, scene.bodies);
            const double start = bench::thread_cpu_seconds();
            for (int step = 0; step < kSteps; ++step) core.update();
            seconds += bench::thread_cpu_seconds() - start;
        }
        best = std::min(best, seconds * 1e6 / (kWorlds * kSteps));
    }
    return best;
}

void stepTable() {
    std::printf("\n| scene (continuous on) | us a step | with its rectangles as polygons |\n|---|---|---|\n");
    for (const char* name : {"thin.json", "shots.json"}) {
        engine::Scene scene = engine::loadScene(std::filesystem::path(STAGE_FOLDER) / name);
        engine::Scene as_polygons = scene;
        test::boxesAsPolygons(as_polygons);
        std::printf("| %s | %.2f | %.2f |\n", name, usPerStep(scene), usPerStep(as_polygons));
    }
}

}  // namespace

int main(int argc, char**) {
    if (argc > 1) {
        std::fprintf(stderr, "gap_study: takes no arguments (its settings are constants in the source)\n");
        return 2;
    }
    const double started = bench::thread_cpu_seconds();
    queryTable();
    impactTable();
    tunnellingTable();
    stepTable();
    std::printf("(%.0f s of processor time)\n", bench::thread_cpu_seconds() - started);
    return 0;
}
