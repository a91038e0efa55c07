#include "contact_solver.h"

#include <algorithm>
#include <numeric>

#include "physics.h"

namespace engine {

namespace {

// An impulse j at the point: b's motion changes by j / m and (r x j) / I, and a's by
// the same turned round (Newton's third law). `motion` picks the real or the pseudo one.
void push(SolverBody& a, SolverBody& b, Vec2 arm_a, Vec2 arm_b, Vec2 impulse, Motion SolverBody::*motion) {
    (a.*motion).linear -= impulse * a.inv_mass;
    (a.*motion).angular -= arm_a.cross(impulse) * a.inv_inertia;
    (b.*motion).linear += impulse * b.inv_mass;
    (b.*motion).angular += arm_b.cross(impulse) * b.inv_inertia;
}

// How fast the point on b moves away from the point on a, along `direction`.
double speedAlong(const Motion& a, const Motion& b, Vec2 arm_a, Vec2 arm_b, Vec2 direction) {
    return (b.at(arm_b) - a.at(arm_a)).dot(direction);
}

// 1 / (the change of the pair's relative speed along `direction` that one unit of
// impulse at the point makes): 1/m for moving each shape, (r x d)^2 / I for turning it.
// This "effective mass" turns a wrong speed into the impulse that puts it right:
// impulse = effective mass * (wanted speed - speed).
double effectiveMass(double inv_mass_sum, double inv_inertia_a, double inv_inertia_b, Vec2 arm_a, Vec2 arm_b,
                     Vec2 direction) {
    const double turn_a = arm_a.cross(direction);
    const double turn_b = arm_b.cross(direction);
    const double response = inv_mass_sum + turn_a * turn_a * inv_inertia_a + turn_b * turn_b * inv_inertia_b;
    return response > 0 ? 1.0 / response : 0.0;
}

}  // namespace

std::size_t ContactSolver::pointCount() const {
    return std::accumulate(contacts_.begin(), contacts_.end(), std::size_t{0},
                           [](std::size_t sum, const Contact& contact) { return sum + contact.points.size(); });
}

void ContactSolver::step(ShapeList shapes, BroadPhase& broad_phase, const WorldSettings& world,
                         std::vector<Collision>& found) {
    findContacts(shapes, broad_phase, world, found);
    prepare(shapes, world);
    if (world.warm_starting) warmStart();
    solveVelocities(world);
    if (world.positional_correction && world.position_method == PositionMethod::split_impulse) {
        solvePositions(shapes, world);
    }
    for (std::size_t i = 0; i < shapes.size(); ++i) {
        if (shapes[i]->isStatic()) continue;
        shapes[i]->setVelocity(bodies_[i].velocity.linear);
        shapes[i]->setAngularVelocity(bodies_[i].velocity.angular);
    }
}

// One look at every pair the broad phase hands out (nothing moves while it looks), and
// for each pair that overlaps its contact points, each matched by key with the points
// of the same pair in the last step.
void ContactSolver::findContacts(ShapeList shapes, BroadPhase& broad_phase, const WorldSettings& world,
                                 std::vector<Collision>& found) {
    last_.swap(contacts_);
    contacts_.clear();
    last_index_.clear();
    for (std::size_t k = 0; k < last_.size(); ++k) last_index_[{last_[k].shape_a, last_[k].shape_b}] = k;
    persisted_ = 0;

    broad_phase.startStep(shapes);
    broad_phase.pass([&](std::size_t i, std::size_t j) {
        const RigidShape& a = *shapes[i];
        const RigidShape& b = *shapes[j];
        if (a.isStatic() && b.isStatic()) return false;
        const std::optional<CollisionInfo> info = narrowPhase(a, b);
        if (!info) return false;
        found.push_back({i, j, *info});
        ContactManifold manifold = contactManifold(a, b, *info);
        Contact contact{.a = i,
                        .b = j,
                        .shape_a = &a,
                        .shape_b = &b,
                        .normal = manifold.normal,
                        .tangent = {manifold.normal.y, -manifold.normal.x},
                        .friction = world.friction ? std::min(a.friction(), b.friction()) : 0.0,
                        .restitution = std::min(a.restitution(), b.restitution()),
                        .points = {}};
        const auto last = last_index_.find({&a, &b});
        for (const ContactPoint& point : manifold.points) {
            Point solved{.contact = point};
            if (last != last_index_.end()) {
                for (const Point& before : last_[last->second].points) {
                    if (before.contact.key != point.key) continue;
                    solved.normal_impulse = before.normal_impulse;
                    solved.tangent_impulse = before.tangent_impulse;
                    ++persisted_;
                }
            }
            contact.points.push_back(solved);
        }
        contacts_.push_back(std::move(contact));
        return false;  // nothing has moved yet
    });
}

// What stays the same over the step's iterations: the arms, the effective masses and
// the speeds to aim at, worked out from the velocities the step starts with.
void ContactSolver::prepare(ShapeList shapes, const WorldSettings& world) {
    bodies_.resize(shapes.size());
    for (std::size_t i = 0; i < shapes.size(); ++i) {
        const RigidShape& shape = *shapes[i];
        bodies_[i] = SolverBody{.velocity = {shape.velocity(), shape.angularVelocity()},
                                .pseudo = {},
                                .inv_mass = shape.invMass(),
                                .inv_inertia = world.rotation ? shape.invInertia() : 0.0};
    }
    for (Contact& contact : contacts_) {
        const SolverBody& a = bodies_[contact.a];
        const SolverBody& b = bodies_[contact.b];
        const double inv_mass_sum = a.inv_mass + b.inv_mass;
        for (Point& point : contact.points) {
            // Without rotation the impulses act as through the centres: zero arms.
            point.arm_a = world.rotation ? point.contact.position - shapes[contact.a]->center() : Vec2{};
            point.arm_b = world.rotation ? point.contact.position - shapes[contact.b]->center() : Vec2{};
            point.normal_mass =
                effectiveMass(inv_mass_sum, a.inv_inertia, b.inv_inertia, point.arm_a, point.arm_b, contact.normal);
            point.tangent_mass =
                effectiveMass(inv_mass_sum, a.inv_inertia, b.inv_inertia, point.arm_a, point.arm_b, contact.tangent);

            // Newton's law of restitution asks the point to leave at e times the speed
            // it came in with; but only a real impact, faster than the threshold. The
            // approach gravity adds in one step (g dt, a third of a px/s here) would
            // otherwise bounce back each step, and nothing would ever rest.
            const double approach = speedAlong(a.velocity, b.velocity, point.arm_a, point.arm_b, contact.normal);
            point.target_speed = approach < -world.restitution_threshold ? -contact.restitution * approach : 0.0;

            // The overlap past the slop, to be removed at position_rate of it per step:
            // as a speed that lasts one step, it is rate * excess / dt.
            const double excess = std::max(point.contact.depth - world.slop, 0.0);
            const double removal_speed = world.positional_correction ? world.position_rate * excess / world.dt : 0.0;
            if (world.position_method == PositionMethod::baumgarte) {
                point.target_speed = std::max(point.target_speed, removal_speed);
            } else {
                point.split_speed = removal_speed;
            }
        }
    }
}

// The totals carried over from the last step, applied before the first iteration.
void ContactSolver::warmStart() {
    for (Contact& contact : contacts_) {
        for (const Point& point : contact.points) {
            const Vec2 impulse = contact.normal * point.normal_impulse + contact.tangent * point.tangent_impulse;
            push(bodies_[contact.a], bodies_[contact.b], point.arm_a, point.arm_b, impulse, &SolverBody::velocity);
        }
    }
}

// Gauss-Seidel over the contact points: each point in turn gets the impulse that puts
// its own speed right, as the others' impulses have left it; repeated, the impulses
// settle on values that suit all the points together.
void ContactSolver::solveVelocities(const WorldSettings& world) {
    for (int iteration = 0; iteration < world.velocity_iterations; ++iteration) {
        for (Contact& contact : contacts_) {
            SolverBody& a = bodies_[contact.a];
            SolverBody& b = bodies_[contact.b];
            // Friction first, within the cone of the normal totals as they stand: the
            // normal impulses below, solved last, are then the ones the iteration ends on.
            for (Point& point : contact.points) {
                const double sliding = speedAlong(a.velocity, b.velocity, point.arm_a, point.arm_b, contact.tangent);
                const double limit = contact.friction * point.normal_impulse;
                const double total = std::clamp(point.tangent_impulse - point.tangent_mass * sliding, -limit, limit);
                push(a, b, point.arm_a, point.arm_b, contact.tangent * (total - point.tangent_impulse),
                     &SolverBody::velocity);
                point.tangent_impulse = total;
            }
            for (Point& point : contact.points) {
                const double speed = speedAlong(a.velocity, b.velocity, point.arm_a, point.arm_b, contact.normal);
                const double total = std::max(point.normal_impulse + point.normal_mass * (point.target_speed - speed), 0.0);
                push(a, b, point.arm_a, point.arm_b, contact.normal * (total - point.normal_impulse),
                     &SolverBody::velocity);
                point.normal_impulse = total;
            }
        }
    }
}

// Split impulses: the overlap is removed by pseudo velocities, solved as the real ones
// are (effective masses, totals never below 0), that move the shapes once and are then
// dropped. The real velocities never see them, so removing overlap adds no energy: a
// box pushed out of the floor does not fly up.
void ContactSolver::solvePositions(ShapeList shapes, const WorldSettings& world) {
    for (int iteration = 0; iteration < world.position_iterations; ++iteration) {
        for (Contact& contact : contacts_) {
            SolverBody& a = bodies_[contact.a];
            SolverBody& b = bodies_[contact.b];
            for (Point& point : contact.points) {
                const double speed = speedAlong(a.pseudo, b.pseudo, point.arm_a, point.arm_b, contact.normal);
                const double total = std::max(point.split_impulse + point.normal_mass * (point.split_speed - speed), 0.0);
                push(a, b, point.arm_a, point.arm_b, contact.normal * (total - point.split_impulse), &SolverBody::pseudo);
                point.split_impulse = total;
            }
        }
    }
    for (std::size_t i = 0; i < shapes.size(); ++i) {
        const SolverBody& body = bodies_[i];
        if (body.inv_mass == 0.0 || (body.pseudo.linear == Vec2{} && body.pseudo.angular == 0.0)) continue;
        shapes[i]->move(body.pseudo.linear * world.dt);
        if (world.rotation) shapes[i]->rotate(body.pseudo.angular * world.dt);
    }
}

}  // namespace engine
