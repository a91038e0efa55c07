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

// An impulse is a sudden change of momentum, j = m dv: it changes the velocity of a
// shape by j / m (here j times the inverse mass). Newton's third law: `b` gets `impulse`
// and `a` the same impulse turned round.
void applyImpulse(RigidShape& a, RigidShape& b, Vec2 impulse) {
    a.setVelocity(a.velocity() - impulse * a.invMass());
    b.setVelocity(b.velocity() + impulse * b.invMass());
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
// the impulse method. Along the normal, the impulse jN makes the pair separate at e
// times the speed it met with (Newton's law of restitution, Equation 1). Along the
// tangent, friction takes away part of the sliding; the book's "simplistic" model
// scales the impulse that would stop the slide by (1 + e) mu and caps it at jN
// (Equation 3, not Coulomb's |jT| <= mu jN; see docs/errata.md).
// What it did goes into `response`, the overlay's record of the pair (nullptr while
// the overlay keeps none).
void resolveCollision(RigidShape& a, RigidShape& b, const CollisionInfo& info, const WorldSettings& world,
                      PairResponse* response) {
    // Nothing moves two static shapes: 1/mA + 1/mB = 0, and every share below is 0 / 0.
    if (a.isStatic() && b.isStatic()) return;
    if (world.positional_correction) positionalCorrection(a, b, info, world.correction_rate, response);
    if (response) response->contact = (info.start() + info.end()) * 0.5;

    const Vec2 normal = info.normal();  // from a to b
    const Vec2 relative_velocity = b.velocity() - a.velocity();
    const double normal_speed = relative_velocity.dot(normal);
    // Moving apart already: the velocities need no help. (The positions above were
    // corrected even so, in every relaxation pass.)
    if (normal_speed > 0) return;

    // The less bouncy and the less grippy of the two surfaces decide.
    const double restitution = std::min(a.restitution(), b.restitution());
    const double friction = std::min(a.friction(), b.friction());
    const double inv_mass_sum = a.invMass() + b.invMass();

    // Equation 2: after the impulse the normal speed is -e times what it was.
    const double jN = -(1 + restitution) * normal_speed / inv_mass_sum;
    applyImpulse(a, b, normal * jN);
    if (response) response->normal_impulse += normal * jN;

    // The tangent points against the sliding, from the velocity before the impulse.
    const Vec2 tangent = againstTheSliding(relative_velocity, normal);
    double jT = -(1 + restitution) * relative_velocity.dot(tangent) * friction / inv_mass_sum;
    jT = std::min(jT, jN);  // friction never pushes harder than the collision itself
    applyImpulse(a, b, tangent * jT);
    if (response) response->tangent_impulse += tangent * jT;
}

}  // namespace

std::optional<CollisionInfo> findCollision(const RigidShape& a, const RigidShape& b) {
    if (!a.boundTest(b)) return std::nullopt;
    std::optional<CollisionInfo> info = a.collisionTest(b);
    // A normal with a negative component along the line between the centres points
    // from b towards a.
    if (info && info->normal().dot(b.center() - a.center()) < 0) info->changeDir();
    return info;
}

void Physics::keepResponses(bool keep) {
    keep_responses_ = keep;
    if (!keep) responses_.clear();
}

PairResponse* Physics::responseOf(PairKey pair) { return keep_responses_ ? &responses_[pair] : nullptr; }

void Physics::collision(ShapeList shapes, const WorldSettings& world) {
    collisions_.clear();
    responses_.clear();
    for (int pass = 0; pass < world.relaxation_iterations; ++pass) relaxationPass(shapes, world);
}

// Every pair is resolved as soon as it is found, so the pairs after it already see the
// shapes where that correction left them.
void Physics::relaxationPass(ShapeList shapes, const WorldSettings& world) {
    collisions_.clear();
    for (std::size_t i = 0; i < shapes.size(); ++i) {
        for (std::size_t j = i + 1; j < shapes.size(); ++j) {
            RigidShape& a = *shapes[i];
            RigidShape& b = *shapes[j];
            const std::optional<CollisionInfo> info = findCollision(a, b);
            if (!info) continue;
            // Nothing draws the record from 4.3 on: it keeps the pairs the resolution
            // works on, for the tests, so two static shapes lying in each other are
            // left out of it.
            if (!(a.isStatic() && b.isStatic())) collisions_.push_back({i, j, *info});
            resolveCollision(a, b, *info, world, responseOf({i, j}));
        }
    }
}

}  // namespace engine
