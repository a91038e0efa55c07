// What GJK, SAT and EPA cost per pair of n-gons, n = 3 to 8, and how far EPA's depth and
// normal are from SAT's (which are exact for polygons). Prints a Markdown table; its
// figures are in docs/polygons_geometry.md. Not a test: timings depend on the machine and its load.
//
//   build/polygons_bench
//
// Each row: 2,000 random pairs of n-gons (seeded, the tests' generator), timed over 50
// passes. GJK runs on pairs placed at random (about half apart, half overlapping), cold
// and then started from the simplex of the same pair a step earlier (moved 0.5 px), as a
// world step would; SAT and EPA run on overlapping pairs only, where both answer.
//
// Then the stage itself: 5.4's pyramid of 20 rows (210 boxes), its boxes given as the
// book's rectangles and as 4-gons, on both solvers, the time of a step (the fastest of
// three runs of 120 steps each, taken in turns), and the ratio the issue bounds by 2.

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <vector>

#include "boxes_as_polygons.h"
#include "browser.h"
#include "core.h"

#include "epa.h"
#include "gjk.h"
#include "polygon_sat.h"
#include "random_convex.h"
#include "scene_io.h"

namespace bench {

using engine::ConvexPolygon;
using engine::ConvexProxy;
using engine::Vec2;

constexpr int kPairs = 2000;
constexpr int kPasses = 50;
constexpr double kStepMove = 0.5;  // px: how far B moves between the cached call's two steps

struct Pair {
    std::vector<Vec2> a;
    std::vector<Vec2> b;
};

std::vector<Pair> randomPairs(browser::Random& random, std::size_t n, double spread) {
    std::vector<Pair> pairs;
    while (pairs.size() < static_cast<std::size_t>(kPairs)) {
        Pair pair;
        pair.a =
            test::randomConvex(random, n, Vec2{spread * random.next(), spread * random.next()}, 5 + 60 * random.next());
        pair.b =
            test::randomConvex(random, n, Vec2{spread * random.next(), spread * random.next()}, 5 + 60 * random.next());
        pairs.push_back(pair);
    }
    return pairs;
}

// Nanoseconds per call of `run` on each element, over kPasses passes.
template <class Each>
double nsPerPair(std::size_t count, Each run) {
    const auto start = std::chrono::steady_clock::now();
    for (int pass = 0; pass < kPasses; ++pass) {
        for (std::size_t i = 0; i < count; ++i) run(i);
    }
    const std::chrono::duration<double, std::nano> took = std::chrono::steady_clock::now() - start;
    return took.count() / (static_cast<double>(count) * kPasses);
}

struct Row {
    std::size_t n = 0;
    double gjk_ns = 0, gjk_cached_ns = 0, sat_ns = 0, manifold_ns = 0, epa_ns = 0;
    double gjk_iterations = 0, gjk_cached_iterations = 0;
    int gjk_most = 0, epa_most = 0;
    double depth_error = 0, normal_error = 0;
    int ties = 0, overlapping = 0;
};

Row measure(std::size_t n) {
    browser::Random random(38 + n);
    Row row;
    row.n = n;
    double sink = 0.0;  // every answer is added in, so no call can be left out

    // GJK, cold and cached, on pairs placed at random.
    const auto mixed = randomPairs(random, n, 100.0);
    std::vector<ConvexProxy> a, b, b_before;
    for (const Pair& pair : mixed) {
        a.push_back(engine::makeProxy(pair.a));
        b.push_back(engine::makeProxy(pair.b));
        std::vector<Vec2> before;
        for (Vec2 p : pair.b) before.push_back(p - Vec2{kStepMove, kStepMove});
        b_before.push_back(engine::makeProxy(before));
    }
    row.gjk_ns = nsPerPair(a.size(), [&](std::size_t i) { sink += engine::gjkDistance(a[i], b[i]).distance; });
    std::vector<engine::SimplexCache> caches;
    for (std::size_t i = 0; i < a.size(); ++i) caches.push_back(engine::gjkDistance(a[i], b_before[i]).cache);
    row.gjk_cached_ns =
        nsPerPair(a.size(), [&](std::size_t i) { sink += engine::gjkDistance(a[i], b[i], caches[i]).distance; });
    for (std::size_t i = 0; i < a.size(); ++i) {
        const int cold = engine::gjkDistance(a[i], b[i]).iterations;
        const int warm = engine::gjkDistance(a[i], b[i], caches[i]).iterations;
        row.gjk_iterations += cold;
        row.gjk_cached_iterations += warm;
        row.gjk_most = std::max({row.gjk_most, cold, warm});
    }
    row.gjk_iterations /= static_cast<double>(a.size());
    row.gjk_cached_iterations /= static_cast<double>(a.size());

    // SAT and EPA on overlapping pairs.
    std::vector<ConvexPolygon> pa, pb;
    std::vector<ConvexProxy> xa, xb;
    while (pa.size() < static_cast<std::size_t>(kPairs)) {
        for (const Pair& pair : randomPairs(random, n, 50.0)) {
            const ConvexPolygon first = engine::makeConvexPolygon(pair.a);
            const ConvexPolygon second = engine::makeConvexPolygon(pair.b);
            if (!engine::satCollision(first, second) || pa.size() == static_cast<std::size_t>(kPairs)) continue;
            pa.push_back(first);
            pb.push_back(second);
            xa.push_back(engine::makeProxy(pair.a));
            xb.push_back(engine::makeProxy(pair.b));
        }
    }
    row.overlapping = static_cast<int>(pa.size());
    row.sat_ns = nsPerPair(pa.size(), [&](std::size_t i) { sink += engine::satCollision(pa[i], pb[i])->depth; });
    row.manifold_ns = nsPerPair(pa.size(), [&](std::size_t i) {
        const auto hit = engine::satCollision(pa[i], pb[i]);
        sink += engine::polygonManifold(pa[i], pb[i], *hit).points[0].depth;
    });
    row.epa_ns = nsPerPair(xa.size(), [&](std::size_t i) { sink += engine::epaPenetration(xa[i], xb[i])->depth; });
    for (std::size_t i = 0; i < pa.size(); ++i) {
        const auto sat = engine::satCollision(pa[i], pb[i]);
        const auto epa = engine::epaPenetration(xa[i], xb[i]);
        row.epa_most = std::max(row.epa_most, epa->iterations);
        row.depth_error = std::max(row.depth_error, std::abs(epa->depth - sat->depth));
        const double normal_error = (epa->normal - sat->normal).length();
        if (normal_error > 1e-9) {
            ++row.ties;  // two faces equally deep: either normal is right (epa_test.cpp)
        } else {
            row.normal_error = std::max(row.normal_error, normal_error);
        }
    }
    if (sink == 0.12345) std::printf(" ");
    return row;
}

constexpr int kPyramidSteps = 120;
constexpr int kPyramidRuns = 3;

// Microseconds a step of the pyramid, its boxes rectangles or polygons.
double pyramidStepUs(engine::SolverKind solver, bool as_polygons) {
    engine::Scene scene = engine::loadScene(std::filesystem::path(STAGE_FOLDER) / "pyramid.json");
    scene.world.solver = solver;
    if (as_polygons) test::boxesAsPolygons(scene);
    browser::Window window(scene.world.dt * 1000.0);
    engine::Core core(window, scene.world);
    engine::buildScene(core, scene.bodies);
    const auto began = std::chrono::steady_clock::now();
    for (int step = 0; step < kPyramidSteps; ++step) core.update();
    const std::chrono::duration<double, std::micro> took = std::chrono::steady_clock::now() - began;
    return took.count() / kPyramidSteps;
}

void pyramidTable() {
    std::printf("\n| pyramid of 20 rows, a step | rectangles us | polygon boxes us | ratio (at most 2) |\n");
    std::printf("|---|---|---|---|\n");
    for (const engine::SolverKind solver : {engine::SolverKind::book, engine::SolverKind::sequential_impulse}) {
        double rectangles = 1e300, polygons = 1e300;
        for (int run = 0; run < kPyramidRuns; ++run) {
            rectangles = std::min(rectangles, pyramidStepUs(solver, false));
            polygons = std::min(polygons, pyramidStepUs(solver, true));
        }
        std::printf("| %s | %.0f | %.0f | %.2f |\n",
                    solver == engine::SolverKind::book ? "book's passes" : "sequential impulse", rectangles, polygons,
                    polygons / rectangles);
    }
}

}  // namespace bench

int main(int argc, char**) {
    if (argc > 1) {
        std::fprintf(stderr, "polygons_bench: takes no arguments (its settings are constants in the source)\n");
        return 2;
    }
    std::printf(
        "| n | GJK ns | GJK cached ns | GJK queries (cold / cached, most) | SAT ns | SAT + clipping ns | "
        "EPA ns | EPA queries (most) | EPA depth error px | EPA normal error | ties |\n");
    std::printf("|---|---|---|---|---|---|---|---|---|---|---|\n");
    for (std::size_t n = 3; n <= engine::kMaxPolygonVertices; ++n) {
        const bench::Row row = bench::measure(n);
        std::printf("| %zu | %.0f | %.0f | %.2f / %.2f, %d | %.0f | %.0f | %.0f | %d | %.1e | %.1e | %d |\n", row.n,
                    row.gjk_ns, row.gjk_cached_ns, row.gjk_iterations, row.gjk_cached_iterations, row.gjk_most,
                    row.sat_ns, row.manifold_ns, row.epa_ns, row.epa_most, row.depth_error, row.normal_error, row.ties);
    }
    bench::pyramidTable();
    return 0;
}
