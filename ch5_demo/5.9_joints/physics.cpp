#include "physics.h"

#include <algorithm>

namespace engine {

namespace {

// Moves the two shapes apart along the normal by `rate` of their overlap, shared in
// proportion to their inverse masses: a shape twice as heavy moves half as far, a
// static one not at all, and the pair's centre of mass stays where it was. The moves
// are added to `response` when the overlay keeps one.
void positionalCorrection(RigidShape& a, RigidShape& b, const CollisionInfo& info, double rate,
                          PairResponse* response) {
    const double amount = info.depth() / (a.invMass() + b.invMass()) * rate;
    const Vec2 correction = info.normal() * amount;  // the normal points from a to b
    a.move(correction * -a.invMass());
    b.move(correction * b.invMass());
    if (!response) return;
    response->moved_first += correction * -a.invMass();
    response->moved_second += correction * b.invMass();
}

// Where the pair touches, seen from each shape's centre: the lever arms r of Figure
// 4-10, through which an impulse also turns the shape.
struct LeverArms {
    Vec2 a;
    Vec2 b;
};

// The book takes one contact point between start and end, weighted by the inverse
// masses, and measures the arms from the centres as they are now, after this pair's
// positional correction (docs/errata.md, "... lever arms from before the correction").
LeverArms leverArms(const RigidShape& a, const RigidShape& b, const CollisionInfo& info) {
    const double inv_mass_sum = a.invMass() + b.invMass();
    const Vec2 contact = info.start() * (b.invMass() / inv_mass_sum) + info.end() * (a.invMass() / inv_mass_sum);
    return {contact - a.center(), contact - b.center()};
}

// The velocity of the shape's point at `arm` from its centre (Figure 4-9): the
// centre's velocity plus w x r, which for a turn w about the z axis is (-w r.y, w r.x).
Vec2 velocityAt(const RigidShape& shape, Vec2 arm) {
    const double w = shape.angularVelocity();
    return shape.velocity() + Vec2{-w * arm.y, w * arm.x};
}

// How much a unit impulse along `direction` at the contact changes the pair's relative
// velocity along it: the denominator of Equations 5 and 6. 1/m for moving each shape,
// (r x d)^2 / I for turning it.
double impulseResponse(const RigidShape& a, const RigidShape& b, const LeverArms& arms, Vec2 direction) {
    const double turn_a = arms.a.cross(direction);
    const double turn_b = arms.b.cross(direction);
    return a.invMass() + b.invMass() + turn_a * turn_a * a.invInertia() + turn_b * turn_b * b.invInertia();
}

// An impulse is a sudden change of momentum, j = m dv: it changes the velocity of a
// shape by j / m, and, acting at the arm r, its angular velocity by (r x j) / I.
// Newton's third law: `b` gets `impulse` and `a` the same impulse turned round.
void applyImpulse(RigidShape& a, RigidShape& b, const LeverArms& arms, Vec2 impulse) {
    a.setVelocity(a.velocity() - impulse * a.invMass());
    b.setVelocity(b.velocity() + impulse * b.invMass());
    a.setAngularVelocity(a.angularVelocity() - arms.a.cross(impulse) * a.invInertia());
    b.setAngularVelocity(b.angularVelocity() + arms.b.cross(impulse) * b.invInertia());
}

// The tangent impulse that friction applies. `sliding` is the contact's speed along the
// tangent, which points against the slide (so sliding <= 0), and -sliding / response
// is the impulse that would stop the slide. The book's "simplistic" model scales that
// by (1 + e) mu and caps it at jN; Coulomb's law takes it as it is, but never more than
// mu jN: a contact pressed together by jN can hold at most mu jN sideways.
double frictionImpulse(double sliding, double response, double jN, double restitution, double friction,
                       FrictionModel model) {
    if (model == FrictionModel::coulomb) return std::min(-sliding / response, friction * jN);
    const double jT = -(1 + restitution) * sliding * friction / response;
    return std::min(jT, jN);  // friction never pushes harder than the collision itself
}

// The unit tangent against the sliding part of `velocity`: what is left of it off the
// normal. A head-on hit leaves nothing there but rounding noise, some 1e-16 of the
// speed, in any direction; normalized, it would become a whole unit vector, and
// friction would push along it, even along the normal (docs/errata.md, "Friction from
// rounding noise"). Sliding under 1e-9 of the speed is no sliding: no tangent.
constexpr double kNoSliding = 1e-9;

Vec2 againstTheSliding(Vec2 velocity, Vec2 normal) {
    const Vec2 sliding = velocity - normal * velocity.dot(normal);
    if (sliding.length() <= kNoSliding * velocity.length()) return {};
    return sliding.normalize() * -1;
}

// What a collision does to the pair: push them apart, then change their velocities by
// the impulse method, with rotation (Equations 4 to 6). Along the normal, the impulse
// jN makes the contact points separate at e times the speed they met with (Newton's
// law of restitution at the contact, Equation 4). Along the tangent, friction takes
// away part of the sliding (see frictionImpulse; docs/errata.md, "Friction"). Never
// called for two static shapes: 1/mA + 1/mB = 0 would make every share below 0 / 0.
// What it did goes into `response`, the overlay's record of the pair (nullptr while
// the overlay keeps none).
void resolveCollision(RigidShape& a, RigidShape& b, const CollisionInfo& info, const WorldSettings& world,
                      PairResponse* response) {
    if (world.positional_correction) positionalCorrection(a, b, info, world.correction_rate, response);

    const Vec2 normal = info.normal();  // from a to b
    // Without rotation the impulses act as if through the centres: zero lever arms drop
    // every angular term (w x r, (r x d)^2 / I, r x j) and leave the rest as it is.
    const LeverArms arms = world.rotation ? leverArms(a, b, info) : LeverArms{};
    if (response) {
        response->contact = a.center() + arms.a;
        response->arm_first = arms.a;
        response->arm_second = arms.b;
    }
    const Vec2 relative_velocity = velocityAt(b, arms.b) - velocityAt(a, arms.a);
    const double normal_speed = relative_velocity.dot(normal);
    // Moving apart already: the velocities need no help. (The positions above were
    // corrected even so, in every relaxation pass.)
    if (normal_speed > 0) return;

    // The less bouncy and the less grippy of the two surfaces decide.
    const double restitution = std::min(a.restitution(), b.restitution());
    const double friction = std::min(a.friction(), b.friction());

    // Equation 5: after the impulse the contact's normal speed is -e times what it was.
    const double jN = -(1 + restitution) * normal_speed / impulseResponse(a, b, arms, normal);
    const double spin_a = a.angularVelocity(), spin_b = b.angularVelocity();
    applyImpulse(a, b, arms, normal * jN);
    if (response) response->normal_impulse += normal * jN;
    if (world.friction) {
        // Equation 6. The book takes the tangent, and the sliding, from the velocity before
        // the normal impulse. But that impulse has turned the shapes, and so changed the
        // sliding: stopping a slide that is no longer there can speed the contact up and
        // create energy (docs/errata.md, "Friction from the velocity before the bounce").
        // The Coulomb model measures the sliding after the normal impulse, as it is when
        // friction acts; an impulse that at most stops it can only take energy away.
        const Vec2 sliding_velocity = world.friction_model == FrictionModel::coulomb
                                          ? velocityAt(b, arms.b) - velocityAt(a, arms.a)
                                          : relative_velocity;
        const Vec2 tangent = againstTheSliding(sliding_velocity, normal);
        const double jT = frictionImpulse(sliding_velocity.dot(tangent), impulseResponse(a, b, arms, tangent), jN,
                                          restitution, friction, world.friction_model);
        applyImpulse(a, b, arms, tangent * jT);
        if (response) response->tangent_impulse += tangent * jT;
    }
    if (response) {
        response->spin_first += a.angularVelocity() - spin_a;
        response->spin_second += b.angularVelocity() - spin_b;
    }
}

}  // namespace

void Physics::keepResponses(bool keep) {
    keep_responses_ = keep;
    if (!keep) responses_.clear();
}

PairResponse* Physics::responseOf(PairKey pair) { return keep_responses_ ? &responses_[pair] : nullptr; }

void Physics::collision(ShapeList shapes, const WorldSettings& world, MouseJoint* mouse) {
    collisions_.clear();
    responses_.clear();
    if (world.broad_phase != broad_phase_.kind()) broad_phase_ = BroadPhase(world.broad_phase);
    islands_.startStep(shapes);
    if (world.solver == SolverKind::sequential_impulse) {
        return contact_solver_.step(shapes, broad_phase_, islands_, events_, joints_, world, collisions_, mouse);
    }
    broad_phase_.startStep(shapes, world.relaxation_iterations);
    for (int pass = 0; pass < world.relaxation_iterations; ++pass) {
        // The record keeps what the last pass found.
        const bool last_pass = pass + 1 == world.relaxation_iterations;
        // Every pair is resolved as soon as it is found, so the pairs after it already
        // see the shapes where that correction left them. The broad phase walks each
        // row's partners in ascending order, so pairs are met in the book's order
        // whichever it is.
        const bool changed = broad_phase_.pass([&](std::size_t i, std::size_t j) {
            RigidShape& a = *shapes[i];
            RigidShape& b = *shapes[j];
            // Nothing moves two static shapes lying in each other, nor two sleeping ones,
            // nor a sleeping one on a static one: the pair changes nothing, and is not
            // even tested. Nothing draws the record from 4.3 on: it keeps the pairs the
            // resolution works on, for the tests, and leaves such a pair out.
            if (a.isResting() && b.isResting()) return false;
            // 5.9: nor a kinematic shape and a static or kinematic one, both of infinite
            // mass: nothing could move either.
            if (!a.isDynamic() && !b.isDynamic()) return false;
            const std::optional<CollisionInfo> info = narrowPhase(a, b);
            if (!info) return false;
            // A sensor only tells what overlaps it (rigid_shape.h): no response, no island.
            if (a.isSensor() || b.isSensor()) {
                events_.sensed(a, b, *info);
                return false;
            }
            if (islands_.touching(shapes, i, j, info->depth())) broad_phase_.noteResting();
            events_.touching(a, b, *info);
            if (last_pass) collisions_.push_back({i, j, *info});
            resolveCollision(a, b, *info, world, responseOf({i, j}));
            return true;
        });
        // The book runs every pass. But a pass that changed nothing left every shape's
        // position and velocity as it found them, and a pass reads nothing else: the
        // next pass would meet the same pairs in the same state, find the same
        // collisions, all of two static shapes, and change nothing either; and so on to
        // the last, whose record would hold none of them. So the step's passes end here,
        // with the record as empty as the last pass would have left it.
        if (!changed) break;
    }
}

}  // namespace engine
