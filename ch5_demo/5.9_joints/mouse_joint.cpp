#include "mouse_joint.h"

#include <algorithm>
#include <numbers>

#include "circle.h"
#include "contact_solver.h"
#include "joints.h"
#include "narrow_phase.h"

namespace engine {

namespace {

// The pointer as a shape: a circle this small about the point, tested against each
// shape by the narrow phase the shapes already have, whatever their outlines.
constexpr double kProbeRadius = 0.5;  // px
constexpr double kDotRadius = 3.0;    // px, the ends of the line drawn

}  // namespace

std::optional<std::size_t> MouseJoint::grab(ShapeList shapes, Vec2 point) {
    const Circle probe(point, kProbeRadius);
    for (std::size_t k = shapes.size(); k-- > 0;) {
        const RigidShape& shape = *shapes[k];
        if (!shape.isDynamic() || !narrowPhase(probe, shape)) continue;
        body_ = shape.id();
        local_anchor_ = toBody(point - shape.center(), shape.angle());
        target_ = point;
        total_ = {};
        return k;
    }
    return std::nullopt;
}

Vec2 MouseJoint::grabbedPoint(const RigidShape& shape) const {
    return shape.center() + toWorld(local_anchor_, shape.angle());
}

bool MouseJoint::begin(ShapeList shapes, const WorldSettings& world) {
    step_.reset();
    if (body_ == 0) return false;
    const auto held = std::find_if(shapes.begin(), shapes.end(), [&](const auto& s) { return s->id() == body_; });
    if (held == shapes.end() || !(*held)->isDynamic()) {  // removed, or made static by a key
        release();
        return false;
    }
    const RigidShape& shape = **held;
    if (shape.sleep().asleep || !world.movement) return false;

    const double h = world.dt;
    const double inv_mass = shape.invMass();
    const double inv_inertia = world.rotation ? shape.invInertia() : 0.0;
    const double mass = shape.mass();
    // The spring the constraint stands for (mouse_joint.h): stiffness and damping in
    // proportion to the mass, so every shape follows at the same frequency.
    const double omega = 2.0 * std::numbers::pi * kHertz;
    const double stiffness = mass * omega * omega;              // k, (px/s^2) per px, times the mass
    const double damping = 2.0 * mass * kDampingRatio * omega;  // c
    const double gamma = 1.0 / (h * (damping + h * stiffness));
    const double beta = h * stiffness / (damping + h * stiffness);

    Step step;
    step.index = static_cast<std::size_t>(held - shapes.begin());
    step.arm = toWorld(local_anchor_, shape.angle());
    step.bias = (shape.center() + step.arm - target_) * (beta / h);  // C = p - target, px
    step.gamma = gamma;
    // K + gamma 1: a unit impulse P at the arm r changes the point's velocity by P / m
    // and, through the turn (r x P) / I, by (r x P) / I times (-r.y, r.x).
    step.k11 = inv_mass + inv_inertia * step.arm.y * step.arm.y + gamma;
    step.k12 = -inv_inertia * step.arm.x * step.arm.y;
    step.k22 = inv_mass + inv_inertia * step.arm.x * step.arm.x + gamma;
    step.most = kMaxPullAcceleration * mass * h;
    step_ = step;
    return true;
}

void MouseJoint::solveOn(SolverBody& body) {
    const Step& step = *step_;
    const double w = body.velocity.angular;
    const Vec2 point_velocity = body.velocity.linear + Vec2{-w * step.arm.y, w * step.arm.x};
    // The total already given counts as the spring's own give (gamma): the iterations
    // stop changing it when it is the implicit spring's impulse for the step.
    const Vec2 wanted = (point_velocity + step.bias + total_ * step.gamma) * -1.0;
    const double determinant = step.k11 * step.k22 - step.k12 * step.k12;  // > 0: K is semi-definite, gamma > 0
    const Vec2 change{(step.k22 * wanted.x - step.k12 * wanted.y) / determinant,
                      (step.k11 * wanted.y - step.k12 * wanted.x) / determinant};
    Vec2 total = total_ + change;
    if (total.length() > step.most) total = total * (step.most / total.length());
    const Vec2 applied = total - total_;
    total_ = total;
    body.velocity.linear += applied * body.inv_mass;
    body.velocity.angular += step.arm.cross(applied) * body.inv_inertia;
}

void MouseJoint::apply(ShapeList shapes, const WorldSettings& world) {
    if (!begin(shapes, world)) return;
    RigidShape& shape = *shapes[step_->index];
    // The passes keep nothing from one step to the next: the pull starts from 0 each step,
    // and one solve is exact for the shape alone.
    total_ = {};
    // The spin's damping, implicitly as the spring: dw/dt = -kSpinDamping w over h.
    SolverBody body{.velocity = {shape.velocity(), shape.angularVelocity() / (1.0 + world.dt * kSpinDamping)},
                    .pseudo = {},
                    .inv_mass = shape.invMass(),
                    .inv_inertia = world.rotation ? shape.invInertia() : 0.0};
    solveOn(body);
    shape.setVelocity(body.velocity.linear);
    shape.setAngularVelocity(body.velocity.angular);
    step_.reset();
}

void MouseJoint::prepare(ShapeList shapes, std::vector<SolverBody>& bodies, const WorldSettings& world) {
    if (!begin(shapes, world)) {
        total_ = {};
        return;
    }
    SolverBody& body = bodies[step_->index];
    body.velocity.angular /= 1.0 + world.dt * kSpinDamping;
    if (!world.warm_starting) total_ = {};
    // The last step's total, given again (capped to this step's most): the iterations
    // start at the answer instead of at 0, as the contacts' and the joints' do.
    if (total_.length() > step_->most) total_ = total_ * (step_->most / total_.length());
    body.velocity.linear += total_ * body.inv_mass;
    body.velocity.angular += step_->arm.cross(total_) * body.inv_inertia;
}

void MouseJoint::solve(std::vector<SolverBody>& bodies) {
    if (step_) solveOn(bodies[step_->index]);
}

void MouseJoint::draw(browser::Canvas& context, ShapeList shapes) const {
    if (body_ == 0) return;
    const auto held = std::find_if(shapes.begin(), shapes.end(), [&](const auto& s) { return s->id() == body_; });
    if (held == shapes.end()) return;
    const Vec2 grabbed = grabbedPoint(**held);
    context.setStrokeStyle(kLineColor);
    context.beginPath();
    context.moveTo(grabbed.x, grabbed.y);
    context.lineTo(target_.x, target_.y);
    context.stroke();
    for (const Vec2 end : {grabbed, target_}) {
        context.beginPath();
        context.arc(end.x, end.y, kDotRadius, 0.0, 2.0 * std::numbers::pi);
        context.stroke();
    }
}

}  // namespace engine
