#include "joints.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "contact_events.h"
#include "contact_solver.h"
#include "islands.h"

namespace engine {

namespace {

constexpr double kUnbounded = std::numeric_limits<double>::infinity();
// A distance joint whose anchors are closer than this has no direction to push along
// this step (the rod's length is then 0 px to rounding): its rows wait for the next.
constexpr double kShortestLink = 1e-9;  // px

// The velocity a spin w gives a point at arm r from the centre: w x r.
Vec2 spinAt(double w, Vec2 arm) { return {-w * arm.y, w * arm.x}; }

// Where a joint's anchors are now, and what the step needs of them.
struct Frame {
    Vec2 arm_a, arm_b;   // centre to anchor, world px
    Vec2 gap;            // anchor b less anchor a
    double angle = 0.0;  // b's angle less a's, less the reference
};

// The joint's angle alone needs no sine or cosine: the positional passes ask for it
// where they need nothing else, as they run a few times a step for every joint.
// (They take a shape, or the positional passes' Placed, joints.h: both have a centre and
// an angle.)
template <typename Body>
double angleOf(const JointDefinition& joint, const Body& a, const Body& b) {
    return b.angle() - a.angle() - joint.reference_angle;
}

// A point of a body's frame in the world's: a shape works out its angle's cosine and
// sine each time, the positional passes' Placed keeps them (joints.h).
Vec2 inWorld(Vec2 local, const RigidShape& body) { return toWorld(local, body.angle()); }
Vec2 inWorld(Vec2 local, const Joints::Placed& body) { return body.toWorld(local); }

template <typename Body>
Frame frameOf(const JointDefinition& joint, const Body& a, const Body& b) {
    Frame frame;
    frame.arm_a = inWorld(joint.local_a, a);
    frame.arm_b = inWorld(joint.local_b, b);
    frame.gap = (b.center() + frame.arm_b) - (a.center() + frame.arm_a);
    frame.angle = angleOf(joint, a, b);
    return frame;
}

// A slider's axis as a's turn has carried it, and the direction across it.
template <typename Body>
Vec2 axisOf(const JointDefinition& joint, const Body& a) {
    return inWorld(joint.local_axis, a);
}
Vec2 across(Vec2 axis) { return {-axis.y, axis.x}; }

// A pair of bodies as the joints keep them apart: the smaller id first.
std::pair<BodyId, BodyId> orderedPair(BodyId a, BodyId b) { return {std::min(a, b), std::max(a, b)}; }

// 1 / k, or 0 where nothing answers the impulse (two static bodies, no turning).
double inverseOr0(double k) { return k > 0.0 ? 1.0 / k : 0.0; }

}  // namespace

std::string_view jointTypeName(JointType type) {
    switch (type) {
        case JointType::revolute: return "revolute";
        case JointType::distance: return "distance";
        case JointType::weld: return "weld";
        case JointType::prismatic: return "prismatic";
    }
    return {};
}

JointDefinition pinAt(JointType type, const RigidShape& a, const RigidShape& b, Vec2 anchor) {
    JointDefinition joint;
    joint.type = type;
    joint.body_a = a.id();
    joint.body_b = b.id();
    joint.local_a = toBody(anchor - a.center(), a.angle());
    joint.local_b = toBody(anchor - b.center(), b.angle());
    joint.reference_angle = b.angle() - a.angle();
    return joint;
}

JointDefinition linkBetween(const RigidShape& a, const RigidShape& b, std::pair<Vec2, Vec2> anchors) {
    JointDefinition joint;
    joint.type = JointType::distance;
    joint.body_a = a.id();
    joint.body_b = b.id();
    joint.local_a = toBody(anchors.first - a.center(), a.angle());
    joint.local_b = toBody(anchors.second - b.center(), b.angle());
    joint.reference_angle = b.angle() - a.angle();
    joint.length = anchors.first.distance(anchors.second);
    return joint;
}

std::pair<Vec2, Vec2> anchorsOf(const JointDefinition& joint, const RigidShape& a, const RigidShape& b) {
    return {a.center() + toWorld(joint.local_a, a.angle()), b.center() + toWorld(joint.local_b, b.angle())};
}

double positionOf(const JointDefinition& joint, const RigidShape& a, const RigidShape& b) {
    const Frame frame = frameOf(joint, a, b);
    switch (joint.type) {
        case JointType::distance: return frame.gap.length();
        case JointType::prismatic: return axisOf(joint, a).dot(frame.gap);
        case JointType::revolute:
        case JointType::weld: break;
    }
    return frame.angle;
}

double separationOf(const JointDefinition& joint, const RigidShape& a, const RigidShape& b) {
    const Frame frame = frameOf(joint, a, b);
    switch (joint.type) {
        case JointType::revolute:
        case JointType::weld: return frame.gap.length();
        case JointType::prismatic: return std::abs(across(axisOf(joint, a)).dot(frame.gap));
        case JointType::distance: break;
    }
    const double length = frame.gap.length();
    if (joint.length_range) {
        return std::max({0.0, joint.length_range->lower - length, length - joint.length_range->upper});
    }
    if (joint.hertz > 0.0) return 0.0;  // a spring's stretch is its working, not an error
    return std::abs(length - joint.length);
}

// A spring of stiffness k = m w^2 and damping c = 2 m zeta w (w = 2 pi f), stepped by
// implicit Euler over h, asks each step for the impulse
//     -m (h w^2 C + a2 Cdot) / (1 + a2),   a2 = h w (2 zeta + h w)
// (README.md, "Soft constraints"), which is the three numbers below.
Softness softness(double hertz, double damping_ratio, double dt) {
    if (hertz <= 0.0) return {};
    const double omega = 2.0 * std::numbers::pi * hertz;
    const double a1 = 2.0 * damping_ratio + dt * omega;
    const double a2 = dt * omega * a1;
    const double a3 = 1.0 / (1.0 + a2);
    return {.bias_rate = omega / a1, .mass_scale = a2 * a3, .impulse_scale = a3};
}

// A soft row is implicit Euler's spring only where the iterations reach its fixed
// point. A chain's pins share their bodies, and 8 Gauss-Seidel sweeps over a chain with
// a 10:1 load leave them far from it; then a stiff row (60 Hz at 60 steps a second asks
// back 61 % of its error each step, a 30 Hz one 44 %) overshoots the way an explicit
// spring does, and the chain bounced ever higher (README.md, "Soft constraints"). So
// the frequency is capped by the step's rate, as Box2D v3 caps its contacts' at a
// quarter of its sub-step rate and makes its joints twice as stiff as those: at most
// half the step's rate. A larger joint_hertz is taken, and runs at the cap.
double jointHertz(const WorldSettings& world, double dt) {
    if (world.joint_hertz <= 0.0 || dt <= 0.0) return world.joint_hertz;
    constexpr double kShareOfStepRate = 0.5;
    return std::min(world.joint_hertz, kShareOfStepRate / dt);
}

void Joints::add(const Joint& joint) {
    joints_.push_back(joint);
    const JointDefinition& added = joint.definition;
    if (!added.collide_connected) {
        apart_.push_back(orderedPair(added.body_a, added.body_b));
        std::sort(apart_.begin(), apart_.end());
    }
}

void Joints::forgetBody(BodyId body) {
    std::erase_if(joints_, [body](const Joint& joint) {
        return joint.definition.body_a == body || joint.definition.body_b == body;
    });
    std::erase_if(apart_, [body](const auto& pair) { return pair.first == body || pair.second == body; });
}

bool Joints::keepsApart(BodyId a, BodyId b) const {
    return !apart_.empty() && std::binary_search(apart_.begin(), apart_.end(), orderedPair(a, b));
}

bool Joints::startStep(ShapeList shapes, Islands& islands) {
    // A body is looked for first where the joint found it in the last step: only a
    // removal before it in the list moves it (and a joint added or forgotten shifts the
    // joints after it, so a place is a guess, checked by the id). Else it is found by
    // bisection: the list holds its shapes in the order the world took them in, and
    // ids only go up (rigid_shape.h), so it is sorted by id. A grid of 900 bodies and
    // 1,740 pins spent a sixth of its step on the bisections alone.
    const auto place = [shapes](BodyId id, std::optional<std::size_t> last) -> std::optional<std::size_t> {
        if (last && *last < shapes.size() && shapes[*last]->id() == id) return last;
        const auto found = std::lower_bound(shapes.begin(), shapes.end(), id,
                                            [](const auto& shape, BodyId wanted) { return shape->id() < wanted; });
        if (found == shapes.end() || (*found)->id() != id) return std::nullopt;
        return static_cast<std::size_t>(found - shapes.begin());
    };
    places_.resize(joints_.size());
    bool woke = false;
    for (std::size_t k = 0; k < joints_.size(); ++k) {
        const auto last = places_[k];
        const std::optional<std::size_t> a =
            place(joints_[k].definition.body_a, last ? std::optional{last->first} : std::nullopt);
        const std::optional<std::size_t> b =
            place(joints_[k].definition.body_b, last ? std::optional{last->second} : std::nullopt);
        places_[k].reset();
        if (!a || !b) continue;
        places_[k] = {*a, *b};
        woke = islands.joined(shapes, *a, *b) || woke;
    }
    orderFromSupports(shapes);
    return woke;
}

// Gauss-Seidel ends each sweep on the joints it meets last: their speeds (or, in the
// positional passes, their gaps) are right when the sweep ends, those met before only
// nearly, as the later ones have pulled their bodies since. The joints nearest a
// support (a static or kinematic body) carry the weight of everything beyond them, and
// a chain's widest gap opens there. So the joints are met farthest from the supports
// first and nearest last: a load's pull then reaches the support within one sweep
// (support first, it would move one link a sweep), and the sweep ends on the joints
// that carry the most. The distance is counted in joints, from the nearest support,
// by a breadth-first walk; a group with no support comes first, its joints in the
// order they were made (ties keep that order too). A general order: it holds for a chain, a
// bridge held at both ends (the middle first), a net hung from a corner, a ragdoll on
// a kinematic hand. (Box2D 2.4 happens to meet a hanging chain in this order: it builds
// an island from its newest body, the chain's load.) The walk runs again only when a
// joint, a body's place or a body's being a support changed.
void Joints::orderFromSupports(ShapeList shapes) {
    const auto supports = [&](std::size_t body) { return !shapes[body]->isDynamic(); };
    bool same = ordered_places_.size() == places_.size();
    for (std::size_t k = 0; same && k < places_.size(); ++k) {
        same = ordered_places_[k] == places_[k] &&
               (!places_[k] ||
                ordered_supports_[k] == std::pair{supports(places_[k]->first), supports(places_[k]->second)});
    }
    if (same) return;
    ordered_places_ = places_;
    ordered_supports_.assign(places_.size(), {false, false});
    // The joints at each body, as a list per body (first_joint_[i] to first_joint_[i + 1]).
    constexpr std::size_t kUnreached = std::numeric_limits<std::size_t>::max();
    first_joint_.assign(shapes.size() + 1, 0);
    for (const auto& place : places_) {
        if (!place) continue;
        ++first_joint_[place->first + 1];
        ++first_joint_[place->second + 1];
    }
    for (std::size_t i = 0; i < shapes.size(); ++i) first_joint_[i + 1] += first_joint_[i];
    joint_at_.resize(first_joint_.back());
    std::vector<std::size_t> filled(first_joint_.begin(), first_joint_.end() - 1);
    for (std::size_t k = 0; k < places_.size(); ++k) {
        if (!places_[k]) continue;
        joint_at_[filled[places_[k]->first]++] = k;
        joint_at_[filled[places_[k]->second]++] = k;
    }
    // Hops from the nearest support, breadth first from every support at once.
    hops_.assign(shapes.size(), kUnreached);
    std::vector<std::size_t> queue;
    for (std::size_t k = 0; k < places_.size(); ++k) {
        if (!places_[k]) continue;
        const auto [a, b] = *places_[k];
        ordered_supports_[k] = {supports(a), supports(b)};
        for (const std::size_t body : {a, b}) {
            if (supports(body) && hops_[body] == kUnreached) {
                hops_[body] = 0;
                queue.push_back(body);
            }
        }
    }
    for (std::size_t next = 0; next < queue.size(); ++next) {
        const std::size_t body = queue[next];
        for (std::size_t j = first_joint_[body]; j < first_joint_[body + 1]; ++j) {
            const auto [a, b] = *places_[joint_at_[j]];
            const std::size_t other = a == body ? b : a;
            if (hops_[other] != kUnreached) continue;
            hops_[other] = hops_[body] + 1;
            queue.push_back(other);
        }
    }
    order_.clear();
    for (std::size_t k = 0; k < places_.size(); ++k) {
        if (places_[k]) order_.push_back(k);
    }
    const auto distance = [&](std::size_t k) { return std::min(hops_[places_[k]->first], hops_[places_[k]->second]); };
    std::stable_sort(order_.begin(), order_.end(),
                     [&](std::size_t one, std::size_t other) { return distance(one) > distance(other); });
}

void Joints::prepare(ShapeList shapes, const std::vector<SolverBody>& bodies, const WorldSettings& world) {
    prepared_.clear();
    rows_.clear();
    // Each body's angle's cosine and sine once a step, however many joints hold it (a
    // link of a chain is held by two): a body is placed when a joint first asks for it.
    placed_.resize(shapes.size());
    placed_known_.assign(shapes.size(), false);
    const auto placedOf = [&](std::size_t i) -> const Placed& {
        if (!placed_known_[i]) {
            placed_[i] = placedFrom(*shapes[i]);
            placed_known_[i] = true;
        }
        return placed_[i];
    };
    const Softness stiff = softness(jointHertz(world, world.dt), world.joint_damping_ratio, world.dt);
    for (const std::size_t k : order_) {
        const auto [a, b] = *places_[k];
        const RigidShape& shape_a = *shapes[a];
        const RigidShape& shape_b = *shapes[b];
        // Nothing moves two resting bodies: a sleeping island keeps its totals for when
        // it wakes, as 5.5's contacts do.
        if (shape_a.isResting() && shape_b.isResting()) continue;
        Joint& joint = joints_[k];
        if (!world.warm_starting) joint.impulses = {};
        const JointDefinition& definition = joint.definition;
        const SolverBody& body_a = bodies[a];
        const SolverBody& body_b = bodies[b];
        const double inv_mass_sum = body_a.inv_mass + body_b.inv_mass;
        Frame frame = frameOf(definition, placedOf(a), placedOf(b));
        if (!world.rotation) frame.arm_a = frame.arm_b = {};  // impulses act through the centres

        Prepared prepared{.joint = k, .a = a, .b = b, .first_row = rows_.size()};
        const auto addRow = [&](Row row) {
            rows_.push_back(row);
            ++prepared.row_count;
        };
        // A row along `direction` at the anchors (none: a turn), its mass worked out here.
        const auto row = [&](Vec2 direction, double turn_a, double turn_b, double JointImpulses::*total) {
            Row made{.direction = direction, .turn_a = turn_a, .turn_b = turn_b, .total = total};
            made.mass = inverseOr0(inv_mass_sum * direction.dot(direction) + turn_a * turn_a * body_a.inv_inertia +
                                   turn_b * turn_b * body_b.inv_inertia);
            return made;
        };
        // An equation C = 0, pulled back softly.
        const auto equation = [&](Row made, double error, Softness soft) {
            made.bias = soft.bias_rate * error;
            made.mass_scale = soft.mass_scale;
            made.impulse_scale = soft.impulse_scale;
            made.lowest = -kUnbounded;
            made.highest = kUnbounded;
            addRow(made);
        };
        // A limit C >= 0. While C > 0 the row only keeps the joint from passing the
        // limit within this step (it may close the gap C, no more): a speculative limit,
        // which never pulls. Past the limit it pushes back as softly as an equation.
        const auto limit = [&](Row made, double error) {
            made.approach = -(made.direction.dot(body_b.velocity.linear - body_a.velocity.linear) +
                              made.turn_b * body_b.velocity.angular - made.turn_a * body_a.velocity.angular);
            if (error > 0.0) {
                made.bias = error / world.dt;
            } else {
                made.bias = stiff.bias_rate * error;
                made.mass_scale = stiff.mass_scale;
                made.impulse_scale = stiff.impulse_scale;
            }
            made.lowest = 0.0;
            made.highest = kUnbounded;
            addRow(made);
        };
        const auto pin = [&] {
            Pin made{.arm_a = frame.arm_a,
                     .arm_b = frame.arm_b,
                     .bias = frame.gap * stiff.bias_rate,
                     .soft = stiff,
                     .rigid = stiff.mass_scale == 1.0 && stiff.impulse_scale == 0.0};
            const Vec2 ra = frame.arm_a, rb = frame.arm_b;
            // K: the speeds unit impulses make.
            const double k11 = inv_mass_sum + ra.y * ra.y * body_a.inv_inertia + rb.y * rb.y * body_b.inv_inertia;
            const double k12 = -ra.x * ra.y * body_a.inv_inertia - rb.x * rb.y * body_b.inv_inertia;
            const double k22 = inv_mass_sum + ra.x * ra.x * body_a.inv_inertia + rb.x * rb.x * body_b.inv_inertia;
            // Its inverse, once a step: the iterations multiply where they would divide.
            const double determinant = k11 * k22 - k12 * k12;
            if (determinant > 0.0) {
                made.inverse11 = k22 / determinant;
                made.inverse12 = -k12 / determinant;
                made.inverse22 = k11 / determinant;
            }
            prepared.pin = made;
        };

        switch (definition.type) {
            case JointType::revolute:
                if (definition.motor) {
                    Row motor = row({}, 1.0, 1.0, &JointImpulses::motor);
                    motor.target_speed = definition.motor->speed;
                    motor.highest = definition.motor->max_torque * world.dt;
                    motor.lowest = -motor.highest;
                    addRow(motor);
                }
                if (definition.limit) {
                    limit(row({}, 1.0, 1.0, &JointImpulses::lower), frame.angle - definition.limit->lower);
                    limit(row({}, -1.0, -1.0, &JointImpulses::upper), definition.limit->upper - frame.angle);
                }
                pin();
                break;
            case JointType::weld:
                equation(row({}, 1.0, 1.0, &JointImpulses::angular), frame.angle, stiff);
                pin();
                break;
            case JointType::prismatic: {
                // The axis turns with a, so a's arm reaches to b's anchor: (gap + r_a).
                const Vec2 axis = axisOf(definition, placedOf(a));
                const Vec2 normal = across(axis);
                const Vec2 arm_a = frame.gap + frame.arm_a;
                if (definition.limit) {
                    const double translation = axis.dot(frame.gap);
                    limit(row(axis, arm_a.cross(axis), frame.arm_b.cross(axis), &JointImpulses::lower),
                          translation - definition.limit->lower);
                    limit(row(-axis, -arm_a.cross(axis), -frame.arm_b.cross(axis), &JointImpulses::upper),
                          definition.limit->upper - translation);
                }
                equation(row(normal, arm_a.cross(normal), frame.arm_b.cross(normal), &JointImpulses::across),
                         normal.dot(frame.gap), stiff);
                equation(row({}, 1.0, 1.0, &JointImpulses::angular), frame.angle, stiff);
                break;
            }
            case JointType::distance: {
                const double length = frame.gap.length();
                if (length < kShortestLink) break;
                const Vec2 along = frame.gap * (1.0 / length);
                const double turn_a = frame.arm_a.cross(along), turn_b = frame.arm_b.cross(along);
                if (definition.hertz > 0.0) {
                    equation(row(along, turn_a, turn_b, &JointImpulses::axial), length - definition.length,
                             softness(definition.hertz, definition.damping_ratio, world.dt));
                } else if (!definition.length_range) {
                    equation(row(along, turn_a, turn_b, &JointImpulses::axial), length - definition.length, stiff);
                }
                if (definition.length_range) {
                    limit(row(along, turn_a, turn_b, &JointImpulses::lower), length - definition.length_range->lower);
                    limit(row(-along, -turn_a, -turn_b, &JointImpulses::upper),
                          definition.length_range->upper - length);
                }
                break;
            }
        }
        prepared_.push_back(prepared);
    }
}

namespace {

// An impulse `amount` along a row: b gets it, a the same turned round.
void pushRow(SolverBody& a, SolverBody& b, Vec2 direction, double turn_a, double turn_b, double amount) {
    a.velocity.linear -= direction * (amount * a.inv_mass);
    a.velocity.angular -= turn_a * amount * a.inv_inertia;
    b.velocity.linear += direction * (amount * b.inv_mass);
    b.velocity.angular += turn_b * amount * b.inv_inertia;
}

// An impulse at a pin's anchors: b gets it, a the same turned round.
void pushPin(SolverBody& a, SolverBody& b, Vec2 arm_a, Vec2 arm_b, Vec2 impulse) {
    a.velocity.linear -= impulse * a.inv_mass;
    a.velocity.angular -= arm_a.cross(impulse) * a.inv_inertia;
    b.velocity.linear += impulse * b.inv_mass;
    b.velocity.angular += arm_b.cross(impulse) * b.inv_inertia;
}

}  // namespace

void Joints::warmStart(std::vector<SolverBody>& bodies) const {
    for (const Prepared& prepared : prepared_) {
        const JointImpulses& totals = joints_[prepared.joint].impulses;
        SolverBody& a = bodies[prepared.a];
        SolverBody& b = bodies[prepared.b];
        for (std::size_t r = 0; r < prepared.row_count; ++r) {
            const Row& row = rows_[prepared.first_row + r];
            pushRow(a, b, row.direction, row.turn_a, row.turn_b, totals.*row.total);
        }
        if (prepared.pin) pushPin(a, b, prepared.pin->arm_a, prepared.pin->arm_b, totals.point);
    }
}

// Gauss-Seidel, as the contacts: each row in turn gets the impulse that puts its own
// speed right (less the soft share), as the rows before it left the bodies; the pin
// last, so that of all a joint's rows it is the one an iteration ends on.
void Joints::solve(std::vector<SolverBody>& bodies) {
    for (const Prepared& prepared : prepared_) {
        JointImpulses& totals = joints_[prepared.joint].impulses;
        SolverBody& a = bodies[prepared.a];
        SolverBody& b = bodies[prepared.b];
        for (std::size_t r = 0; r < prepared.row_count; ++r) {
            const Row& row = rows_[prepared.first_row + r];
            const double speed = row.direction.dot(b.velocity.linear - a.velocity.linear) +
                                 row.turn_b * b.velocity.angular - row.turn_a * a.velocity.angular;
            double& total = totals.*row.total;
            const double impulse =
                -row.mass_scale * row.mass * (speed - row.target_speed + row.bias) - row.impulse_scale * total;
            const double clamped = std::clamp(total + impulse, row.lowest, row.highest);
            pushRow(a, b, row.direction, row.turn_a, row.turn_b, clamped - total);
            total = clamped;
        }
        if (!prepared.pin) continue;
        const Pin& pin = *prepared.pin;
        // The speed at which the anchors part, and the impulse that, with the soft
        // share, stops it: K impulse = -(speed + bias), K the pin's 2 x 2 effective mass.
        const Vec2 speed = b.velocity.linear + spinAt(b.velocity.angular, pin.arm_b) - a.velocity.linear -
                           spinAt(a.velocity.angular, pin.arm_a);
        const Vec2 wanted = speed + pin.bias;
        const Vec2 solved{pin.inverse11 * wanted.x + pin.inverse12 * wanted.y,
                          pin.inverse12 * wanted.x + pin.inverse22 * wanted.y};
        // A rigid pin (the world's joint_hertz 0) keeps the whole of it: its mass scale 1
        // and impulse scale 0 would change nothing but the time it takes, and this is the
        // solver's innermost line.
        const Vec2 impulse =
            pin.rigid ? -solved : solved * -pin.soft.mass_scale - totals.point * pin.soft.impulse_scale;
        pushPin(a, b, pin.arm_a, pin.arm_b, impulse);
        totals.point += impulse;
    }
}

// The fastest a body a joint holds leaves the solver's iterations, px/s: Box2D 2.4's
// b2_maxTranslation, 2 m a step at 60 Hz, at 30 px to the metre. No scene of the stage
// comes near it: a body falling at 300 px/s^2 reaches it after 12 s, 21,600 px down.
// It is there for joints stiffer than the iterations can solve: a grid of boxes of half
// side 2 px, each pinned 8 px out to its neighbours, at 2000 px/s^2, ends each step with
// impulses that do not agree, and warm started from them the next step it gained energy
// step after step, its bodies flung ever faster (1e20 px in 10 s at 8 iterations). At
// this speed the energy has nowhere to grow: the grid tears (thousands of px, as Box2D
// 2.4's tears, build/joints_bench with GRID) but stays finite; sub-steps hold it.
constexpr double kFastestHeldSpeed = 3600.0;

void Joints::capSpeeds(std::vector<SolverBody>& bodies) const {
    for (std::size_t i = 0; i < placed_known_.size() && i < bodies.size(); ++i) {
        SolverBody& body = bodies[i];
        if (!placed_known_[i] || body.inv_mass == 0.0) continue;  // static or kinematic: its own
        const double speed = body.velocity.linear.length();
        if (speed > kFastestHeldSpeed) body.velocity.linear = body.velocity.linear * (kFastestHeldSpeed / speed);
    }
}

void Joints::reportLimits(ShapeList shapes, ContactEvents& events) {
    for (const Prepared& prepared : prepared_) {
        Joint& joint = joints_[prepared.joint];
        for (std::size_t r = 0; r < prepared.row_count; ++r) {
            const Row& row = rows_[prepared.first_row + r];
            const bool lower = row.total == &JointImpulses::lower;
            if (!lower && row.total != &JointImpulses::upper) continue;
            bool& was = lower ? joint.at_lower : joint.at_upper;
            const bool holds = joint.impulses.*row.total > 0.0;
            if (holds && !was) {
                const RigidShape& a = *shapes[prepared.a];
                const RigidShape& b = *shapes[prepared.b];
                events.limitReached(a.id(), b.id(), anchorsOf(joint.definition, a, b).second, row.direction,
                                    row.approach);
            }
            was = holds;
        }
    }
}

namespace {

// The most a positional pass moves a rod or a slider along itself, or a limit back,
// px: a rod stretched by a whole link in one step is pulled back over a few steps, not
// thrown (Box2D 2.4's b2_maxLinearCorrection, 0.2 m, at 30 px to the metre, which its
// distance joint is cut at; its revolute joint is not cut, nor is a pin here).
constexpr double kLongestJointShift = 6.0;

// The most a correction turns a body, rad: a trust region on the pass's linear step.
// A pass solves each joint's equations made straight (linear) where the bodies are,
// and in that model a turn t carries an anchor at arm r along the arm's tangent by r t.
// It goes along a chord: r sin t along the tangent and r (1 - cos t) in towards the
// centre. At half a radian that is 4 % short and 12 % of the arm inwards, and the step
// still closes most of the gap; at 2 or 3 rad the anchor lands where the model never
// looked, and the next joint starts further off. On a body whose arms are long beside
// its size this feeds itself: the joint grid's discs (radius 4 px, pins 6 px out) turn
// the most, and the grid, whose every disc is pulled by four pins, blew up (5.8e8 px).
// So a step that would turn a body further is shortened, along its own direction, until
// the larger turn is this one; the next pass or step closes what is left. The distance
// itself is not cut: where no body turns far the step is the model's own, as Box2D
// 2.4's revolute joint takes it, and a whipping chain's end pin closes in one pass.
constexpr double kLongestTrustedTurn = 0.5;  // rad

// The share of a step, at most 1, that turns neither body further than the trusted turn.
double trustedShare(double turn_a, double turn_b) {
    const double larger = std::max(std::abs(turn_a), std::abs(turn_b));
    return larger > kLongestTrustedTurn ? kLongestTrustedTurn / larger : 1.0;
}

// Moves and turns the pair by an impulse-like `amount` along `direction` at the arms
// (a turn alone when the direction is 0): each by its inverse mass and inertia, as an
// impulse would change its velocity, but applied to its position.
void shiftAlong(Joints::Placed& a, Joints::Placed& b, Vec2 direction, double turn_a, double turn_b, double amount,
                bool rotation) {
    if (rotation) amount *= trustedShare(turn_a * amount * a.inv_inertia, turn_b * amount * b.inv_inertia);
    a.move(direction * (-amount * a.inv_mass));
    b.move(direction * (amount * b.inv_mass));
    if (!rotation) return;
    a.rotate(-turn_a * amount * a.inv_inertia);
    b.rotate(turn_b * amount * b.inv_inertia);
}

double correctionMass(const Joints::Placed& a, const Joints::Placed& b, Vec2 direction, double turn_a, double turn_b,
                      bool rotation) {
    const double turning = rotation ? turn_a * turn_a * a.inv_inertia + turn_b * turn_b * b.inv_inertia : 0.0;
    return inverseOr0((a.inv_mass + b.inv_mass) * direction.dot(direction) + turning);
}

// One limit C >= 0 pushed back when passed (C < 0), not pulled when within.
void correctLimit(Joints::Placed& a, Joints::Placed& b, Vec2 direction, double turn_a, double turn_b, double error,
                  bool rotation) {
    if (error >= 0.0) return;
    const double amount =
        -std::max(error, -kLongestJointShift) * correctionMass(a, b, direction, turn_a, turn_b, rotation);
    shiftAlong(a, b, direction, turn_a, turn_b, amount, rotation);
}

// An equation C = 0 put right in one go (a rod's cut at kLongestJointShift), as far as
// the trusted turn allows.
void correctEquation(Joints::Placed& a, Joints::Placed& b, Vec2 direction, double turn_a, double turn_b, double error,
                     bool rotation) {
    const double amount = -std::clamp(error, -kLongestJointShift, kLongestJointShift) *
                          correctionMass(a, b, direction, turn_a, turn_b, rotation);
    shiftAlong(a, b, direction, turn_a, turn_b, amount, rotation);
}

// A pin's two anchors made one point: the 2 x 2 system K x = -gap on the positions.
void correctPin(Joints::Placed& a, Joints::Placed& b, const JointDefinition& joint, bool rotation) {
    const Frame frame = frameOf(joint, a, b);
    const Vec2 ra = rotation ? frame.arm_a : Vec2{}, rb = rotation ? frame.arm_b : Vec2{};
    const double ia = rotation ? a.inv_inertia : 0.0, ib = rotation ? b.inv_inertia : 0.0;
    const double mass_sum = a.inv_mass + b.inv_mass;
    const double k11 = mass_sum + ra.y * ra.y * ia + rb.y * rb.y * ib;
    const double k12 = -ra.x * ra.y * ia - rb.x * rb.y * ib;
    const double k22 = mass_sum + ra.x * ra.x * ia + rb.x * rb.x * ib;
    const double determinant = k11 * k22 - k12 * k12;
    if (determinant <= 0.0) return;
    const Vec2 gap = frame.gap;
    const Vec2 impulse{-(k22 * gap.x - k12 * gap.y) / determinant, -(k11 * gap.y - k12 * gap.x) / determinant};
    // Without rotation the arms and inverse inertias are 0: no turn, the whole step.
    const double turn_a = -ra.cross(impulse) * ia, turn_b = rb.cross(impulse) * ib;
    const double share = trustedShare(turn_a, turn_b);
    a.move(impulse * (-share * a.inv_mass));
    b.move(impulse * (share * b.inv_mass));
    if (!rotation) return;
    a.rotate(turn_a * share);
    b.rotate(turn_b * share);
}

}  // namespace

Joints::Placed Joints::placedFrom(const RigidShape& shape) {
    return {.position = shape.center(),
            .turned = shape.angle(),
            .inv_mass = shape.invMass(),
            .inv_inertia = shape.invInertia(),
            .cosine = std::cos(shape.angle()),
            .sine = std::sin(shape.angle())};
}

// A turn by the positional passes is mostly small: a pin's correction turns a link by
// a few thousandths of a radian, a disc by a tenth or so. The cosine and sine of the
// new angle are then the old ones turned by the small one, whose cosine and sine are
// the first terms of their series (what is left out is under 1e-17 of the turn below
// kSmallTurn, under the rounding of a double): a dozen products where std::sin and
// std::cos would cost several times as much, for each body twice a pass. A larger turn
// takes the library's functions. A general saving: it holds for any body the passes
// turn, and the angle itself stays the same sum, so the shapes end where they did, to
// rounding.
void Joints::Placed::rotate(double turn) {
    turned += turn;
    constexpr double kSmallTurn = 0.25;  // rad
    if (std::abs(turn) >= kSmallTurn) {
        cosine = std::cos(turned);
        sine = std::sin(turned);
        return;
    }
    const double t2 = turn * turn;
    // Most turns a pass makes are tiny: under 0.01 rad the series' terms past t^5 and
    // t^6 are below 2e-18, under a double's rounding, so they are left out.
    constexpr double kTinyTurn = 0.01;  // rad
    if (std::abs(turn) < kTinyTurn) {
        const double tiny_sine = turn * (1.0 - t2 * (1.0 / 6.0 - t2 * (1.0 / 120.0)));
        const double tiny_cosine = 1.0 - t2 * (1.0 / 2.0 - t2 * (1.0 / 24.0 - t2 * (1.0 / 720.0)));
        const double turned_cosine = cosine * tiny_cosine - sine * tiny_sine;
        sine = sine * tiny_cosine + cosine * tiny_sine;
        cosine = turned_cosine;
        return;
    }
    // sin t = t - t^3/3! + ... - t^11/11!,  cos t = 1 - t^2/2! + ... + t^12/12!, nested.
    constexpr double k2 = 1.0 / 2.0, k3 = 1.0 / 6.0, k4 = 1.0 / 24.0, k5 = 1.0 / 120.0, k6 = 1.0 / 720.0;
    constexpr double k7 = 1.0 / 5040.0, k8 = 1.0 / 40320.0, k9 = 1.0 / 362880.0, k10 = 1.0 / 3628800.0;
    constexpr double k11 = 1.0 / 39916800.0, k12 = 1.0 / 479001600.0;
    const double small_sine = turn * (1.0 - t2 * (k3 - t2 * (k5 - t2 * (k7 - t2 * (k9 - t2 * k11)))));
    const double small_cosine = 1.0 - t2 * (k2 - t2 * (k4 - t2 * (k6 - t2 * (k8 - t2 * (k10 - t2 * k12)))));
    const double turned_cosine = cosine * small_cosine - sine * small_sine;
    sine = sine * small_cosine + cosine * small_sine;
    cosine = turned_cosine;
}

void Joints::correctPositions(ShapeList shapes, const WorldSettings& world) {
    // Soft joints are left to their springs: a soft row holds a load only where its
    // error has grown to pull with it (C = F / (m w^2)), and the passes would close that
    // error after every step, so that each step's bias asked for speed again: a bob at
    // rest on a soft pin kept g h / a2 of velocity (0.52 px/s at 2000 px/s^2) down it.
    if (!world.positional_correction || !world.movement || jointHertz(world, world.dt) > 0.0) return;
    const bool rotation = world.rotation;
    // The passes move each body's centre and angle alone, and each shape is put where
    // its body ended once, after the last pass: turning a rectangle turns its four
    // corners and rebuilds its normals, which a body between two pins would otherwise
    // pay twice a pass. The centres and angles are the ones the shapes' own moves and
    // turns would reach, the same sums in the same order.
    //
    // The bodies placed are the ones prepare placed (the joints the passes meet are the
    // ones it prepared), where they are now; a body no joint holds is left alone, so a
    // pile beside a pendulum costs the passes nothing.
    if (placed_known_.size() != shapes.size()) return;  // the list changed since prepare
    for (std::size_t i = 0; i < shapes.size(); ++i) {
        if (placed_known_[i]) placed_[i] = placedFrom(*shapes[i]);
    }
    for (int pass = 0; pass < world.position_iterations; ++pass) {
        for (const std::size_t k : order_) {
            if (shapes[places_[k]->first]->isResting() && shapes[places_[k]->second]->isResting()) continue;
            Placed& a = placed_[places_[k]->first];
            Placed& b = placed_[places_[k]->second];
            const JointDefinition& joint = joints_[k].definition;
            // The angle first: a pin then works out its own anchors, after the angle's
            // turn (correctPin), so the anchors are worked out here only for a slider or
            // a rod, where they are used before anything moves.
            const double angle = angleOf(joint, a, b);
            switch (joint.type) {
                case JointType::revolute:
                    if (joint.limit) {
                        correctLimit(a, b, {}, 1.0, 1.0, angle - joint.limit->lower, rotation);
                        correctLimit(a, b, {}, -1.0, -1.0, joint.limit->upper - angle, rotation);
                    }
                    correctPin(a, b, joint, rotation);
                    break;
                case JointType::weld:
                    correctEquation(a, b, {}, 1.0, 1.0, angle, rotation);
                    correctPin(a, b, joint, rotation);
                    break;
                case JointType::prismatic: {
                    correctEquation(a, b, {}, 1.0, 1.0, angle, rotation);
                    const Frame now = frameOf(joint, a, b);
                    const Vec2 axis = axisOf(joint, a), normal = across(axis);
                    const Vec2 arm_a = now.gap + now.arm_a;
                    correctEquation(a, b, normal, arm_a.cross(normal), now.arm_b.cross(normal), normal.dot(now.gap),
                                    rotation);
                    if (joint.limit) {
                        const Frame last = frameOf(joint, a, b);
                        const double translation = axis.dot(last.gap);
                        const Vec2 reach = last.gap + last.arm_a;
                        correctLimit(a, b, axis, reach.cross(axis), last.arm_b.cross(axis),
                                     translation - joint.limit->lower, rotation);
                        correctLimit(a, b, -axis, -reach.cross(axis), -last.arm_b.cross(axis),
                                     joint.limit->upper - translation, rotation);
                    }
                    break;
                }
                case JointType::distance: {
                    const Frame frame = frameOf(joint, a, b);
                    const double length = frame.gap.length();
                    if (length < kShortestLink) break;
                    const Vec2 along = frame.gap * (1.0 / length);
                    const double turn_a = frame.arm_a.cross(along), turn_b = frame.arm_b.cross(along);
                    if (joint.length_range) {
                        correctLimit(a, b, along, turn_a, turn_b, length - joint.length_range->lower, rotation);
                        correctLimit(a, b, -along, -turn_a, -turn_b, joint.length_range->upper - length, rotation);
                    } else if (joint.hertz == 0.0) {
                        correctEquation(a, b, along, turn_a, turn_b, length - joint.length, rotation);
                    }
                    break;
                }
            }
        }
    }
    for (std::size_t i = 0; i < shapes.size(); ++i) {
        if (!placed_known_[i]) continue;
        RigidShape& shape = *shapes[i];
        if (placed_[i].center() != shape.center()) shape.move(placed_[i].center() - shape.center());
        if (placed_[i].angle() != shape.angle()) shape.rotate(placed_[i].angle() - shape.angle());
    }
}

}  // namespace engine
