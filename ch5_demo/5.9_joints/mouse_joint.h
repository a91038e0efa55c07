#pragma once
// The mouse joint (not in the book: every engine's testbed has one, and the book teaches
// by play). A press on a shape that moves grabs it at the point pressed; while the
// button is held, a soft point constraint pulls that point of the shape toward the
// pointer; the release lets it go. The shape is pulled, not placed: it still collides,
// turns about the grabbed point, and can be held back by what it is stuck under.
//
// Soft, as in Erin Catto's "Soft Constraints" (GDC 2011), and derived in README.md ("The
// mouse"): the constraint C = p - target (p the grabbed point, px) is made to behave as
// a spring of frequency kHertz and damping ratio kDampingRatio on the shape's own mass,
// solved implicitly, so it cannot blow up however stiff. Per step h, with m the shape's
// mass, w = 2 pi kHertz, k = m w^2 and c = 2 m kDampingRatio w:
//     gamma = 1 / (h (c + h k)),  beta = h k / (c + h k)
//     impulse P = -(K + gamma 1)^-1 (v_p + beta C / h),   |P| <= kMaxPullAcceleration m h
// where v_p is the grabbed point's velocity and K the 2 x 2 matrix of how a unit impulse
// at the point changes v_p (1/m and the turning r x P / I). The pull is capped at a force
// in proportion to the mass, so a drag lifts a shape and what rests on it briskly but
// cannot fling a pile through the floor.
//
// Where it acts. On 5.4's sequential impulses, as Box2D solves its mouse joint: in the
// velocity iterations, after the joints and before the contacts, its total over the
// step kept, capped and warm started as theirs are (P above is then the change of the
// total, and the gamma term counts the total already given). So the pull and the
// contacts answer each other in one step: a shape dragged into the floor stops at the
// floor, and a box lifted with another on it moves both as the spring would move their
// two masses (README.md works it out). On the book's passes, which
// keep no totals, once each (sub-)step before the collisions, as a force would: solved
// alone the constraint is exact for the shape by itself, and the passes then correct
// what it did (README.md).

#include <optional>
#include <vector>

#include "canvas.h"
#include "rigid_shape.h"
#include "world_settings.h"

namespace engine {

struct SolverBody;  // contact_solver.h: a body's velocities as the solver works on them

class MouseJoint {
public:
    // The testbeds' softness: a pull that settles in about a fifth of a second, barely
    // overshooting.
    static constexpr double kHertz = 5.0;
    static constexpr double kDampingRatio = 0.7;
    // The most the pull may accelerate the shape by, px/s^2. Box2D's testbed allows
    // 1000 m/s^2 in a world some 40 m across: 25 widths a second squared, which on the
    // book's 800 px canvas is 20,000 px/s^2 (1000 times the book's gravity). Less, and a
    // drag across the canvas overshoots: the cap that speeds the shape up also limits
    // how hard the spring can stop it at the pointer.
    static constexpr double kMaxPullAcceleration = 20000.0;
    // The grabbed shape's spin is damped at this rate, per second: each (sub-)step divides
    // it by 1 + h kSpinDamping, 1.02 at 1/60 s, so a spin falls to 0.98 of itself a step,
    // to 30 % in a second. The pull acts at one point, so it turns the shape about it
    // as a pendulum, and the spring, damped along its line, does nothing against the
    // swing: held off its centre, a shape would swing on and on. Box2D 2.4's mouse joint
    // takes the same 2 % from the spin in each of its 1/60 s steps; as a rate, the damping
    // is the same whatever the step or the sub-steps.
    static constexpr double kSpinDamping = 1.2;  // 1/s

    // Grabs the shape at `point` that forces move (not a static or kinematic one), the
    // one drawn last where several overlap there; returns its place in the list, or
    // nothing when there is none.
    std::optional<std::size_t> grab(ShapeList shapes, Vec2 point);
    void moveTo(Vec2 target) { target_ = target; }
    void release() {
        body_ = 0;
        step_.reset();
        total_ = {};
    }
    bool holding() const { return body_ != 0; }
    BodyId body() const { return body_; }
    Vec2 target() const { return target_; }
    // The grabbed point where it is now, on the shape `shape` (the grabbed one).
    Vec2 grabbedPoint(const RigidShape& shape) const;

    // The book's passes: one (sub-)step's pull, before the collisions: changes the
    // grabbed shape's velocity and angular velocity. Lets go when the shape has left the
    // world; does nothing to a sleeping shape (the pointer's moves wake it, core.cpp).
    void apply(ShapeList shapes, const WorldSettings& world);

    // The sequential impulses (contact_solver.cpp), on the solver's velocities, which hold
    // the step's gravity already: prepare once a (sub-)step, after the joints are
    // prepared (the spring's numbers, the spin's damping, and with warm starting the last
    // step's total given again); then solve in every iteration, after the joints.
    void prepare(ShapeList shapes, std::vector<SolverBody>& bodies, const WorldSettings& world);
    void solve(std::vector<SolverBody>& bodies);

    // A line from the grabbed point to the pointer, and a dot at each end, in this colour
    // (the overlay's legend names it, joints_overlay.h).
    static constexpr browser::Color kLineColor = browser::colors::kOrange;
    void draw(browser::Canvas& context, ShapeList shapes) const;

private:
    // What a step's pull needs, worked out once a (sub-)step from where the shape is.
    struct Step {
        std::size_t index = 0;                   // the held shape's place in the list
        Vec2 arm;                                // from its centre to the grabbed point, px
        Vec2 bias;                               // beta C / h, px/s: the speed that closes the error
        double gamma = 0.0;                      // the softness, s/kg
        double k11 = 0.0, k12 = 0.0, k22 = 0.0;  // K + gamma 1, symmetric
        double most = 0.0;                       // the largest total pull of the step, kMaxPullAcceleration m h
    };
    // Finds the held shape and works out step_; false (and nothing held, if the shape
    // has gone or become static) when there is nothing to pull this step.
    bool begin(ShapeList shapes, const WorldSettings& world);
    // One solve on the held shape's velocities: the change of the total that the soft
    // constraint asks for, the total capped, the change applied.
    void solveOn(SolverBody& body);

    BodyId body_ = 0;    // 0: nothing held
    Vec2 local_anchor_;  // the grabbed point in the shape's frame: px from its centre, unturned
    Vec2 target_;        // where the pointer is, px
    std::optional<Step> step_;
    Vec2 total_;  // the pull given over the step so far; the next step starts from it
};

}  // namespace engine
