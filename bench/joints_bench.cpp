// 5.9's joints beside Box2D 2.4's (issue 39): the chain, the bridge and the grid of the
// stage's tests (tests/stages/s5_9_test.cpp), built once in px and given to both
// engines, Box2D at 30 px to the metre. For each engine and each number of velocity
// iterations (and for the stage, with 4 sub-steps a step, its world's substeps): the
// cost of a step (ms, the median of the run's steps) against what the joints let go:
// the largest gap at any pin over the run, and the most the chain grew (the gaps
// summed), px. A point further down and to the left is better on both.
//
// The chain and the bridge are swept over iteration counts: their fronts. A point is
// beaten when the other engine has one both cheaper and tighter (a smaller ms a step
// and a smaller largest gap); the last column names the cheapest such point. Each of
// their runs is timed three times and the fastest median kept (the gaps are the same to
// the bit each time), so that another process on the machine moves the figures less.
//   build/joints_bench              the tables (about 20 s of one core)
//   BOX_MASS=30 build/joints_bench  the bridge's box of another mass (planks are 1)
//   NO_BOX=1 build/joints_bench     the bridge with nothing on it
//   build/joints_bench --only grid  one scene alone (chain, bridge or grid): for perf record
//   STAGE_ONLY=1 build/joints_bench the stage's rows alone (farm-bench's ratios of two builds)
//   GRID="20 12 2 300" build/joints_bench --only grid
//                                   another grid: side, spacing px, radius px, gravity px/s^2,
//                                   and "boxes" after them for boxes of that half side
//                                   (tests/stages/s5_9/positional_passes_test.cpp's sweep)
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <memory>
#include <numbers>
#include <string>
#include <string_view>
#include <vector>

#include "browser.h"
#include "circle.h"
#include "core.h"
#include "joints.h"
#include "rectangle.h"

#if BENCH_HAS_BOX2D
#include <box2d/box2d.h>
#endif

namespace {

using lib::Vec2;

constexpr double kPixelsPerMetre = 30.0;
constexpr double kGravity = 300.0;  // px/s^2: 10 m/s^2
constexpr double kDt = 1.0 / 60.0;
constexpr int kSteps = 600;  // 10 s

// A scene of boxes and discs joined by pins, in px.
struct Piece {
    bool disc = false;
    Vec2 center;
    double width = 0.0, height = 0.0, radius = 0.0, angle = 0.0;
    double mass = 1.0;  // 0: static
    double friction = 0.6;
};
struct Pin {
    std::size_t a, b;
    Vec2 anchor;
};
struct JointScene {
    std::string name;
    std::vector<Piece> pieces;
    std::vector<Pin> pins;
    // A piece added after this many steps (the bridge's load), or none.
    std::optional<Piece> dropped;
    int drop_at = 0;
    double gravity = kGravity;  // px/s^2, down
};

// 40 links of 20 x 5 px from a post, released level, a disc of 10 links' mass at the end.
JointScene chain() {
    JointScene scene{.name = "chain: 40 links, load 10:1", .pieces = {}, .pins = {}, .dropped = {}, .drop_at = 0};
    const Vec2 start{40, 40};
    scene.pieces.push_back({.disc = true, .center = start, .radius = 2, .mass = 0});
    for (int i = 0; i < 40; ++i) {
        scene.pieces.push_back({.center = start + Vec2{20.0 * (i + 0.5), 0}, .width = 20, .height = 5});
        scene.pins.push_back({scene.pieces.size() - 2, scene.pieces.size() - 1, start + Vec2{20.0 * i, 0}});
    }
    scene.pieces.push_back({.disc = true, .center = start + Vec2{808, 0}, .radius = 8, .mass = 10});
    scene.pins.push_back({scene.pieces.size() - 2, scene.pieces.size() - 1, start + Vec2{800, 0}});
    return scene;
}

// 50 planks of 16 x 4 px on a sagging arc between two posts 760 px apart (the planks
// span 800), and at 1 s a 40 px box of 100 planks' mass dropped on the middle.
JointScene bridge() {
    JointScene scene{.name = "bridge: 50 planks, box 100:1", .pieces = {}, .pins = {}, .dropped = {}, .drop_at = 60};
    // A circular arc of length 800 over a chord of 760: sin(t) / t = 0.95.
    double half_angle = 0.5;
    for (int i = 0; i < 50; ++i)
        half_angle -= (std::sin(half_angle) / half_angle - 0.95) /
                      ((half_angle * std::cos(half_angle) - std::sin(half_angle)) / (half_angle * half_angle));
    const double radius = 400.0 / half_angle;
    const Vec2 middle{400, 200 - radius * std::cos(half_angle)};  // the arc's centre, above
    const auto on_arc = [&](double s) {                           // s in [0, 800] along the arc, left to right
        const double a = -half_angle + 2 * half_angle * s / 800.0;
        return middle + Vec2{radius * std::sin(a), radius * std::cos(a)};
    };
    scene.pieces.push_back({.disc = true, .center = on_arc(0), .radius = 2, .mass = 0});
    for (int i = 0; i < 50; ++i) {
        const Vec2 from = on_arc(16.0 * i), to = on_arc(16.0 * (i + 1));
        scene.pieces.push_back({.center = (from + to) * 0.5,
                                .width = from.distance(to),
                                .height = 4,
                                .angle = std::atan2(to.y - from.y, to.x - from.x)});
        scene.pins.push_back({scene.pieces.size() - 2, scene.pieces.size() - 1, from});
    }
    scene.pieces.push_back({.disc = true, .center = on_arc(800), .radius = 2, .mass = 0});
    scene.pins.push_back({scene.pieces.size() - 2, scene.pieces.size() - 1, on_arc(800)});
    scene.dropped =
        Piece{.center = {400, 200 + radius * (1 - std::cos(half_angle)) - 23}, .width = 40, .height = 40, .mass = 100};
    if (std::getenv("NO_BOX")) scene.dropped.reset();
    if (const char* mass = std::getenv("BOX_MASS")) scene.dropped->mass = std::atof(mass);
    return scene;
}

// A grid of bodies, each pinned halfway to its right and lower neighbours, the top left
// one static: it falls from level and swings. The bench's own: 30 x 30 discs of radius
// 4 px, 12 px apart (1,740 pins), at 300 px/s^2.
struct GridShape {
    int side = 30;
    double spacing = 12.0;  // px
    double radius = 4.0;    // px: a disc's, or half a box's side
    double gravity = kGravity;
    bool boxes = false;
};

// The grid GRID names ("side spacing radius gravity", then "boxes" or nothing), or the
// bench's own; nullopt when GRID is there but not such a grid.
std::optional<GridShape> gridShape() {
    GridShape shape;
    const char* given = std::getenv("GRID");
    if (given == nullptr) return shape;
    char kind[8] = "";
    const int read =
        std::sscanf(given, "%d %lf %lf %lf %7s", &shape.side, &shape.spacing, &shape.radius, &shape.gravity, kind);
    shape.boxes = std::string_view(kind) == "boxes";
    const bool fits = shape.side >= 2 && shape.side <= 100 && shape.spacing > 0 && shape.spacing < 1000 &&
                      shape.radius > 0 && shape.radius < 1000 && shape.gravity >= 0 && shape.gravity < 1e5;
    if ((read != 4 && read != 5) || (read == 5 && !shape.boxes) || !fits) return std::nullopt;
    return shape;
}

JointScene grid(const GridShape& shape) {
    char name[160];
    std::snprintf(name, sizeof name, "grid: %d x %d %s of %s %g px, %g px apart, %d pins, one corner fixed, g %g",
                  shape.side, shape.side, shape.boxes ? "boxes" : "discs", shape.boxes ? "half side" : "radius",
                  shape.radius, shape.spacing, 2 * shape.side * (shape.side - 1), shape.gravity);
    JointScene scene{.name = name, .pieces = {}, .pins = {}, .dropped = {}, .drop_at = 0, .gravity = shape.gravity};
    const int side = shape.side;
    const double spacing = shape.spacing;
    const Vec2 corner{200, 40};
    for (int row = 0; row < side; ++row) {
        for (int column = 0; column < side; ++column) {
            scene.pieces.push_back({.disc = !shape.boxes,
                                    .center = corner + Vec2{column * spacing, row * spacing},
                                    .width = 2 * shape.radius,
                                    .height = 2 * shape.radius,
                                    .radius = shape.radius,
                                    .mass = row == 0 && column == 0 ? 0.0 : 1.0});
        }
    }
    const auto at = [side](int row, int column) { return static_cast<std::size_t>(row * side + column); };
    for (int row = 0; row < side; ++row) {
        for (int column = 0; column < side; ++column) {
            const Vec2 here = corner + Vec2{column * spacing, row * spacing};
            if (column + 1 < side)
                scene.pins.push_back({at(row, column), at(row, column + 1), here + Vec2{spacing / 2, 0}});
            if (row + 1 < side)
                scene.pins.push_back({at(row, column), at(row + 1, column), here + Vec2{0, spacing / 2}});
        }
    }
    return scene;
}

struct Result {
    double ms_per_step = 0.0;
    double largest_gap = 0.0;  // px
    double most_added = 0.0;   // px
};

double median(std::vector<double> values) {
    std::sort(values.begin(), values.end());
    return values[values.size() / 2];
}

using Clock = std::chrono::steady_clock;
double msSince(Clock::time_point start) {
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

// The stage's engine.
Result runStage(const JointScene& scene, int iterations, int substeps = 1) {
    engine::WorldSettings world = engine::kBookWorld;
    world.substeps = substeps;
    world.solver = engine::SolverKind::sequential_impulse;
    world.gravity = {0, scene.gravity};
    world.velocity_iterations = iterations;
    world.remove_out_of_bounds = false;
    world.sleep = false;
    // As Box2D's runs below (SetContinuousPhysics(false)): nothing in these scenes moves
    // far against its size in a step, and the gaps are the same with the sweeps on.
    world.continuous = false;
    browser::Window window(kDt * 1000.0);
    engine::Core core(window, world);
    const auto add = [&core](const Piece& piece) -> engine::RigidShape& {
        const engine::PhysicalAttributes attributes{.mass = piece.mass, .friction = piece.friction, .restitution = 0.0};
        engine::RigidShape& shape =
            piece.disc
                ? static_cast<engine::RigidShape&>(core.add(engine::Circle(piece.center, piece.radius, attributes)))
                : core.add(engine::Rectangle(piece.center, piece.width, piece.height, attributes));
        shape.rotate(piece.angle);
        return shape;
    };
    for (const Piece& piece : scene.pieces) add(piece);
    for (const Pin& pin : scene.pins) {
        core.join(engine::pinAt(engine::JointType::revolute, core.object(pin.a), core.object(pin.b), pin.anchor));
    }
    Result result;
    std::vector<double> times;
    for (int step = 0; step < kSteps; ++step) {
        if (scene.dropped && step == scene.drop_at) add(*scene.dropped);
        const Clock::time_point start = Clock::now();
        core.update();
        times.push_back(msSince(start));
        double added = 0.0;
        for (std::size_t k = 0; k < scene.pins.size(); ++k) {
            const engine::JointDefinition& joint = core.joints().all()[k].definition;
            const double gap = engine::separationOf(joint, core.object(scene.pins[k].a), core.object(scene.pins[k].b));
            added += gap;
            result.largest_gap = std::max(result.largest_gap, gap);
        }
        result.most_added = std::max(result.most_added, added);
    }
    result.ms_per_step = median(times);
    return result;
}

#if BENCH_HAS_BOX2D
b2Vec2 metres(Vec2 px) {
    return {static_cast<float>(px.x / kPixelsPerMetre), static_cast<float>(px.y / kPixelsPerMetre)};
}
Vec2 pixels(b2Vec2 m) { return Vec2{m.x, m.y} * kPixelsPerMetre; }

// Box2D 2.4, 3 position iterations (its default), the same pieces and pins.
Result runBox2d(const JointScene& scene, int iterations) {
    b2World world(b2Vec2(0.0f, static_cast<float>(scene.gravity / kPixelsPerMetre)));
    world.SetContinuousPhysics(false);
    world.SetAllowSleeping(false);
    std::vector<b2Body*> bodies;
    const auto add = [&](const Piece& piece) {
        b2BodyDef definition;
        definition.type = piece.mass > 0 ? b2_dynamicBody : b2_staticBody;
        definition.position = metres(piece.center);
        definition.angle = static_cast<float>(piece.angle);
        b2Body* body = world.CreateBody(&definition);
        b2FixtureDef fixture;
        b2PolygonShape box;
        b2CircleShape disc;
        double area = 0.0;
        if (piece.disc) {
            disc.m_radius = static_cast<float>(piece.radius / kPixelsPerMetre);
            fixture.shape = &disc;
            area = std::numbers::pi * disc.m_radius * disc.m_radius;
        } else {
            box.SetAsBox(static_cast<float>(piece.width / 2 / kPixelsPerMetre),
                         static_cast<float>(piece.height / 2 / kPixelsPerMetre));
            fixture.shape = &box;
            area = piece.width * piece.height / (kPixelsPerMetre * kPixelsPerMetre);
        }
        fixture.density = piece.mass > 0 ? static_cast<float>(piece.mass / area) : 0.0f;
        fixture.friction = static_cast<float>(piece.friction);
        body->CreateFixture(&fixture);
        bodies.push_back(body);
    };
    for (const Piece& piece : scene.pieces) add(piece);
    std::vector<b2Joint*> joints;
    for (const Pin& pin : scene.pins) {
        b2RevoluteJointDef definition;
        definition.Initialize(bodies[pin.a], bodies[pin.b], metres(pin.anchor));
        joints.push_back(world.CreateJoint(&definition));
    }
    Result result;
    std::vector<double> times;
    for (int step = 0; step < kSteps; ++step) {
        if (scene.dropped && step == scene.drop_at) add(*scene.dropped);
        const Clock::time_point start = Clock::now();
        world.Step(static_cast<float>(kDt), iterations, 3);
        times.push_back(msSince(start));
        double added = 0.0;
        for (b2Joint* joint : joints) {
            const double gap = pixels(joint->GetAnchorA()).distance(pixels(joint->GetAnchorB()));
            added += gap;
            result.largest_gap = std::max(result.largest_gap, gap);
        }
        result.most_added = std::max(result.most_added, added);
    }
    result.ms_per_step = median(times);
    return result;
}
#endif

// One point of a front: an engine at a number of iterations, and what it gave.
struct Point {
    std::string engine;
    int iterations = 0;
    Result result;
};

// The run timed `repeats` times, the fastest median kept: the gaps are the same each time.
template <typename Run>
Result fastestOf(int repeats, Run run) {
    Result best = run();
    for (int r = 1; r < repeats; ++r) best.ms_per_step = std::min(best.ms_per_step, run().ms_per_step);
    return best;
}

bool sameEngine(const Point& one, const Point& other) {
    return one.engine.starts_with("5.9") == other.engine.starts_with("5.9");
}

// The cheapest point of the other engine both cheaper and tighter than `point`, if any.
const Point* beatenBy(const Point& point, const std::vector<Point>& points) {
    const Point* cheapest = nullptr;
    for (const Point& other : points) {
        if (sameEngine(point, other)) continue;
        if (other.result.ms_per_step < point.result.ms_per_step &&
            other.result.largest_gap < point.result.largest_gap &&
            (!cheapest || other.result.ms_per_step < cheapest->result.ms_per_step))
            cheapest = &other;
    }
    return cheapest;
}

void printTable(const std::vector<Point>& points) {
    std::printf(
        "| engine             | iterations | ms/step  | largest gap, px | most added, px  | beaten by          |\n");
    std::printf(
        "| ---                | ---        | ---      | ---             | ---             | ---                |\n");
    for (const Point& point : points) {
        char beaten[64] = "-";
        if (const Point* other = beatenBy(point, points))
            std::snprintf(beaten, sizeof beaten, "%s, %d", other->engine.c_str(), other->iterations);
        std::printf("| %-18s | %10d | %8.3f | %15.2f | %15.2f | %-18s |\n", point.engine.c_str(), point.iterations,
                    point.result.ms_per_step, point.result.largest_gap, point.result.most_added, beaten);
    }
    int stage_points = 0, stage_beaten = 0, box2d_points = 0, box2d_beaten = 0;
    for (const Point& point : points) {
        const bool stage = point.engine.starts_with("5.9");
        (stage ? stage_points : box2d_points) += 1;
        if (beatenBy(point, points)) (stage ? stage_beaten : box2d_beaten) += 1;
    }
    std::printf("\n5.9: %d of %d points beaten by Box2D 2.4; Box2D 2.4: %d of %d beaten by 5.9\n", stage_beaten,
                stage_points, box2d_beaten, box2d_points);
}

}  // namespace

int main(int argc, char** argv) {
    // No arguments: every scene. "--only NAME": that scene alone, so that a profiler
    // sees one scene's step (and nothing is timed that was not asked for).
    std::string_view only;
    if (argc == 3 && std::string_view(argv[1]) == "--only") only = argv[2];
    const bool known = only.empty() || only == "chain" || only == "bridge" || only == "grid";
    if ((argc != 1 && argc != 3) || (argc == 3 && only.empty()) || !known) {
        std::fprintf(stderr, "joints_bench: takes no arguments, or --only chain|bridge|grid\n");
        return 2;
    }
    const std::optional<GridShape> grid_shape = gridShape();
    if (!grid_shape) {
        std::fprintf(stderr,
                     "joints_bench: GRID is \"side spacing radius gravity\" (2-100, px, px, px/s^2), then "
                     "\"boxes\" or nothing\n");
        return 2;
    }
    // The chain and the bridge are cheap: a sweep, each run timed three times. The grid
    // costs a second a run: a few points, once each.
    struct Plan {
        std::string_view name;
        JointScene scene;
        std::vector<int> iterations;
        std::vector<int> substep_iterations;
        int repeats;
    };
    const std::vector<int> sweep{4, 6, 8, 12, 16, 24, 32};
    for (const Plan& plan : {Plan{"chain", chain(), sweep, {4, 8}, 3}, Plan{"bridge", bridge(), sweep, {4, 8}, 3},
                             Plan{"grid", grid(*grid_shape), {8, 12, 16, 32}, {8}, 1}}) {
        if (!only.empty() && plan.name != only) continue;
        std::printf("\n%s, 10 s at 60 Hz\n\n", plan.scene.name.c_str());
        std::vector<Point> points;
        for (const int iterations : plan.iterations) {
            points.push_back(
                {"5.9", iterations, fastestOf(plan.repeats, [&] { return runStage(plan.scene, iterations); })});
        }
        for (const int iterations : plan.substep_iterations) {
            points.push_back({"5.9, 4 sub-steps", iterations,
                              fastestOf(plan.repeats, [&] { return runStage(plan.scene, iterations, 4); })});
        }
#if BENCH_HAS_BOX2D
        for (const int iterations : plan.iterations) {
            if (std::getenv("STAGE_ONLY")) break;
            points.push_back(
                {"Box2D 2.4", iterations, fastestOf(plan.repeats, [&] { return runBox2d(plan.scene, iterations); })});
        }
#endif
        printTable(points);
#if !BENCH_HAS_BOX2D
        std::printf("(Box2D 2.4 not found: no reference rows)\n");
#endif
    }
    return 0;
}
