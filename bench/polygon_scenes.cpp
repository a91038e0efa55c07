// 5.8's polygon scenes beside Box2D 2.4 (ch5_demo/5.8_convex_polygons/README.md, "Beside
// Box2D 2.4"): the same bodies in both engines, the cost of a step and the bench's error
// measures (README.md here, "The figures"):
//   - polygon_rain.json (80 polygons of 3 to 8 corners on a floor between walls), 10 s:
//     the deepest and the mean overlap of two shapes at the end;
//   - hexagons.json (a pyramid of 21 hexagons) and 5.4's pyramid of 20 rows with its
//     210 boxes given as polygons (and as the book's rectangles, 5.8 only, for the
//     ratio build/polygons_bench prints): 1 + 10 s, the top's drift over the 10 s and
//     the overlaps at the end;
//   - slope.json (one triangle at friction 0.5, 0.2 and 0 on a 20-degree slope of
//     friction 1), 2 s: how far each slid against Coulomb's g (sin a - mu cos a) t^2 / 2.
// 5.8 runs each scene as its file says (sleep and continuous collision on), and again
// with both off, as Box2D runs: sleeping and continuous collision off, 8 velocity and 3
// position iterations, 30 px to the metre (box2d_world.h). Box2D is given 5.8's own
// polygons (their centre of area on the body's centre), cores pulled in by its skin
// b2_polygonRadius so that they are the scene's size where they touch, the density that
// gives each body the scene's mass, and the smaller friction and restitution of a pair
// (5.8's rule) through a contact listener. Overlaps are worked out by the tests' own
// separating axes (tests/stages/s5_8/random_convex.h), not by either engine.
//
//   build/polygon_scenes
//
// Linked with stage 5.8's engine alone (namespace engine), as ccd_study is with 5.6's.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#if BENCH_HAS_BOX2D
#include <box2d/box2d.h>
#endif

#include "boxes_as_polygons.h"
#include "browser.h"
#include "core.h"
#include "polygon.h"
#include "random_convex.h"
#include "rectangle.h"
#include "scene_io.h"
#include "thread_clock.h"

namespace {

using engine::Vec2;

constexpr double kPixelsPerMetre = 30.0;

// A body as the measures see it: its corners where it stands (counter-clockwise for the
// tests' separating axes), and whether it is static.
struct Body {
    std::vector<Vec2> corners;
    bool is_static = false;
};

// Its corners in its own frame, about its centre, unturned, as 5.8 built it.
std::vector<Vec2> localCorners(const engine::RigidShape& shape) {
    std::vector<Vec2> corners;
    if (shape.type() == engine::ShapeType::Polygon) {
        const engine::ConvexPolygon& body = static_cast<const engine::Polygon&>(shape).bodyOutline();
        corners.assign(body.vertices.begin(), body.vertices.begin() + static_cast<long>(body.count));
    } else if (shape.type() == engine::ShapeType::Rectangle) {
        const auto& box = static_cast<const engine::Rectangle&>(shape);
        corners = test::boxCorners(box.width(), box.height());
    }
    double area = 0.0;
    for (std::size_t i = 0; i < corners.size(); ++i) area += corners[i].cross(corners[(i + 1) % corners.size()]);
    if (area < 0.0) std::reverse(corners.begin(), corners.end());
    return corners;
}

std::vector<Vec2> placed(const std::vector<Vec2>& local, Vec2 center, double angle) {
    std::vector<Vec2> corners;
    for (Vec2 p : local) corners.push_back(center + p.rotate(Vec2{}, angle));
    return corners;
}

struct Overlaps {
    double deepest = 0.0, mean = 0.0;
};

Overlaps overlapsOf(const std::vector<Body>& bodies) {
    Overlaps overlaps;
    int count = 0;
    for (std::size_t i = 0; i < bodies.size(); ++i) {
        for (std::size_t j = i + 1; j < bodies.size(); ++j) {
            if (bodies[i].is_static && bodies[j].is_static) continue;
            const double depth = test::exactPenetration(bodies[i].corners, bodies[j].corners).depth;
            if (depth <= 0.0) continue;
            overlaps.deepest = std::max(overlaps.deepest, depth);
            overlaps.mean += depth;
            ++count;
        }
    }
    if (count > 0) overlaps.mean /= count;
    return overlaps;
}

// What a run measured.
struct Result {
    double us_per_step = 0.0;
    Overlaps overlaps;
    std::optional<double> top_drift;  // px
    std::vector<double> slid;         // px along the slope, per dynamic body
};

// How a scene is run and measured, engine aside.
struct Plan {
    double settle_s = 0.0;  // untimed, then the top is noted (the pyramids)
    double run_s = 0.0;     // timed
    bool drift = false;
    bool slope = false;
};

// The top: the dynamic body highest on the canvas (least y).
std::size_t topOf(const std::vector<Vec2>& centers, const std::vector<bool>& is_static) {
    std::size_t top = 0;
    double least = 1e300;
    for (std::size_t i = 0; i < centers.size(); ++i) {
        if (!is_static[i] && centers[i].y < least) {
            least = centers[i].y;
            top = i;
        }
    }
    return top;
}

// The slope's direction, down it: from the static body's angle.
Vec2 downSlope(double angle) { return Vec2{std::cos(angle), std::sin(angle)}; }

Result run58(const engine::Scene& scene, const Plan& plan) {
    browser::Window window(scene.world.dt * 1000.0);
    engine::Core core(window, scene.world);
    engine::buildScene(core, scene.bodies);
    const auto centers = [&core] {
        std::vector<Vec2> c;
        for (std::size_t i = 0; i < core.objectCount(); ++i) c.push_back(core.object(i).center());
        return c;
    };
    std::vector<bool> is_static;
    for (std::size_t i = 0; i < core.objectCount(); ++i) is_static.push_back(core.object(i).isStatic());
    const int settle = static_cast<int>(std::lround(plan.settle_s / scene.world.dt));
    const int steps = static_cast<int>(std::lround(plan.run_s / scene.world.dt));
    for (int i = 0; i < settle; ++i) core.update();
    const std::vector<Vec2> before = centers();
    const double start = bench::thread_cpu_seconds();
    for (int i = 0; i < steps; ++i) core.update();
    Result result{.us_per_step = (bench::thread_cpu_seconds() - start) * 1e6 / steps};
    const std::vector<Vec2> after = centers();
    if (plan.drift) {
        const std::size_t top = topOf(before, is_static);
        result.top_drift = after[top].distance(before[top]);
    }
    std::vector<Body> bodies;
    for (std::size_t i = 0; i < core.objectCount(); ++i) {
        const engine::RigidShape& shape = core.object(i);
        bodies.push_back({placed(localCorners(shape), shape.center(), shape.angle()), shape.isStatic()});
        if (plan.slope && !shape.isStatic()) {
            result.slid.push_back((after[i] - before[i]).dot(downSlope(core.object(0).angle())));
        }
    }
    result.overlaps = overlapsOf(bodies);
    return result;
}

#if BENCH_HAS_BOX2D
b2Vec2 metres(Vec2 px) {
    return {static_cast<float>(px.x / kPixelsPerMetre), static_cast<float>(px.y / kPixelsPerMetre)};
}
Vec2 pixels(b2Vec2 m) { return Vec2{m.x, m.y} * kPixelsPerMetre; }

// 5.8's rule for a pair: the smaller friction and restitution (Box2D's own: sqrt(f1 f2)
// and the larger restitution).
class SmallerOfPair final : public b2ContactListener {
    void PreSolve(b2Contact* contact, const b2Manifold*) override {
        const b2Fixture* a = contact->GetFixtureA();
        const b2Fixture* b = contact->GetFixtureB();
        contact->SetFriction(std::min(a->GetFriction(), b->GetFriction()));
        contact->SetRestitution(std::min(a->GetRestitution(), b->GetRestitution()));
    }
};

// A polygon's corners pulled in by Box2D's skin: every side moves in by the skin, so the
// rounded core is the scene's outline where it touches.
std::vector<b2Vec2> coreCorners(const std::vector<Vec2>& local) {
    const std::size_t n = local.size();
    const double skin = b2_polygonRadius * kPixelsPerMetre;
    std::vector<b2Vec2> core;
    for (std::size_t i = 0; i < n; ++i) {
        const Vec2 to_next = (local[(i + 1) % n] - local[i]).normalize();
        const Vec2 to_previous = (local[(i + n - 1) % n] - local[i]).normalize();
        core.push_back(metres(local[i] + (to_next + to_previous) * (skin / std::abs(to_next.cross(to_previous)))));
    }
    return core;
}

Result runBox2d(const engine::Scene& scene, const Plan& plan) {
    // The bodies as 5.8 builds them: their corners about their centre of area.
    browser::Window window(scene.world.dt * 1000.0);
    engine::Core built(window, scene.world);
    engine::buildScene(built, scene.bodies);
    b2World world(metres(scene.world.gravity));
    world.SetContinuousPhysics(false);
    world.SetAllowSleeping(false);
    SmallerOfPair smaller;
    world.SetContactListener(&smaller);
    std::vector<b2Body*> bodies;
    std::vector<std::vector<Vec2>> locals;
    std::vector<bool> is_static;
    for (std::size_t i = 0; i < built.objectCount(); ++i) {
        const engine::RigidShape& shape = built.object(i);
        b2BodyDef definition;
        definition.type = shape.isStatic() ? b2_staticBody : b2_dynamicBody;
        definition.position = metres(shape.center());
        definition.angle = static_cast<float>(shape.angle());
        definition.linearVelocity = metres(shape.velocity());
        definition.angularVelocity = static_cast<float>(shape.angularVelocity());
        b2Body* body = world.CreateBody(&definition);
        locals.push_back(localCorners(shape));
        const std::vector<b2Vec2> core = coreCorners(locals.back());
        b2PolygonShape polygon;
        polygon.Set(core.data(), static_cast<int32>(core.size()));
        double area = 0.0;  // m^2, of the core Box2D weighs
        for (std::size_t k = 0; k < core.size(); ++k) area += b2Cross(core[k], core[(k + 1) % core.size()]) / 2;
        b2FixtureDef fixture;
        fixture.shape = &polygon;
        fixture.density = shape.isStatic() ? 0.0f : static_cast<float>(shape.mass() / std::abs(area));
        fixture.friction = static_cast<float>(shape.friction());
        fixture.restitution = static_cast<float>(shape.restitution());
        body->CreateFixture(&fixture);
        bodies.push_back(body);
        is_static.push_back(shape.isStatic());
    }
    const auto centers = [&bodies] {
        std::vector<Vec2> c;
        for (const b2Body* body : bodies) c.push_back(pixels(body->GetPosition()));
        return c;
    };
    const float dt = static_cast<float>(scene.world.dt);
    const int settle = static_cast<int>(std::lround(plan.settle_s / scene.world.dt));
    const int steps = static_cast<int>(std::lround(plan.run_s / scene.world.dt));
    for (int i = 0; i < settle; ++i) world.Step(dt, 8, 3);
    const std::vector<Vec2> before = centers();
    const double start = bench::thread_cpu_seconds();
    for (int i = 0; i < steps; ++i) world.Step(dt, 8, 3);
    Result result{.us_per_step = (bench::thread_cpu_seconds() - start) * 1e6 / steps};
    const std::vector<Vec2> after = centers();
    if (plan.drift) {
        const std::size_t top = topOf(before, is_static);
        result.top_drift = after[top].distance(before[top]);
    }
    std::vector<Body> measured;
    for (std::size_t i = 0; i < bodies.size(); ++i) {
        measured.push_back({placed(locals[i], after[i], bodies[i]->GetAngle()), is_static[i]});
        if (plan.slope && !is_static[i]) {
            result.slid.push_back((after[i] - before[i]).dot(downSlope(bodies[0]->GetAngle())));
        }
    }
    result.overlaps = overlapsOf(measured);
    return result;
}
#endif

std::string figures(const Result& result, const Plan& plan, const std::vector<double>& exact_slide) {
    char text[256];
    std::string row;
    std::snprintf(text, sizeof text, " %.0f | %.3f | %.3f |", result.us_per_step, result.overlaps.deepest,
                  result.overlaps.mean);
    row += text;
    if (plan.drift) {
        std::snprintf(text, sizeof text, " %.3f |", *result.top_drift);
        row += text;
    }
    if (plan.slope) {
        for (std::size_t i = 0; i < result.slid.size(); ++i) {
            std::snprintf(text, sizeof text, " %.1f (%.1f) |", result.slid[i], exact_slide[i]);
            row += text;
        }
    }
    return row;
}

void study(const std::string& title, const engine::Scene& scene, const Plan& plan,
           const std::vector<double>& exact_slide = {}) {
    std::printf("\n%s\n\n| engine | us a step | deepest overlap px | mean overlap px |%s%s\n", title.c_str(),
                plan.drift ? " top's drift px |" : "", plan.slope ? " slid px (Coulomb), mu 0.5 | 0.2 | 0 |" : "");
    std::printf("|---|---|---|---|%s%s\n", plan.drift ? "---|" : "", plan.slope ? "---|---|---|" : "");
    std::printf("| 5.8, the scene's world |%s\n", figures(run58(scene, plan), plan, exact_slide).c_str());
    engine::Scene plain = scene;
    plain.world.sleep = false;
    plain.world.continuous = false;
    std::printf("| 5.8, sleep and continuous off |%s\n", figures(run58(plain, plan), plan, exact_slide).c_str());
#if BENCH_HAS_BOX2D
    std::printf("| Box2D 2.4 |%s\n", figures(runBox2d(scene, plan), plan, exact_slide).c_str());
#endif
}

engine::Scene load(const char* name) { return engine::loadScene(std::filesystem::path(STAGE_FOLDER) / name); }

}  // namespace

int main(int argc, char**) {
    if (argc > 1) {
        std::fprintf(stderr, "polygon_scenes: takes no arguments (its settings are constants in the source)\n");
        return 2;
    }
#if !BENCH_HAS_BOX2D
    std::printf("Box2D 2.4 not found (Debian: libbox2d-dev): no reference row\n");
#endif
    const double started = bench::thread_cpu_seconds();
    study("polygon_rain.json: 80 polygons of 3 to 8 corners, 10 s", load("polygon_rain.json"), {.run_s = 10});
    const Plan pyramid{.settle_s = 1, .run_s = 10, .drift = true};
    study("hexagons.json: a pyramid of 21 hexagons, 1 + 10 s", load("hexagons.json"), pyramid);
    engine::Scene boxes = load("pyramid.json");
    test::boxesAsPolygons(boxes);
    for (const engine::SolverKind solver : {engine::SolverKind::book, engine::SolverKind::sequential_impulse}) {
        const char* name = solver == engine::SolverKind::book ? "book's passes" : "sequential impulse";
        engine::Scene rectangles = load("pyramid.json");
        rectangles.world.solver = solver;
        boxes.world.solver = solver;
        study(std::string("pyramid.json, 210 boxes as polygons, 5.8 on the ") + name + ", 1 + 10 s", boxes, pyramid);
        std::printf("| 5.8, the same as rectangles |%s\n", figures(run58(rectangles, pyramid), pyramid, {}).c_str());
    }
    // The slope: 2 s from rest. Coulomb: s = g (sin a - mu cos a) t^2 / 2 where tan a > mu,
    // else 0; mu the smaller of the triangle's and the slope's (1).
    const engine::Scene slope = load("slope.json");
    const double angle = slope.bodies[0].angle, g = slope.world.gravity.y, t = 2.0;
    std::vector<double> exact;
    for (const engine::BodyDescription& body : slope.bodies) {
        if (body.mass == 0.0) continue;
        const double mu = std::min(body.friction, slope.bodies[0].friction);
        exact.push_back(std::max(0.0, g * (std::sin(angle) - mu * std::cos(angle))) * t * t / 2);
    }
    study("slope.json: a triangle at friction 0.5, 0.2 and 0 on a 20-degree slope, 2 s", slope,
          {.run_s = t, .slope = true}, exact);
    std::printf("\n(%.0f s of processor time)\n", bench::thread_cpu_seconds() - started);
    return 0;
}
