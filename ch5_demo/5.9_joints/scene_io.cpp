#include "scene_io.h"

#include <array>
#include <cmath>
#include <optional>
#include <string>

#include "circle.h"
#include "convex_hull.h"
#include "polygon.h"
#include "rectangle.h"

namespace engine {

namespace {

// The rules of the stage's numbers. No number of an accepted scene may make a NaN or
// an infinity. Every quantity a body derives from them is then a plain double: with
// masses in [1e-3, 1e6] and sizes in [0.01, 1e5] px, the inverse mass lies in [1e-6,
// 1e3] and the moment of inertia (m r^2 / 2, m (w^2 + h^2) / 12) in [1e-8, 1e16], its
// inverse in [1e-16, 1e8]: finite and > 0 for every moving body. The ranges are those
// the extremes suite (tests/features/extremes_test.cpp) runs and finds finite: shapes of
// 0.01 px to 1e5 px, masses of 1 against 1e6, speeds up to 1e6 px/s.
constexpr browser::NumberRule kPosition{[](double v) { return v >= -1e6 && v <= 1e6; },
                                        "must be a number in [-1e6, 1e6] (px)"};
constexpr browser::NumberRule kSize{[](double v) { return v >= 0.01 && v <= 1e5; },
                                    "must be a number in [0.01, 1e5] (px)"};
// 0 makes a static body; a moving one needs an inverse mass and inertia to divide by.
constexpr browser::NumberRule kMass{[](double v) { return v == 0.0 || (v >= 1e-3 && v <= 1e6); },
                                    "must be 0 (static) or a number in [1e-3, 1e6]"};
constexpr browser::NumberRule kFriction{[](double v) { return v >= 0.0 && v <= 100.0; },
                                        "must be a number in [0, 100]"};
constexpr browser::NumberRule kAngle{[](double v) { return v >= -1e6 && v <= 1e6; },
                                     "must be a number in [-1e6, 1e6] (rad)"};
constexpr browser::NumberRule kSpeed{[](double v) { return v >= -1e6 && v <= 1e6; },
                                     "must be a number in [-1e6, 1e6] (px/s)"};
constexpr browser::NumberRule kTurnRate{[](double v) { return v >= -1e4 && v <= 1e4; },
                                        "must be a number in [-1e4, 1e4] (rad/s)"};
constexpr browser::NumberRule kAcceleration{[](double v) { return v >= -1e6 && v <= 1e6; },
                                            "must be a number in [-1e6, 1e6] (px/s^2)"};
// One simulated second takes 1/dt steps; below 1e-5 s a short run never ends.
constexpr browser::NumberRule kTimeStep{[](double v) { return v >= 1e-5 && v <= 1.0; },
                                        "must be a number in [1e-5, 1]"};
// A number of loop passes: whole (JSON does not tell 15.0 from 15), and small enough
// that every step still ends soon.
constexpr browser::NumberRule kPassCount{[](double v) { return v >= 0.0 && v <= 1000.0 && std::floor(v) == v; },
                                         "must be a whole number in [0, 1000]"};
// Sub-steps and the solver's velocity sweeps: each runs a share of a step's work again,
// at least once; 1000 keeps a step's work bounded.
constexpr browser::NumberRule kRepeats{[](double v) { return v >= 1.0 && v <= 1000.0 && std::floor(v) == v; },
                                       "must be a whole number in [1, 1000]"};
// A slop of more than a few pixels would let shapes sink visibly; 100 keeps typos out.
constexpr browser::NumberRule kSlopRule{[](double v) { return v >= 0.0 && v <= 100.0; },
                                        "must be a number of px in [0, 100]"};
constexpr browser::NumberRule kSpeedRule{[](double v) { return std::isfinite(v) && v >= 0.0; },
                                         "must be a finite speed >= 0"};
constexpr browser::NumberRule kDurationRule{[](double v) { return std::isfinite(v) && v >= 0.0; },
                                            "must be a finite number of s >= 0"};

// Every step tests every pair of bodies; 2,500 (the bench's largest scene has 2,003)
// take about 650 KB of JSON.
constexpr std::size_t kMaxBodies = 2500;

// The shape types, as scene files and state dumps spell them.
constexpr std::array<std::pair<std::string_view, ShapeType>, 3> kShapes{
    {{"rectangle", ShapeType::Rectangle}, {"circle", ShapeType::Circle}, {"polygon", ShapeType::Polygon}}};

// A polygon's corners, in its own frame: as far out as the largest size (1e5 px), which
// is also as far as the hull builder takes them (convex_hull.h).
constexpr browser::NumberRule kCorner{[](double v) { return v >= -kMaxHullCoordinate && v <= kMaxHullCoordinate; },
                                      "must be a number in [-1e5, 1e5] (px)"};

// What the corners must be together: a convex polygon's, which the hull builder says.
std::optional<std::string> hullRefusal(std::span<const Vec2> corners) {
    HullResult hull = convexHull(corners);
    if (hull.hull) return std::nullopt;
    return std::move(hull.refusal);
}

// 5.9: what a kinematic body cannot be at once. Mass 0 says static, which does not move
// at all; a bullet is swept to its impacts, which never stop a kinematic body.
std::optional<std::string> kinematicRefusal(const BodyDescription& body) {
    if (!body.kinematic) return std::nullopt;
    if (body.mass == 0.0) return "kinematic and static (mass 0) at once: a kinematic body moves by its velocity";
    if (body.bullet) return "kinematic and a bullet at once: nothing stops a kinematic body, so it is never swept";
    return std::nullopt;
}

RigidShape& addBody(Core& core, const BodyDescription& body) {
    const PhysicalAttributes attributes{.mass = body.mass, .friction = body.friction, .restitution = body.restitution};
    switch (body.shape) {
        case ShapeType::Circle: return core.add(Circle(body.center, body.radius, attributes));
        case ShapeType::Polygon: return core.add(Polygon(body.center, body.vertices, attributes));
        case ShapeType::Rectangle: break;
    }
    return core.add(Rectangle(body.center, body.width, body.height, attributes));
}

}  // namespace

std::vector<browser::SceneKey> worldKeys(WorldSettings& world) {
    return {
        {"width", world.width, browser::rules::kCanvasSize},
        {"height", world.height, browser::rules::kCanvasSize},
        {"gravity", world.gravity, kAcceleration},
        {"dt", world.dt, kTimeStep},
        {"movement", world.movement},
        {"relaxation_iterations", world.relaxation_iterations, kPassCount},
        {"correction_rate", world.correction_rate, browser::rules::kFraction},
        {"positional_correction", world.positional_correction},
        {"remove_out_of_bounds", world.remove_out_of_bounds},
        {"broad_phase",
         world.broad_phase,
         {{"bounding_circle", BroadPhaseKind::bounding_circle},
          {"all_pairs", BroadPhaseKind::all_pairs},
          {"grid", BroadPhaseKind::grid}}},
        {"substeps", world.substeps, kRepeats},
        {"integrator",
         world.integrator,
         {{"symplectic", Integrator::symplectic}, {"explicit", Integrator::explicit_euler}}},
        {"friction_model", world.friction_model, {{"book", FrictionModel::book}, {"coulomb", FrictionModel::coulomb}}},
        {"rotation", world.rotation},
        {"friction", world.friction},
        {"solver", world.solver, {{"book", SolverKind::book}, {"sequential_impulse", SolverKind::sequential_impulse}}},
        {"velocity_iterations", world.velocity_iterations, kRepeats},
        {"position_iterations", world.position_iterations, kPassCount},
        {"warm_starting", world.warm_starting},
        {"restitution_threshold", world.restitution_threshold, kSpeedRule},
        {"position_method",
         world.position_method,
         {{"split_impulse", PositionMethod::split_impulse},
          {"baumgarte", PositionMethod::baumgarte},
          {"relax", PositionMethod::relax}}},
        {"position_rate", world.position_rate, browser::rules::kFraction},
        {"slop", world.slop, kSlopRule},
        {"sleep", world.sleep},
        {"sleep_speed", world.sleep_speed, kSpeedRule},
        {"time_to_sleep", world.time_to_sleep, kDurationRule},
        {"continuous", world.continuous},
    };
}

std::vector<browser::SceneKey> bodyKeys(BodyDescription& body) {
    using browser::kRequired;
    std::vector<browser::SceneKey> keys{{"center", body.center, kPosition, kRequired}};
    if (body.shape == ShapeType::Rectangle) {
        keys.push_back({"width", body.width, kSize, kRequired});
        keys.push_back({"height", body.height, kSize, kRequired});
    } else if (body.shape == ShapeType::Polygon) {
        keys.push_back({"vertices", body.vertices, kCorner,
                        browser::PointsRule{.fewest = 3, .most = kMaxPolygonVertices, .check = hullRefusal},
                        kRequired});
    } else {
        keys.push_back({"radius", body.radius, kSize, kRequired});
    }
    keys.insert(keys.end(), {{"mass", body.mass, kMass},
                             {"friction", body.friction, kFriction},
                             {"restitution", body.restitution, browser::rules::kFraction},
                             {"angle", body.angle, kAngle},
                             {"velocity", body.velocity, kSpeed},
                             {"angular_velocity", body.angular_velocity, kTurnRate},
                             {"bullet", body.bullet},
                             {"sensor", body.sensor},
                             {"kinematic", body.kinematic}});
    return keys;
}

std::string_view shapeName(ShapeType type) {
    for (const auto& [name, shape] : kShapes) {
        if (shape == type) return name;
    }
    return {};
}

browser::SceneList bodyList(std::vector<BodyDescription>& bodies) {
    std::vector<std::string_view> shapes;
    for (const auto& [name, type] : kShapes) shapes.push_back(name);
    return {.name = "bodies",
            .element = "body",
            .kind_key = "shape",
            .kinds = shapes,
            .most = kMaxBodies,
            .why_most = "every step tests every pair of them",
            .add = [&bodies](std::size_t kind) {
                BodyDescription& body = bodies.emplace_back();
                body.shape = kShapes[kind].second;
                return bodyKeys(body);
            }};
}

Scene readScene(const std::string& text, std::string_view source) {
    Scene scene;
    const browser::SceneList bodies = bodyList(scene.bodies);
    browser::read_scene_text(text, source, worldKeys(scene.world), {&bodies, 1});
    for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
        if (const std::optional<std::string> problem = kinematicRefusal(scene.bodies[i])) {
            throw browser::SceneError(std::string(source) + ": bodies[" + std::to_string(i) + "]: " + *problem);
        }
    }
    return scene;
}

Scene loadScene(const std::filesystem::path& file) { return readScene(browser::scene_text(file), file.string()); }

std::pair<double, double> canvasOf(const Scene* scene) {
    const WorldSettings& world = scene ? scene->world : kBookWorld;
    return {world.width, world.height};
}

void buildScene(Core& core, const std::vector<BodyDescription>& bodies) {
    for (const BodyDescription& body : bodies) {
        RigidShape& shape = addBody(core, body);
        shape.rotate(body.angle);
        shape.setVelocity(body.velocity);
        shape.setAngularVelocity(body.angular_velocity);
        shape.setBullet(body.bullet);
        shape.setSensor(body.sensor);
        if (body.kinematic) shape.makeKinematic();
    }
}

}  // namespace engine
