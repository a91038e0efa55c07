#include "scene_io.h"

#include <array>
#include <charconv>
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
// How stiff the world's rigid joints are: a spring of at least 0.1 Hz (softer holds
// nothing up), at most 1e4 Hz.
constexpr browser::NumberRule kJointHertzRule{[](double v) { return v == 0.0 || (v >= 0.1 && v <= 1e4); },
                                              "must be 0 (rigid) or a number in [0.1, 1e4] (1/s)"};
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

// 5.9's joints. A joint names its bodies by their places in the body list.
constexpr browser::NumberRule kBodyIndex{
    [](double v) { return v >= 0.0 && v < static_cast<double>(kMaxBodies) && std::floor(v) == v; },
    "must be a whole number in [0, 2499] (a place in the body list)"};
constexpr browser::NumberRule kLength{[](double v) { return v >= 0.0 && v <= 1e6; },
                                      "must be a number of px in [0, 1e6]"};
constexpr browser::NumberRule kDirection{[](double v) { return v >= -1e6 && v <= 1e6; },
                                         "must be a number in [-1e6, 1e6]"};
// A spring stiffer than 1e4 Hz is far past what any step can follow (it is then a rod).
constexpr browser::NumberRule kHertz{[](double v) { return v >= 0.0 && v <= 1e4; },
                                     "must be a number in [0, 1e4] (1/s)"};
constexpr browser::NumberRule kDampingRatio{[](double v) { return v >= 0.0 && v <= 1e4; },
                                            "must be a number in [0, 1e4]"};
constexpr browser::NumberRule kTorque{[](double v) { return v >= 0.0 && v <= 1e12; },
                                      "must be a number in [0, 1e12] (mass px^2/s^2)"};
// A 30 x 30 grid of pins has 1,740 joints; each step solves every one.
constexpr std::size_t kMaxJoints = 5000;
// A rope or a spring with a least length and no most: as long as nothing in a scene
// can ever be (positions stay within 1e6 px).
constexpr double kNoLongest = 1e9;  // px

constexpr std::array<std::pair<std::string_view, JointType>, 4> kJointTypes{{{"revolute", JointType::revolute},
                                                                             {"distance", JointType::distance},
                                                                             {"weld", JointType::weld},
                                                                             {"prismatic", JointType::prismatic}}};

bool given(double value) { return !std::isnan(value); }

// The shortest text that reads back to `value`, for a refusal's "(got ...)".
std::string numberText(double value) {
    std::array<char, 32> text{};
    const auto result = std::to_chars(text.data(), text.data() + text.size(), value);
    return std::string(text.data(), result.ptr);
}

// A joint the body list cannot hold, or whose keys disagree with each other: one line,
// as every refusal of a scene (browser::SceneError).
[[noreturn]] void refuseJoint(std::string_view source, std::size_t k, std::string_view key, std::string_view problem) {
    std::string line(source);
    line.append(": joints[").append(std::to_string(k)).append("]");
    if (!key.empty()) line.append(".").append(key);
    throw browser::SceneError(line.append(": ").append(problem));
}

// What the keys one by one cannot say: the bodies are two of the scene's, a pair of
// limits is a pair in order, a slider's axis has a direction, a damping ratio has a
// spring to damp. And the book's relaxation passes solve no joint.
void checkJoints(const Scene& scene, std::string_view source) {
    if (!scene.joints.empty() && scene.world.solver != SolverKind::sequential_impulse) {
        throw browser::SceneError(std::string(source) +
                                  ": joints: the book's relaxation passes solve no joint; add \"solver\": "
                                  "\"sequential_impulse\" to the world (README.md says why)");
    }
    const double count = static_cast<double>(scene.bodies.size());
    for (std::size_t k = 0; k < scene.joints.size(); ++k) {
        const JointDescription& joint = scene.joints[k];
        for (const auto& [index, key] :
             {std::pair{joint.bodies.x, "bodies[0]"}, std::pair{joint.bodies.y, "bodies[1]"}}) {
            if (index >= count) {
                refuseJoint(source, k, key,
                            "must name one of the scene's " + std::to_string(scene.bodies.size()) + " bodies, 0 to " +
                                numberText(count - 1) + " (got " + numberText(index) + ")");
            }
        }
        if (joint.bodies.x == joint.bodies.y) {
            refuseJoint(source, k, "bodies",
                        "must name two different bodies: a joint of a body with itself holds nothing (got [" +
                            numberText(joint.bodies.x) + ", " + numberText(joint.bodies.y) + "])");
        }
        const auto pair = [&](double lower, double upper, std::string_view lower_key, std::string_view upper_key) {
            if (given(lower) != given(upper)) {
                refuseJoint(source, k, given(lower) ? lower_key : upper_key,
                            std::string("comes with ") + std::string(given(lower) ? upper_key : lower_key) +
                                ": a limit needs both ends");
            }
            if (given(lower) && lower > upper) {
                refuseJoint(source, k, lower_key,
                            "must not be more than " + std::string(upper_key) + " (got " + numberText(lower) + " > " +
                                numberText(upper) + ")");
            }
        };
        pair(joint.lower_angle, joint.upper_angle, "lower_angle", "upper_angle");
        pair(joint.lower_translation, joint.upper_translation, "lower_translation", "upper_translation");
        if (given(joint.motor_speed) && !given(joint.max_motor_torque)) {
            refuseJoint(source, k, "motor_speed", "needs max_motor_torque: a motor with no torque turns nothing");
        }
        if (joint.type == JointType::prismatic && joint.axis == Vec2{}) {
            refuseJoint(source, k, "axis", "must not be [0, 0]: a slider needs a direction (got [0, 0])");
        }
        if (given(joint.min_length) && given(joint.max_length) && joint.min_length > joint.max_length) {
            refuseJoint(source, k, "min_length",
                        "must not be more than max_length (got " + numberText(joint.min_length) + " > " +
                            numberText(joint.max_length) + ")");
        }
        if (given(joint.damping_ratio) && !(given(joint.hertz) && joint.hertz > 0.0)) {
            refuseJoint(source, k, "damping_ratio", "needs hertz > 0: it damps a spring, and a rod is no spring");
        }
    }
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
        {"joint_hertz", world.joint_hertz, kJointHertzRule},
        {"joint_damping_ratio", world.joint_damping_ratio, kDampingRatio},
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

std::vector<browser::SceneKey> jointKeys(JointDescription& joint) {
    using browser::kRequired;
    std::vector<browser::SceneKey> keys{{"bodies", joint.bodies, kBodyIndex, kRequired}};
    switch (joint.type) {
        case JointType::revolute:
            keys.insert(keys.end(), {{"anchor", joint.anchor, kPosition, kRequired},
                                     {"lower_angle", joint.lower_angle, kAngle},
                                     {"upper_angle", joint.upper_angle, kAngle},
                                     {"motor_speed", joint.motor_speed, kTurnRate},
                                     {"max_motor_torque", joint.max_motor_torque, kTorque}});
            break;
        case JointType::weld: keys.push_back({"anchor", joint.anchor, kPosition, kRequired}); break;
        case JointType::prismatic:
            keys.insert(keys.end(), {{"anchor", joint.anchor, kPosition, kRequired},
                                     {"axis", joint.axis, kDirection, kRequired},
                                     {"lower_translation", joint.lower_translation, kPosition},
                                     {"upper_translation", joint.upper_translation, kPosition}});
            break;
        case JointType::distance:
            keys.insert(keys.end(), {{"anchors", joint.anchors, kPosition,
                                      browser::PointsRule{.fewest = 2, .most = 2, .check = {}}, kRequired},
                                     {"length", joint.length, kLength},
                                     {"min_length", joint.min_length, kLength},
                                     {"max_length", joint.max_length, kLength},
                                     {"hertz", joint.hertz, kHertz},
                                     {"damping_ratio", joint.damping_ratio, kDampingRatio}});
            break;
    }
    keys.push_back({"collide_connected", joint.collide_connected});
    return keys;
}

browser::SceneList jointList(std::vector<JointDescription>& joints) {
    std::vector<std::string_view> types;
    for (const auto& [name, type] : kJointTypes) types.push_back(name);
    return {.name = "joints",
            .element = "joint",
            .kind_key = "type",
            .kinds = types,
            .most = kMaxJoints,
            .why_most = "every step solves every one of them",
            .add = [&joints](std::size_t kind) {
                JointDescription& joint = joints.emplace_back();
                joint.type = kJointTypes[kind].second;
                return jointKeys(joint);
            }};
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
    const std::array<browser::SceneList, 2> lists{bodyList(scene.bodies), jointList(scene.joints)};
    browser::read_scene_text(text, source, worldKeys(scene.world), lists);
    checkJoints(scene, source);
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

namespace engine {

void buildScene(Core& core, const Scene& scene) {
    const std::size_t first = core.objectCount();
    buildScene(core, scene.bodies);
    for (const JointDescription& joint : scene.joints) {
        const RigidShape& a = core.object(first + static_cast<std::size_t>(joint.bodies.x));
        const RigidShape& b = core.object(first + static_cast<std::size_t>(joint.bodies.y));
        JointDefinition definition;
        if (joint.type == JointType::distance) {
            definition = linkBetween(a, b, {joint.anchors[0], joint.anchors[1]});
            if (given(joint.length)) definition.length = joint.length;
            if (given(joint.hertz)) definition.hertz = joint.hertz;
            if (given(joint.damping_ratio)) definition.damping_ratio = joint.damping_ratio;
            if (given(joint.min_length) || given(joint.max_length)) {
                // A rope is slack up to its length; a spring with a least length may
                // stretch as far as it likes.
                const double longest = definition.hertz > 0.0 ? kNoLongest : definition.length;
                definition.length_range = JointRange{.lower = given(joint.min_length) ? joint.min_length : 0.0,
                                                     .upper = given(joint.max_length) ? joint.max_length : longest};
            }
        } else {
            definition = pinAt(joint.type, a, b, joint.anchor);
        }
        if (given(joint.lower_angle)) definition.limit = JointRange{joint.lower_angle, joint.upper_angle};
        if (given(joint.lower_translation)) {
            definition.limit = JointRange{joint.lower_translation, joint.upper_translation};
        }
        if (given(joint.max_motor_torque)) {
            definition.motor = JointMotor{.speed = given(joint.motor_speed) ? joint.motor_speed : 0.0,
                                          .max_torque = joint.max_motor_torque};
        }
        // The axis as the scene gives it, in the world; kept in a's frame, to turn with a.
        if (joint.type == JointType::prismatic) definition.local_axis = toBody(joint.axis.normalize(), a.angle());
        definition.collide_connected = joint.collide_connected;
        core.join(definition);
    }
}

}  // namespace engine
