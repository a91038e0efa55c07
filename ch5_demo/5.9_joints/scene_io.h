#pragma once
// Scene files (--scene FILE): the stage's vocabulary, the words a scene may use, each
// bound to the setting or the member it fills, and the world built from a scene. Not in
// the book: a reader changes the scene without recompiling (docs/scene_format.md). The
// browser reads the JSON and reports every problem in one format (scene_file.h); the
// words, their rules and their defaults are the stage's, written here once.

#include <filesystem>
#include <limits>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "core.h"
#include "joints.h"
#include "scene_file.h"
#include "stage_main.h"
#include "world_settings.h"

namespace engine {

// One body of a scene file, as its keys describe it (bodyKeys).
struct BodyDescription {
    ShapeType shape = ShapeType::Rectangle;
    Vec2 center;
    double width = 0.0;   // rectangles only
    double height = 0.0;  // rectangles only
    double radius = 0.0;  // circles only
    // Polygons only (5.8): the corners in the body's frame, px from its centre; the
    // polygon is their convex hull, its centre of area put on `center` (polygon.h).
    std::vector<Vec2> vertices;
    double mass = 1.0;  // 0 makes the body static
    double friction = 0.8;
    double restitution = 0.2;
    double angle = 0.0;  // rad, applied after construction as the book's rotate(angle)
    Vec2 velocity;
    double angular_velocity = 0.0;  // rad/s
    // A bullet is also swept against moving shapes, not only static ones (continuous.h).
    bool bullet = false;
    // A sensor feels overlaps and tells them as events, with no response (contact_events.h).
    bool sensor = false;
    // 5.9: a kinematic body moves by its velocity and angular velocity alone, with
    // infinite mass (rigid_shape.h). Refused with mass 0 (static) or as a bullet.
    bool kinematic = false;

    friend bool operator==(const BodyDescription&, const BodyDescription&) = default;
};

// 5.9: one joint of a scene file, as its keys describe it (jointKeys; joints.h). A
// number left out is kNotGiven (no file can give a NaN: every rule refuses it).
inline constexpr double kNotGiven = std::numeric_limits<double>::quiet_NaN();
struct JointDescription {
    JointType type = JointType::revolute;
    Vec2 bodies;                     // the two bodies' places in the scene's body list, as read
    Vec2 anchor;                     // revolute, weld, prismatic: world px at the start
    std::vector<Vec2> anchors;       // distance: one on each body, world px at the start
    Vec2 axis;                       // prismatic
    double lower_angle = kNotGiven;  // revolute, rad
    double upper_angle = kNotGiven;
    double motor_speed = kNotGiven;  // revolute, rad/s
    double max_motor_torque = kNotGiven;
    double lower_translation = kNotGiven;  // prismatic, px
    double upper_translation = kNotGiven;
    double length = kNotGiven;  // distance, px
    double min_length = kNotGiven;
    double max_length = kNotGiven;
    double hertz = kNotGiven;  // distance: a spring
    double damping_ratio = kNotGiven;
    bool collide_connected = false;
};

// The world keys the stage reads, bound to `world`: one for each of its settings.
std::vector<browser::SceneKey> worldKeys(WorldSettings& world);
// The keys a body of `body.shape` takes, bound to `body`, in the order refusals list them.
std::vector<browser::SceneKey> bodyKeys(BodyDescription& body);
// The "bodies" list of a scene: each element a body of one of the shapes, read into
// `bodies` in file order.
browser::SceneList bodyList(std::vector<BodyDescription>& bodies);
// The keys a joint of `joint.type` takes, and the "joints" list (5.9).
std::vector<browser::SceneKey> jointKeys(JointDescription& joint);
browser::SceneList jointList(std::vector<JointDescription>& joints);
// How scene files and state dumps spell a shape type: "rectangle", "circle".
std::string_view shapeName(ShapeType type);

// A scene file, read with the stage's keys: the book's world where the file says
// nothing, and the file's bodies. Throws browser::SceneError with one line.
struct Scene {
    WorldSettings world = kBookWorld;
    std::vector<BodyDescription> bodies;
    std::vector<JointDescription> joints;  // 5.9
};
Scene loadScene(const std::filesystem::path& file);
// The same for a scene that is already text; `source` stands for the file in a refusal.
Scene readScene(const std::string& text, std::string_view source);

// The canvas a scene's world asks for, px (nullptr: the book's).
std::pair<double, double> canvasOf(const Scene* scene);
// What the stage program needs to read scene files (common/stage_main.h).
inline constexpr browser::SceneFiles<Scene> kSceneFiles{.load = loadScene, .canvas = canvasOf};

// Adds the bodies of a scene file, in file order (object 0 is the first body), in
// place of the book's MyGame scene. Each is built as the book builds a shape, then
// turned with rotate(angle) and set moving with its velocity and angular velocity; a
// body with "bullet": true becomes a bullet (continuous.h), one with "sensor": true a
// sensor (rigid_shape.h), one with "kinematic": true kinematic (rigid_shape.h).
void buildScene(Core& core, const std::vector<BodyDescription>& bodies);
// 5.9: the bodies, then the joints between them (joints.h), each anchored where the
// bodies stand once built and turned.
void buildScene(Core& core, const Scene& scene);

}  // namespace engine
