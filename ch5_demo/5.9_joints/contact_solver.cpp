#include "contact_solver.h"

#include <algorithm>
#include <numeric>

#include "mouse_joint.h"
#include "narrow_phase.h"

namespace engine {

namespace {

// An impulse of `amount` along `direction` at the point: b's motion changes by j / m
// and (r x j) / I, and a's by the same turned round (Newton's third law). `motion`
// picks the real or the pseudo one.
void pushAlong(SolverBody& a, SolverBody& b, Motion SolverBody::*motion, Vec2 direction, Turns turns, double amount) {
    (a.*motion).linear -= direction * (amount * a.inv_mass);
    (a.*motion).angular -= turns.a * amount * a.inv_inertia;
    (b.*motion).linear += direction * (amount * b.inv_mass);
    (b.*motion).angular += turns.b * amount * b.inv_inertia;
}

// How fast the point on b moves away from the point on a, along `direction`.
double speedAlong(const Motion& a, const Motion& b, Vec2 direction, Turns turns) {
    return (b.linear - a.linear).dot(direction) + b.angular * turns.b - a.angular * turns.a;
}

// 1 / (the change of the pair's relative speed along a direction that one unit of
// impulse at the point makes): 1/m for moving each shape, (r x d)^2 / I for turning it.
// This "effective mass" turns a wrong speed into the impulse that puts it right:
// impulse = effective mass * (wanted speed - speed).
double effectiveMass(double inv_mass_sum, double inv_inertia_a, double inv_inertia_b, Turns turns) {
    const double response = inv_mass_sum + turns.a * turns.a * inv_inertia_a + turns.b * turns.b * inv_inertia_b;
    return response > 0 ? 1.0 / response : 0.0;
}

// What gravity adds to a moving shape's velocity in this step (its own step, after
// the collisions); nothing while the world's movement is off.
Vec2 gravityThisStep(const WorldSettings& world) { return world.movement ? world.gravity * world.dt : Vec2{}; }

// The share of k11 k22 that the determinant of a pair's 2 x 2 system must exceed for
// the two points to be solved together (1 - cos^2 of the angle between their rows).
constexpr double kWellConditioned = 1e-3;

}  // namespace

std::size_t ContactSolver::pointCount() const {
    return std::accumulate(contacts_.begin(), contacts_.end(), std::size_t{0},
                           [](std::size_t sum, const Contact& contact) { return sum + contact.points.size(); });
}

void ContactSolver::step(ShapeList shapes, BroadPhase& broad_phase, Islands& islands, ContactEvents& events,
                         Joints& joints, const WorldSettings& world, std::vector<Collision>& found, MouseJoint* mouse) {
    mouse_ = mouse;
    // The joints first: a body joined to an awake one wakes before the pass meets its pairs.
    if (!joints.empty()) joints.startStep(shapes, islands);
    findContacts(shapes, broad_phase, islands, events, joints, world, found);
    prepare(shapes, world);
    joints.prepare(shapes, bodies_, world);
    if (mouse_ != nullptr) mouse_->prepare(shapes, bodies_, world);  // warm started, as the joints
    if (world.warm_starting) {
        joints.warmStart(bodies_);
        warmStart();
    }
    switch (world.position_method) {
        case PositionMethod::baumgarte: solveVelocities(world.velocity_iterations, true, joints); break;
        case PositionMethod::relax:
            solveVelocities(world.velocity_iterations, true, joints);
            relaxAndMove(shapes, world, joints);
            break;
        case PositionMethod::split_impulse:
            solveVelocities(world.velocity_iterations, false, joints);
            solvePositions(shapes, world);
            break;
    }
    // 5.9: the limits that began to hold, for whoever reads events (nothing else changes).
    if (events.kept() && !joints.empty()) joints.reportLimits(shapes, events);
    if (!joints.empty()) joints.capSpeeds(bodies_);
    // The shapes' own step adds this step's gravity again (see prepare).
    // A kinematic shape's (5.9) is its own: no impulse changed it.
    for (std::size_t i = 0; i < shapes.size(); ++i) {
        if (shapes[i]->isResting() || shapes[i]->isKinematic()) continue;
        shapes[i]->setVelocity(bodies_[i].velocity.linear - gravityThisStep(world));
        shapes[i]->setAngularVelocity(bodies_[i].velocity.angular);
    }
}

namespace {
// Whether the contact still names the shapes at its places in the list: removing a
// shape moves the ones after it up the list.
bool stillInPlace(const ContactSolver::Contact& contact, ShapeList shapes) {
    return contact.a < shapes.size() && contact.b < shapes.size() && shapes[contact.a]->id() == contact.id_a &&
           shapes[contact.b]->id() == contact.id_b;
}
bool bothResting(const ContactSolver::Contact& contact, ShapeList shapes) {
    return shapes[contact.a]->isResting() && shapes[contact.b]->isResting();
}
}  // namespace

void ContactSolver::indexLastContacts(ShapeList shapes, std::uint64_t wakes) {
    // A contact of an island that woke comes back, to be met again. Only a wake can
    // change that, so while nothing wakes the sleeping contacts are not looked at: a
    // pile asleep costs nothing here.
    if (wakes != asleep_checked_at_) {
        asleep_checked_at_ = wakes;
        std::erase_if(asleep_, [&](Contact& contact) {
            if (!stillInPlace(contact, shapes)) return true;
            if (bothResting(contact, shapes)) return false;
            last_.push_back(std::move(contact));
            return true;
        });
    }
    // A contact whose shapes both rest now (they fell asleep at the end of the last
    // step) goes to sleep with them: the pass will pass its pair over.
    std::erase_if(last_, [&](Contact& contact) {
        if (!stillInPlace(contact, shapes) || !bothResting(contact, shapes)) return false;
        asleep_.push_back(std::move(contact));
        return true;
    });

    last_index_.clear();
    for (std::size_t k = 0; k < last_.size(); ++k) last_index_.push_back({{last_[k].id_a, last_[k].id_b}, k});
    std::sort(last_index_.begin(), last_index_.end());
}

// One look at every pair the broad phase hands out (nothing moves while it looks), and
// for each pair that overlaps its contact points, each matched by key with the points
// of the same pair in the last step.
void ContactSolver::findContacts(ShapeList shapes, BroadPhase& broad_phase, Islands& islands, ContactEvents& events,
                                 const Joints& joints, const WorldSettings& world, std::vector<Collision>& found) {
    last_.swap(contacts_);
    contacts_.clear();
    indexLastContacts(shapes, islands.wakeCount());
    const std::size_t found_before = found.size();
    if (!meetPairs(shapes, broad_phase, islands, events, joints, world, found)) return;
    // An awake shape reached a sleeping island in the middle of the pass, and woke it:
    // the island's own pairs that the pass met before that were passed over as asleep.
    // Nothing has moved yet, so the pass runs again, and the island is solved whole in
    // the very step it wakes, as Box2D solves it, with the contacts it slept with.
    contacts_.clear();
    found.resize(found_before);
    indexLastContacts(shapes, islands.wakeCount());
    meetPairs(shapes, broad_phase, islands, events, joints, world, found);
}

bool ContactSolver::meetPairs(ShapeList shapes, BroadPhase& broad_phase, Islands& islands, ContactEvents& events,
                              const Joints& joints, const WorldSettings& world, std::vector<Collision>& found) {
    persisted_ = 0;
    bool woke = false;
    broad_phase.startStep(shapes, 1);
    broad_phase.pass([&](std::size_t i, std::size_t j) {
        const RigidShape& a = *shapes[i];
        const RigidShape& b = *shapes[j];
        if (a.isResting() && b.isResting()) return false;
        if (!a.isDynamic() && !b.isDynamic()) return false;  // 5.9: both of infinite mass
        // Two bodies a joint holds together do not collide (joints.h): a chain's links
        // overlap at their pins.
        if (joints.keepsApart(a.id(), b.id())) return false;
        const std::optional<CollisionInfo> info = narrowPhase(a, b);
        if (!info) return false;
        // A sensor only tells what overlaps it (rigid_shape.h): no contact, no island.
        if (a.isSensor() || b.isSensor()) {
            events.sensed(a, b, *info);
            return false;
        }
        if (islands.touching(shapes, i, j, info->depth())) {
            broad_phase.noteResting();
            woke = true;
        }
        events.touching(a, b, *info);
        found.push_back({i, j, *info});
        // Depths closer than the slop are one depth to the solver: no reason to change
        // which shape's face the points are measured from (contact_manifold.cpp).
        ContactManifold manifold = contactManifold(a, b, *info, world.slop);
        Contact contact{.a = i,
                        .b = j,
                        .id_a = a.id(),
                        .id_b = b.id(),
                        .normal = manifold.normal,
                        .tangent = {manifold.normal.y, -manifold.normal.x},
                        .friction = world.friction ? std::min(a.friction(), b.friction()) : 0.0,
                        .restitution = std::min(a.restitution(), b.restitution()),
                        .points = {}};
        const std::pair<PairKey, std::size_t> wanted{{a.id(), b.id()}, 0};
        const auto last = std::lower_bound(last_index_.begin(), last_index_.end(), wanted);
        const bool met_before = last != last_index_.end() && last->first == wanted.first;
        for (const ContactPoint& point : manifold.points) {
            Point solved{.contact = point};
            if (met_before) {
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
    return woke;
}

// What stays the same over the step's iterations: the arms, the effective masses and
// the speeds to aim at, worked out from the velocities the step starts with.
void ContactSolver::prepare(ShapeList shapes, const WorldSettings& world) {
    bodies_.resize(shapes.size());
    for (std::size_t i = 0; i < shapes.size(); ++i) {
        const RigidShape& shape = *shapes[i];
        // The book's order runs the collisions first and then each shape's step, which
        // adds gravity's g dt and moves with the new velocity. The velocities to get
        // right are the ones the shapes will move with, so the solver works on them:
        // were it to stop a resting box and let gravity add g dt afterwards, the box
        // would move g dt^2 into the floor, and down a slope, every step.
        const Vec2 gravity = shape.isDynamic() ? gravityThisStep(world) : Vec2{};
        bodies_[i] = SolverBody{.velocity = {shape.velocity() + gravity, shape.angularVelocity()},
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
            const Vec2 arm_a = world.rotation ? point.contact.position - shapes[contact.a]->center() : Vec2{};
            const Vec2 arm_b = world.rotation ? point.contact.position - shapes[contact.b]->center() : Vec2{};
            point.normal_turns = {arm_a.cross(contact.normal), arm_b.cross(contact.normal)};
            point.tangent_turns = {arm_a.cross(contact.tangent), arm_b.cross(contact.tangent)};
            point.normal_mass = effectiveMass(inv_mass_sum, a.inv_inertia, b.inv_inertia, point.normal_turns);
            point.tangent_mass = effectiveMass(inv_mass_sum, a.inv_inertia, b.inv_inertia, point.tangent_turns);

            // Newton's law of restitution asks the point to leave at e times the speed
            // it came in with; but only a real impact, faster than the threshold. The
            // approach gravity adds in one step (g dt, a third of a px/s here) would
            // otherwise bounce back each step, and nothing would ever rest.
            const double approach = speedAlong(a.velocity, b.velocity, contact.normal, point.normal_turns);
            point.bounce_speed = approach < -world.restitution_threshold ? -contact.restitution * approach : 0.0;

            // The overlap past the slop, to be removed at position_rate of it per step:
            // as a speed that lasts one step, it is rate * excess / dt.
            const double excess = std::max(point.contact.depth - world.slop, 0.0);
            point.removal_speed = world.positional_correction ? world.position_rate * excess / world.dt : 0.0;
        }
        contact.solve_as_pair = false;
        if (contact.points.size() != 2) continue;
        // An impulse at point 1 moves point 2 too, through the shapes' motion and turning:
        // k12 = 1/mA + 1/mB + (rA1 x n)(rA2 x n)/IA + (rB1 x n)(rB2 x n)/IB.
        const Point& one = contact.points[0];
        const Point& two = contact.points[1];
        const double k12 = inv_mass_sum + one.normal_turns.a * two.normal_turns.a * a.inv_inertia +
                           one.normal_turns.b * two.normal_turns.b * b.inv_inertia;
        contact.k11 = one.normal_mass > 0 ? 1.0 / one.normal_mass : 0.0;
        contact.k22 = two.normal_mass > 0 ? 1.0 / two.normal_mass : 0.0;
        contact.k12 = k12;
        // Two points close together push almost alike (k12 near k11 and k22): the
        // system is nearly singular and its answer would swing wildly, so such a pair
        // is solved point by point.
        const double determinant = contact.k11 * contact.k22 - k12 * k12;
        contact.solve_as_pair = determinant > kWellConditioned * contact.k11 * contact.k22;
        if (!contact.solve_as_pair) continue;
        // The inverse of K, once per step: the iterations then multiply where they
        // would divide, and a division takes several times as long as a product.
        contact.inverse11 = contact.k22 / determinant;
        contact.inverse12 = -k12 / determinant;
        contact.inverse22 = contact.k11 / determinant;
    }
}

// The totals carried over from the last step, applied before the first iteration.
void ContactSolver::warmStart() {
    for (Contact& contact : contacts_) {
        for (const Point& point : contact.points) {
            SolverBody& a = bodies_[contact.a];
            SolverBody& b = bodies_[contact.b];
            pushAlong(a, b, &SolverBody::velocity, contact.normal, point.normal_turns, point.normal_impulse);
            pushAlong(a, b, &SolverBody::velocity, contact.tangent, point.tangent_turns, point.tangent_impulse);
        }
    }
}

// Gauss-Seidel over the contact points: each point in turn gets the impulse that puts
// its own speed right, as the others' impulses have left it; repeated, the impulses
// settle on values that suit all the points together.
void ContactSolver::solveVelocities(int iterations, bool with_removal, Joints& joints) {
    for (Contact& contact : contacts_) {
        for (Point& point : contact.points) {
            point.target_speed = with_removal ? std::max(point.bounce_speed, point.removal_speed) : point.bounce_speed;
        }
    }
    for (int iteration = 0; iteration < iterations; ++iteration) {
        joints.solve(bodies_);  // the joints first, as Box2D: the contacts have the last word
        if (mouse_ != nullptr) mouse_->solve(bodies_);
        for (Contact& contact : contacts_) {
            SolverBody& a = bodies_[contact.a];
            SolverBody& b = bodies_[contact.b];
            // Friction first, within the cone of the normal totals as they stand: the
            // normal impulses below, solved last, are then the ones the iteration ends on.
            for (Point& point : contact.points) {
                const double sliding = speedAlong(a.velocity, b.velocity, contact.tangent, point.tangent_turns);
                const double limit = contact.friction * point.normal_impulse;
                const double total = std::clamp(point.tangent_impulse - point.tangent_mass * sliding, -limit, limit);
                pushAlong(a, b, &SolverBody::velocity, contact.tangent, point.tangent_turns,
                          total - point.tangent_impulse);
                point.tangent_impulse = total;
            }
            if (contact.solve_as_pair) {
                solvePair(contact);
                continue;
            }
            for (Point& point : contact.points) {
                const double speed = speedAlong(a.velocity, b.velocity, contact.normal, point.normal_turns);
                const double total =
                    std::max(point.normal_impulse + point.normal_mass * (point.target_speed - speed), 0.0);
                pushAlong(a, b, &SolverBody::velocity, contact.normal, point.normal_turns,
                          total - point.normal_impulse);
                point.normal_impulse = total;
            }
        }
    }
}

// The two normal totals x1, x2 of a flat contact at once. Solved point by point, each
// point's impulse also moves the other (k12), so the two take turns correcting each
// other and need many iterations to agree. Together they must satisfy, with the
// speeds w that the totals x leave (w = K x + b, where b is what the speeds would be
// with no normal impulse at all, less the target speeds):
//     x >= 0,  w >= 0,  and x_i w_i = 0   (a point pushes only where it touches)
// With two unknowns there are four cases to try: both push (w = 0, x = -K^-1 b), only
// the first (x2 = 0, w1 = 0), only the second, neither (x = 0). The first case that
// satisfies all three conditions is the answer; if rounding leaves none, the totals
// stay as they are for this iteration.
void ContactSolver::solvePair(Contact& contact) {
    SolverBody& a = bodies_[contact.a];
    SolverBody& b = bodies_[contact.b];
    Point& one = contact.points[0];
    Point& two = contact.points[1];
    const double x1 = one.normal_impulse;
    const double x2 = two.normal_impulse;
    const double b1 = speedAlong(a.velocity, b.velocity, contact.normal, one.normal_turns) - one.target_speed -
                      (contact.k11 * x1 + contact.k12 * x2);
    const double b2 = speedAlong(a.velocity, b.velocity, contact.normal, two.normal_turns) - two.target_speed -
                      (contact.k12 * x1 + contact.k22 * x2);
    const auto accept = [&](double new1, double new2) {
        pushAlong(a, b, &SolverBody::velocity, contact.normal, one.normal_turns, new1 - x1);
        pushAlong(a, b, &SolverBody::velocity, contact.normal, two.normal_turns, new2 - x2);
        one.normal_impulse = new1;
        two.normal_impulse = new2;
    };
    // Both push: K x = -b, so x = -K^-1 b.
    const double both1 = -(contact.inverse11 * b1 + contact.inverse12 * b2);
    const double both2 = -(contact.inverse12 * b1 + contact.inverse22 * b2);
    if (both1 >= 0 && both2 >= 0) return accept(both1, both2);
    // Only the first pushes: w1 = k11 x1 + b1 = 0, and the second must not approach.
    const double only1 = -b1 * one.normal_mass;
    if (only1 >= 0 && contact.k12 * only1 + b2 >= 0) return accept(only1, 0.0);
    const double only2 = -b2 * two.normal_mass;
    if (only2 >= 0 && contact.k12 * only2 + b1 >= 0) return accept(0.0, only2);
    if (b1 >= 0 && b2 >= 0) return accept(0.0, 0.0);
}

// Relaxation after Baumgarte: the iterations so far aimed at the speeds that also
// remove the overlap; the velocities they left, run for one step, move the shapes
// apart. Further iterations aim at the bouncing speeds alone, which takes that extra
// speed back out of the velocities (and out of the totals that warm start the next
// step). The shapes are moved by the difference, so that overall they move as the
// first velocities say, but keep the second ones: the overlap is gone, and no energy
// was added to remove it.
void ContactSolver::relaxAndMove(ShapeList shapes, const WorldSettings& world, Joints& joints) {
    std::vector<Motion> with_removal(bodies_.size());
    for (std::size_t i = 0; i < bodies_.size(); ++i) with_removal[i] = bodies_[i].velocity;
    solveVelocities(world.position_iterations, false, joints);
    for (std::size_t i = 0; i < shapes.size(); ++i) {
        const SolverBody& body = bodies_[i];
        if (body.inv_mass == 0.0) continue;
        const Vec2 extra = with_removal[i].linear - body.velocity.linear;
        const double extra_turn = with_removal[i].angular - body.velocity.angular;
        if (extra == Vec2{} && extra_turn == 0.0) continue;
        shapes[i]->move(extra * world.dt);
        if (world.rotation) shapes[i]->rotate(extra_turn * world.dt);
    }
}

// Split impulses: the overlap is removed by pseudo velocities, solved as the real ones
// are (effective masses, totals never below 0), that move the shapes once and are then
// dropped. The real velocities never see them, so removing overlap adds no energy: a
// box pushed out of the floor does not fly up.
//
// Every point aims at the slop, from either side, at the same rate: one past it is
// pushed out by position_rate of its excess a step; one within it may close by
// position_rate of its room a step, and is held only beyond that. A point that held
// at any depth (asked not to close at all) would make pushing one box out of the floor
// mean lifting the whole pile on it: a problem as large as the velocities', which three
// passes started from nothing leave half solved. The half answer shoves and turns
// shapes all through the pile, opens contacts that carry weight, and moves the points
// under the impulses the next step starts from: such a pile never comes to rest
// (bench/README.md, "Creep at rest"). Letting a point within the slop close keeps a
// push near where it starts (Box2D 2.4's position passes leave such a point alone
// altogether).
void ContactSolver::solvePositions(ShapeList shapes, const WorldSettings& world) {
    // With no overlap past the slop anywhere every pseudo velocity stays 0 (the totals
    // start at 0 and nothing asks for more): a pile at rest skips the passes.
    const bool anything_to_remove = std::any_of(contacts_.begin(), contacts_.end(), [](const Contact& contact) {
        return std::any_of(contact.points.begin(), contact.points.end(),
                           [](const Point& point) { return point.removal_speed > 0.0; });
    });
    if (!anything_to_remove) return;
    for (int iteration = 0; iteration < world.position_iterations; ++iteration) {
        for (Contact& contact : contacts_) {
            SolverBody& a = bodies_[contact.a];
            SolverBody& b = bodies_[contact.b];
            for (Point& point : contact.points) {
                // Past the slop the removal speed; within it, the speed that closes
                // the point to the slop at the same rate (below 0: it may close).
                const double target = world.position_rate * (point.contact.depth - world.slop) / world.dt;
                const double speed = speedAlong(a.pseudo, b.pseudo, contact.normal, point.normal_turns);
                const double total = std::max(point.split_impulse + point.normal_mass * (target - speed), 0.0);
                pushAlong(a, b, &SolverBody::pseudo, contact.normal, point.normal_turns, total - point.split_impulse);
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
