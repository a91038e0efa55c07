#pragma once
// Joints (not in the book: its "Further Exploration" names them, p. 111, "joints (for
// more complex rigid body behavior)", and points to Box2D and Erin Catto). A joint ties
// two bodies together: a pin (revolute), a rod, spring or rope (distance), a weld, or a
// slider (prismatic). Each is a few constraints, equations the positions must keep, such
// as "the two anchors are one point"; and like a contact, each is solved by impulses on
// 5.4's sequential impulse solver (contact_solver.h), in the same iterations, warm
// started from what it applied in the last step.
//
// Soft constraints (Catto, "Soft Constraints", GDC 2011; README.md derives them in px
// and s). A constraint C = 0 that drifted to C != 0 is pulled back as a spring and damper
// would pull it: of frequency f (hertz) and damping ratio zeta. Solved implicitly over
// one step h, that spring gives each impulse three numbers:
//     impulse = -mass_scale * m (Cdot + bias_rate * C) - impulse_scale * total
// where m is the constraint's effective mass and total what the step applied so far. A
// rod or a pin takes the world's joint_hertz (capped at half the step's rate,
// jointHertz) and joint_damping_ratio: stiff, but soft enough that an error is removed
// over a few steps rather than thrown back in one (which would add energy, as
// Baumgarte's bias does); it then holds a load F where its error is F / (m w^2), and no
// positional pass closes that. A distance joint's own "hertz" makes it a real spring:
// the same three numbers, a softer f.
//
// Two bodies a joint joins do not collide with each other (a chain's links overlap at
// their pins), unless it says "collide_connected" (Box2D's collideConnected). A joint
// holds its bodies together in one island (islands.h): they sleep and wake together.

#include <cstddef>
#include <optional>
#include <span>
#include <string_view>
#include <utility>
#include <vector>

#include "rigid_shape.h"
#include "world_settings.h"

namespace engine {

struct SolverBody;  // contact_solver.h: a body's velocities as the solver works on them
class Islands;
class ContactEvents;

enum class JointType { revolute, distance, weld, prismatic };

// A point fixed in a body's frame (px from its centre, as if the body were unturned)
// where it is now that the body has turned by `angle`, and back: a joint's anchors and
// axis, and the mouse joint's grabbed point (mouse_joint.h), are kept in the body's frame.
inline Vec2 toWorld(Vec2 local, double angle) { return local.rotate({}, angle); }
inline Vec2 toBody(Vec2 world, double angle) { return world.rotate({}, -angle); }

// A range a joint keeps between two numbers: an angle (rad), a translation or a length
// (px). Not there: no limit.
struct JointRange {
    double lower = 0.0;
    double upper = 0.0;
};

// A revolute joint's motor: it drives the relative spin toward `speed` (rad/s) with a
// torque of at most `max_torque` (mass px^2 / s^2).
struct JointMotor {
    double speed = 0.0;
    double max_torque = 0.0;
};

// What a joint is: its bodies (by id, rigid_shape.h: the id survives a removal before
// it in the list), where it holds each, and its kind's settings.
struct JointDefinition {
    JointType type = JointType::revolute;
    BodyId body_a = 0;
    BodyId body_b = 0;
    // The anchors in each body's own frame: px from its centre, as if it were unturned.
    Vec2 local_a;
    Vec2 local_b;
    // The angle of b less the angle of a when joined (revolute, weld, prismatic): the
    // joint's angle is measured from there.
    double reference_angle = 0.0;
    Vec2 local_axis;  // prismatic: the slider's direction, a unit vector in a's frame
    // Revolute: the joint's angle; prismatic: the translation along the axis, px.
    std::optional<JointRange> limit;
    std::optional<JointMotor> motor;  // revolute
    // Distance: the length it holds (a rod), or rests at (a spring), px; a spring's
    // frequency (0: a rod, as stiff as the world's joints) and damping ratio; a rope's
    // range (the length may go anywhere in it, and no further).
    double length = 0.0;
    double hertz = 0.0;
    double damping_ratio = 0.0;
    std::optional<JointRange> length_range;
    bool collide_connected = false;
};

// What a joint keeps from step to step: the totals of its impulses in the last step,
// which start the next one (warm starting, as 5.4's contacts).
struct JointImpulses {
    Vec2 point;            // revolute, weld: the pin's
    double across = 0.0;   // prismatic: across the axis
    double angular = 0.0;  // weld, prismatic: the turn held
    double axial = 0.0;    // distance: along the rod or spring
    double lower = 0.0;    // the limit's, each >= 0
    double upper = 0.0;
    double motor = 0.0;
};

struct Joint {
    JointDefinition definition;
    JointImpulses impulses;
    // Whether each side of its limit held it in the last step that solved it while
    // events were kept: a limit event is told when one turns true (Joints::reportLimits).
    bool at_lower = false;
    bool at_upper = false;
};

// The joint that holds `a` and `b` at the world point `anchor` (revolute, weld; a
// prismatic's anchor is where its axis passes), or, for a distance joint, at the world
// points anchors.first on a and anchors.second on b, the bodies where they are now.
JointDefinition pinAt(JointType type, const RigidShape& a, const RigidShape& b, Vec2 anchor);
JointDefinition linkBetween(const RigidShape& a, const RigidShape& b, std::pair<Vec2, Vec2> anchors);

// The two anchors where the bodies hold them now, world px.
std::pair<Vec2, Vec2> anchorsOf(const JointDefinition& joint, const RigidShape& a, const RigidShape& b);
// How far the joint is from what it holds, px: the gap between a pin's or a weld's two
// anchors; a rod's length less the length it holds; how far a rope or a spring is past
// its range (0 inside it); a slider's anchor off its axis. The overlay prints it, the
// tests bound it.
double separationOf(const JointDefinition& joint, const RigidShape& a, const RigidShape& b);
// The joint's angle now (rad; revolute, weld), or its translation along the axis (px;
// prismatic), or its length (px; distance).
double positionOf(const JointDefinition& joint, const RigidShape& a, const RigidShape& b);

// The soft constraint's three numbers for a spring of `hertz` and `damping_ratio` over a
// step of `dt` (README.md derives them).
struct Softness {
    double bias_rate = 0.0;      // 1/s: the share of the error asked back each second
    double mass_scale = 1.0;     // of the effective mass
    double impulse_scale = 0.0;  // of the total so far, taken back each iteration
};
Softness softness(double hertz, double damping_ratio, double dt);
// The stiffness the world's rigid joints get over a step of dt: its joint_hertz, at most
// half the step's rate (Box2D v3's cap; README.md, "Soft constraints"). 0: hard.
double jointHertz(const WorldSettings& world, double dt);

// The world's joints, and their part of the sequential impulse solver's step.
class Joints {
public:
    void add(const Joint& joint);
    // A body leaves the world: its joints go with it.
    void forgetBody(BodyId body);
    const std::vector<Joint>& all() const { return joints_; }
    bool empty() const { return joints_.empty(); }

    // Before the step's contacts: finds each joint's bodies in the list (nullopt: a body
    // gone), joins each pair in one island and wakes a sleeping body joined to an awake
    // one. Returns whether it woke an island.
    bool startStep(ShapeList shapes, Islands& islands);
    // Whether the pair is held by a joint that keeps them from colliding.
    bool keepsApart(BodyId a, BodyId b) const;
    // The joints' part of the solver's step, on its bodies (contact_solver.h).
    void prepare(ShapeList shapes, const std::vector<SolverBody>& bodies, const WorldSettings& world);
    void warmStart(std::vector<SolverBody>& bodies) const;
    void solve(std::vector<SolverBody>& bodies);
    // After the iterations: a body a joint holds leaves them no faster than
    // kFastestHeldSpeed (joints.cpp), a safety net for joints too stiff for the solver.
    void capSpeeds(std::vector<SolverBody>& bodies) const;
    // After the iterations, only while someone reads events: a limit event for each
    // side of a limit that holds now (its total impulse > 0: it stopped the joint from
    // passing within this step) and did not in the step before. Velocities untouched.
    void reportLimits(ShapeList shapes, ContactEvents& events);
    // After the shapes have moved: world.position_iterations passes that move and turn
    // the bodies themselves until each rigid joint's anchors meet again (Box2D 2.4's
    // last step for its joints), with positional correction on and the joints hard
    // (the world's joint_hertz 0: soft joints are left to their springs, joints.cpp). A
    // soft constraint pulls an error back over a few steps; but a link that turns by most
    // of a radian in one step (the end of a whipping chain) leaves its pin by more than
    // any step's pull can keep up with, because the velocities are a straight-line guess
    // at an arc. Each pass trusts its straight step to half a radian of turn (joints.cpp,
    // kLongestTrustedTurn). The passes work on the positions as they are, with no
    // velocity, so they add no energy.
    // Springs and ropes within their range are left as they are.
    void correctPositions(ShapeList shapes, const WorldSettings& world);

    // A body as the positional passes move it: where it is, and how much it answers.
    // It answers center(), angle(), move() and rotate() as a shape does, with the same sums,
    // and turns a point of its own frame into the world's (toWorld) with the cosine and
    // sine of its angle, which it keeps as it turns (rotate, joints.cpp).
    struct Placed {
        Vec2 position;
        double turned = 0.0;
        double inv_mass = 0.0;
        double inv_inertia = 0.0;
        double cosine = 1.0;  // of `turned`
        double sine = 0.0;
        Vec2 center() const { return position; }
        double angle() const { return turned; }
        void move(Vec2 offset) { position = position.add(offset); }
        void rotate(double turn);
        Vec2 toWorld(Vec2 local) const {
            return {local.x * cosine - local.y * sine, local.x * sine + local.y * cosine};
        }
    };
    static Placed placedFrom(const RigidShape& shape);

private:
    // One scalar constraint as the step solves it: its speed is
    //     Cdot = direction . (v_b - v_a) + w_b turn_b - w_a turn_a
    // (an angle's row has no direction and turns of 1), and its total is kept within
    // [lowest, highest]: an equation's anywhere, a limit's >= 0, a motor's within its
    // torque times the step.
    struct Row {
        Vec2 direction;
        double turn_a = 0.0;
        double turn_b = 0.0;
        double mass = 0.0;          // effective mass: 1 / (the speed a unit impulse makes)
        double target_speed = 0.0;  // a motor's; 0 for the rest
        double approach = 0.0;      // a limit's: how fast the joint closed on it at the step's start (-Cdot)
        double bias = 0.0;          // the speed asked for to undo the error, bias_rate * C
        double mass_scale = 1.0;
        double impulse_scale = 0.0;
        double lowest = 0.0;
        double highest = 0.0;
        double JointImpulses::*total = nullptr;  // where the joint keeps its total
    };
    // A pin: two anchors made one point, both directions at once (a 2 x 2 system).
    struct Pin {
        Vec2 arm_a, arm_b;                                         // from each centre to its anchor, world px
        double inverse11 = 0.0, inverse12 = 0.0, inverse22 = 0.0;  // K^-1 (0: nothing answers)
        Vec2 bias;                                                 // bias_rate * the gap between the anchors
        Softness soft;
        bool rigid = false;  // soft is {}: the impulse is K^-1's answer whole
    };
    // A joint as the iterations meet it. Its rows are kept apart (rows_, from first_row
    // on), so that a joint of a pin alone, the commonest, is a small record: the
    // iterations read the joints one after another, and the fewer bytes each takes,
    // the fewer the cache lines they wait for (a chain's step a few % faster than with
    // room for a slider's four rows in every joint).
    struct Prepared {
        std::size_t joint = 0;
        std::size_t a = 0, b = 0;
        std::size_t first_row = 0;
        std::size_t row_count = 0;  // a slider's four at most
        std::optional<Pin> pin;
    };

    std::vector<Joint> joints_;
    // Per joint, this step: the places of its bodies in the list (none: not solved).
    std::vector<std::optional<std::pair<std::size_t, std::size_t>>> places_;
    // The joints that have both bodies, in the order the solver meets them: farthest
    // from a support first (orderFromSupports, joints.cpp), and what it was worked out
    // from, with the walk's lists (kept to reuse their memory).
    void orderFromSupports(ShapeList shapes);
    std::vector<std::size_t> order_;
    std::vector<std::optional<std::pair<std::size_t, std::size_t>>> ordered_places_;
    std::vector<std::pair<bool, bool>> ordered_supports_;
    std::vector<std::size_t> first_joint_, joint_at_, hops_;
    std::vector<Prepared> prepared_;
    std::vector<Row> rows_;
    // Per body in the list, during prepare (the bodies a joint holds, placed_known_) and
    // the positional passes (kept to reuse its memory).
    std::vector<Placed> placed_;
    std::vector<bool> placed_known_;
    // The pairs of body ids (smaller first) of the joints that keep their bodies apart,
    // sorted.
    std::vector<std::pair<BodyId, BodyId>> apart_;
};

// How scene files and refusals spell a joint type.
std::string_view jointTypeName(JointType type);

}  // namespace engine
