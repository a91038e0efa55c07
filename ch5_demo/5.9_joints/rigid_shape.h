#pragma once
// RigidShape: what every simulated object has, whatever its outline (the book's
// RigidBody/RigidShape.js). Rectangle and Circle build on it, and from 5.8 Polygon.
//
// Why a class hierarchy: the book builds Rectangle and Circle on a RigidShape
// prototype, and the engine walks one list of shapes calling draw, update, move and
// rotate without asking which kind each one is. A base class with virtual functions
// says exactly that, so every chapter's change lands in the same file as in the book.
// Where the two kinds must be told apart (the collision tests of chapter 3), type()
// plays the role of the book's mType. The Core owns its shapes through unique_ptr.
//
// The broad phase of collision detection (Figure 3-4): every shape is wrapped in a
// bounding circle about its centre, and two shapes can only touch when their bounding
// circles do. That test costs one distance, whatever the shapes are.
//
// The narrow phase, collisionTest, is exact, and its answer depends on both kinds of
// shape: each kind implements it in its own file (circle_collision.cpp,
// rectangle_collision.cpp) and asks the other shape's type() which test applies.
//
// Chapter 4 gives every shape what Newton's laws need: a velocity and an angular
// velocity that update() integrates, and the attributes the collision response will
// use (mass, rotational inertia, friction, restitution).

#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <stdexcept>
#include <string_view>

#include "canvas.h"
#include "collision_info.h"
#include "world_settings.h"
#include "vec2.h"

namespace engine {

using lib::Vec2;

enum class ShapeType { Rectangle, Circle, Polygon };

// What a wake does to a shape's rest timer (RigidShape::wake).
enum class RestTimer { starts_again, goes_on };

// Where a shape stands with sleeping (islands.h): asleep or not, how long it has rested,
// and which island it last belonged to.
struct SleepState {
    bool asleep = false;
    double rested_s = 0.0;
    double speed = 0.0;       // px/s, its sleep speed in the last step it was awake
    bool held = false;        // it touched something in the last step
    Vec2 rest_center;         // where it was, and how it was turned, when its rest began
    double rest_angle = 0.0;  // (or when the last window of its rest began)
    double noted_at_s = 0.0;  // s: the rest time at which they were noted
    std::uint64_t island = 0;
};

// What a new shape is made of. Mass 0 means "infinitely heavy": a static body that
// nothing moves, such as the borders and platforms.
struct PhysicalAttributes {
    double mass = 1.0;         // the book's defaults
    double friction = 0.8;     // how strongly surfaces grip when they slide (4.3)
    double restitution = 0.2;  // bounciness: 0 sticks, 1 bounces back at full speed (4.3)
};

// A shape that cannot be simulated: a NaN or infinite number, a size <= 0, a negative
// mass or friction, a restitution outside [0, 1]. what() is one line naming the shape,
// the value and the rule, e.g. "circle radius must be a finite number > 0 (got -2)".
struct InvalidShape : std::invalid_argument {
    using std::invalid_argument::invalid_argument;
};

// Who a body is, from 5.4 on, where state first outlives a step: the number the world
// gives a shape when it takes it in (Core::add), from a counter of its own that never
// goes back, so no two shapes of a world ever share one. A shape removed and a new one
// made after it are told apart by it, though the new one may take the old one's place
// in the list, and even its very address: the allocator hands freed memory out again.
// What is kept from one step to the next (warm starting, contact_solver.h) names
// shapes by id, never by place or address.
using BodyId = std::uint64_t;

class RigidShape {
public:
    virtual ~RigidShape() = default;

    // The shape's id in its world (BodyId above); 0 until a world takes it in.
    BodyId id() const { return id_; }
    ShapeType type() const { return type_; }
    Vec2 center() const { return center_; }
    double angle() const { return angle_; }  // radians; turns clockwise on screen (y down)

    // Radius of the smallest circle about the centre that holds the whole shape.
    double boundRadius() const { return bound_radius_; }
    // True when the two bounding circles overlap or touch: the shapes *may* collide.
    bool boundTest(const RigidShape& other) const;
    // The exact test: the collision info when the two shapes overlap, nothing when not.
    virtual std::optional<CollisionInfo> collisionTest(const RigidShape& other) const = 0;

    virtual void move(Vec2 offset) = 0;
    // Turns the shape about its centre by `angle` radians (clockwise on screen).
    virtual void rotate(double angle) = 0;
    // One step of world.dt (a fixed step, or one sub-step of it) of motion, while the
    // world's movement flag is on, by the world's integrator.
    void update(const WorldSettings& world);

    virtual void draw(browser::Canvas& context) const = 0;

    Vec2 velocity() const { return velocity_; }  // px/s
    void setVelocity(Vec2 velocity) { velocity_ = velocity; }
    double angularVelocity() const { return angular_velocity_; }  // rad/s
    void setAngularVelocity(double w) { angular_velocity_ = w; }

    // The engine divides by mass far more often than it multiplies, so it keeps 1/m.
    // A static body's 1/m is 0: no impulse and no gravity changes its velocity.
    double invMass() const { return inv_mass_; }
    bool isStatic() const { return inv_mass_ == 0.0 && !kinematic_; }
    double mass() const { return inv_mass_ == 0.0 ? 0.0 : 1.0 / inv_mass_; }
    // Adds `delta` to the mass. A mass that drops to 0 or below makes the body static
    // and stops it dead; otherwise 1/m is stored again. Either way the rotational
    // inertia follows the new mass.
    void updateMass(double delta);
    // 1/I, the rotational counterpart of 1/m; 0 for a static body.
    double invInertia() const { return inv_inertia_; }

    // 5.9: a kinematic body (a moving platform, a turntable) moves by its velocity and
    // angular velocity and by nothing else. Its mass is infinite, 1/m = 1/I = 0, as a
    // static body's: no impulse and no gravity changes how it moves (the velocity keys
    // do), and it pushes whatever is in its way. Unlike a static body it moves, so what rests on it
    // is carried by friction (README.md, "Kinematic bodies"). isDynamic(): the
    // shapes that forces and impulses move, neither static nor kinematic.
    bool isKinematic() const { return kinematic_; }
    void makeKinematic();
    bool isDynamic() const { return inv_mass_ != 0.0; }

    // A sleeping shape stays where it is and at rest: no step moves it until it wakes.
    const SleepState& sleep() const { return sleep_; }
    // A kinematic body that stands still rests as a static one does (5.9).
    bool isResting() const {
        return isStatic() || sleep_.asleep || (kinematic_ && velocity_ == Vec2{} && angular_velocity_ == 0.0);
    }
    void fallAsleep(std::uint64_t island);
    // Wakes the shape. Its rest starts again from 0 when something changed it or its
    // world (a key, a removal, a setting); it goes on where it stopped when an awake
    // shape only reached its island, which has not moved since it fell asleep
    // (islands.h).
    void wake(RestTimer timer = RestTimer::starts_again) {
        sleep_.asleep = false;
        if (timer == RestTimer::starts_again) sleep_.rested_s = 0.0;
    }
    // Adds dt to the rest timer while `resting`, and starts it again from 0 when not;
    // `held`: the shape touched something in this step. Where the shape stands is noted
    // when its rest begins, and again each `window` of rest, so that its drift is
    // measured over the last window at most.
    void rest(bool resting, bool held, double speed, double dt, double window) {
        if (resting && (sleep_.rested_s == 0.0 || sleep_.rested_s - sleep_.noted_at_s >= window)) {
            sleep_.rest_center = center_;
            sleep_.rest_angle = angle_;
            sleep_.noted_at_s = sleep_.rested_s;
        }
        sleep_.rested_s = resting ? sleep_.rested_s + dt : 0.0;
        sleep_.held = held;
        sleep_.speed = speed;
    }
    void joinIsland(std::uint64_t island) { sleep_.island = island; }

    // A bullet (continuous.h) is swept against moving shapes too, when it is fast; any
    // other fast shape only against static ones.
    bool isBullet() const { return bullet_; }
    void setBullet(bool bullet) { bullet_ = bullet; }

    // A sensor (5.7, contact_events.h) feels what overlaps it and tells it as events,
    // but takes no part in the collision: nothing bounces off it, is pushed out of it or
    // rests on it, and it holds no island together. Zones, triggers and goals are sensors.
    bool isSensor() const { return sensor_; }
    void setSensor(bool sensor) { sensor_ = sensor; }

    double friction() const { return friction_; }
    void setFriction(double friction) { friction_ = friction; }
    double restitution() const { return restitution_; }
    void setRestitution(double restitution) { restitution_ = restitution; }

protected:
    // Throws InvalidShape when the centre or an attribute cannot be simulated. A NaN
    // let in here would spread through every collision the shape takes part in, and a
    // negative mass would make impulses push the wrong way, so both stop at the door.
    RigidShape(ShapeType type, Vec2 center, double bound_radius, PhysicalAttributes attributes);
    // `size` itself when it is a finite number > 0; otherwise throws InvalidShape naming
    // it (e.g. "rectangle width"). Each shape checks its sizes with it before using them.
    static double checkedSize(double size, std::string_view name);
    RigidShape(const RigidShape&) = default;
    RigidShape& operator=(const RigidShape&) = default;

    // The moment of inertia about the centre of this outline with mass `mass`:
    // I = sum of m r^2 over the body, which only the shape itself can work out.
    virtual double rotationalInertia(double mass) const = 0;
    // Stores 1/I for the current mass. Each shape's constructor calls it once its size
    // is known (a base class constructor cannot reach the shape's own formula yet).
    void updateInertia();

    friend class Core;  // only the world gives out ids, once for each shape it takes in
    BodyId id_ = 0;
    ShapeType type_;
    Vec2 center_;
    double angle_ = 0.0;
    double bound_radius_;

    Vec2 velocity_;
    double angular_velocity_ = 0.0;
    double inv_mass_;
    double inv_inertia_ = 0.0;
    double friction_;
    double restitution_;
    SleepState sleep_;
    bool bullet_ = false;
    bool sensor_ = false;
    bool kinematic_ = false;
};

// The world's shapes, as the core keeps them and the physics and its broad phase walk
// them (5.1 keeps this in physics.h; from 5.2 the broad phase needs it too, below the
// physics).
using ShapeList = std::span<const std::unique_ptr<RigidShape>>;

}  // namespace engine
