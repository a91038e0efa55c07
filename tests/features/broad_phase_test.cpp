// The broad phase (every stage from 3.1 on): bounding radii, the bounding-circle test,
// and on random scenes, checked against the exact overlap of collision_oracle.h, that
// it never misses a pair that really touches; it prints how many of its pairs do not.
#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>
#include <vector>

#include "circle.h"
#include "collision_oracle.h"
#include "expect.h"
#include "random_scene.h"
#include "rectangle.h"

namespace broad_phase_test {

using engine::Vec2;

namespace {

constexpr double kPi = std::numbers::pi;

// The canvas and the sizes F and G spawn: rectangle sides 10..40 px, circle radii 20..30 px.
constexpr double kCanvasWidth = 800, kCanvasHeight = 450;
constexpr double kSideMin = 10, kSideMax = 40;
constexpr double kRadiusMin = 20, kRadiusMax = 30;

struct BroadPhaseCount {
    int pairs = 0;
    int bound_overlaps = 0;   // pairs the broad phase reports
    int false_positives = 0;  // ... of which the shapes do not touch
    int missed = 0;           // pairs that touch but the broad phase left out: must stay 0
    double falsePositiveShare() const { return static_cast<double>(false_positives) / bound_overlaps; }
};

void countPairs(const std::vector<oracle::Shape>& scene, BroadPhaseCount& count) {
    std::vector<std::unique_ptr<engine::RigidShape>> shapes;
    for (const oracle::Shape& shape : scene) shapes.push_back(test::build(shape));
    for (std::size_t i = 0; i < scene.size(); ++i) {
        for (std::size_t j = i + 1; j < scene.size(); ++j) {
            const bool bound = shapes[i]->boundTest(*shapes[j]);
            const bool touching = oracle::depth(scene[i], scene[j]) >= 0;
            ++count.pairs;
            count.bound_overlaps += bound;
            count.false_positives += bound && !touching;
            count.missed += touching && !bound;
        }
    }
}

constexpr int kScenes = 20;
constexpr int kShapesPerScene = 100;

}  // namespace

TEST_CASE("broad phase: a circle is its own bounding circle, a rectangle's reaches its corners") {
    test::expectEqual("a circle's bound radius, px: its radius", 7, engine::Circle({10, 20}, 7).boundRadius());
    // A 6 x 8 rectangle's diagonal is 10 (3-4-5 triangle doubled): radius 5.
    engine::Rectangle box({0, 0}, 6, 8);
    test::expectEqual("a 6 x 8 rectangle's bound radius, px: half its diagonal", 5, box.boundRadius());
    box.rotate(0.7);  // turning moves the corners round the same circle
    test::expectEqual("the same rectangle's bound radius turned by 0.7 rad, px", 5, box.boundRadius());
    test::expectEqual("a 2 x 2 square's bound radius, px: sqrt(2)", Approx(std::sqrt(2.0)).epsilon(1e-15),
                      engine::Rectangle({0, 0}, 2, 2).boundRadius());
}

TEST_CASE("broad phase: bounding circles apart, exactly touching and overlapping") {
    const engine::Circle a({0, 0}, 3);
    // Centres 5 apart (a 3-4-5 triangle), radii 3 + 2 = 5: touching counts as overlap.
    const engine::Circle touching({3, 4}, 2);
    test::expectEqual("boundTest of circles whose bounds just touch (centres 5 apart, radii 3 + 2): touching counts",
                      true, a.boundTest(touching));
    test::expectEqual("the same, asked the other way round", true, touching.boundTest(a));
    const engine::Circle apart({6, 8}, 2);  // 10 apart, 5 needed
    test::expectEqual("boundTest of circles 10 apart with radii 3 + 2: apart", false, a.boundTest(apart));
    test::expectEqual("the same, asked the other way round", false, apart.boundTest(a));
    const engine::Circle overlapping({1, 1}, 2);
    test::expectEqual("boundTest of overlapping circles", true, a.boundTest(overlapping));
    // A 6 x 8 rectangle (bound radius 5) 10 from a circle of radius 5: touching bounds.
    const engine::Rectangle box({20, 0}, 6, 8);
    test::expectEqual("boundTest of a 6 x 8 rectangle (bound radius 5) and a circle of radius 5, 10 apart: touching",
                      true, box.boundTest(engine::Circle({10, 0}, 5)));
    test::expectEqual("boundTest of the rectangle and a circle of radius 4.5, 10 apart: apart", false,
                      box.boundTest(engine::Circle({10, 0}, 4.5)));
    // a shape always overlaps itself
    test::expectEqual("boundTest of a shape with itself", true, box.boundTest(box));
}

TEST_CASE("broad phase: a turned rectangle and a circle 1 px apart still pass (Figure 3-5)") {
    // A 40 x 10 rectangle turned by pi/4. Its top side's outward normal, (0, -1) turned
    // by pi/4, is (sin, -cos)(pi/4) = (1, -1)/sqrt(2). A circle of radius 10 whose centre
    // is 5 (half the height) + 10 (radius) + 1 along that normal leaves a 1 px gap.
    engine::Rectangle box({200, 200}, 40, 10);
    box.rotate(kPi / 4);
    const Vec2 normal = Vec2{1, -1} * (1 / std::sqrt(2.0));
    const engine::Circle ball(Vec2{200, 200} + normal * 16, 10);
    // Bounds: 10 + sqrt(40^2 + 10^2) / 2 = 30.6 > 16 between the centres.
    test::expectEqual("boundTest of the turned rectangle and the circle 1 px from it: the bounds overlap", true,
                      box.boundTest(ball));
    const double exact = oracle::depth(oracle::Box{{200, 200}, 40, 10, kPi / 4}, oracle::Disc{ball.center(), 10});
    test::expectEqual("the oracle's depth of the pair, px: a 1 px gap", Approx(-1).epsilon(1e-12), exact);
}

TEST_CASE("broad phase: agrees with bounding circles worked out here, on 20,000 random pairs") {
    test::RandomShapes random(31);
    int borderline = 0;
    for (int k = 0; k < 20'000; ++k) {
        const Vec2 a_center{random.uniform(0, 100), random.uniform(0, 100)};
        const oracle::Shape a = random.shape(k % 2 == 0, a_center, 1, 100);
        const Vec2 b_center{random.uniform(0, 100), random.uniform(0, 100)};
        const oracle::Shape b = random.shape(k % 3 == 0, b_center, 1, 100);
        const double gap = a_center.distance(b_center) - test::reach(a) - test::reach(b);
        if (std::abs(gap) < 1e-9) {
            ++borderline;  // rounding decides: either answer is right
            continue;
        }
        INFO("pair " << k << ", gap between the bounding circles " << gap);
        test::expectEqual("boundTest's verdict: overlap when the gap between the bounding circles is below 0",
                          (gap < 0), test::build(a)->boundTest(*test::build(b)));
    }
    test::expectBelow("random pairs too close to call, of 20,000", 10, borderline);
}

TEST_CASE("broad phase: never misses a touching pair; its false-positive share, printed") {
    test::RandomShapes random(2017);
    // Scenes like the ones F and G make: shapes anywhere on the canvas, turned.
    BroadPhaseCount spawned;
    // And scenes with sizes from 1 px to 300 px, long thin rectangles among them.
    BroadPhaseCount mixed;
    for (int scene = 0; scene < kScenes; ++scene) {
        std::vector<oracle::Shape> like_spawned, mixed_sizes;
        for (int k = 0; k < kShapesPerScene; ++k) {
            const Vec2 where{random.uniform(0, kCanvasWidth), random.uniform(0, kCanvasHeight)};
            if (k % 2) {
                like_spawned.push_back(oracle::Box{where, random.uniform(kSideMin, kSideMax),
                                                   random.uniform(kSideMin, kSideMax), random.anyAngle()});
            } else {
                like_spawned.push_back(oracle::Disc{where, random.uniform(kRadiusMin, kRadiusMax)});
            }
            mixed_sizes.push_back(random.shape(k % 2 == 0, where, 1, 300));
        }
        countPairs(like_spawned, spawned);
        countPairs(mixed_sizes, mixed);
    }
    for (const BroadPhaseCount* count : {&spawned, &mixed}) {
        test::expectEqual("colliding pairs the broad phase missed", 0, count->missed);
        if (!test::expectAbove("pairs whose bounds overlap, in the random scenes", 0, count->bound_overlaps)) return;
        WARN((count == &spawned ? "F/G-like scenes" : "mixed-size scenes")
             << ": " << count->pairs << " pairs, the broad phase passes " << count->bound_overlaps << ", of which "
             << count->false_positives << " do not touch: false-positive share " << 100.0 * count->falsePositiveShare()
             << " %");
    }
}

}  // namespace broad_phase_test
