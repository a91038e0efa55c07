#include "mouse_joint.h"

#include <algorithm>
#include <numbers>

#include "circle.h"
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
        return k;
    }
    return std::nullopt;
}

Vec2 MouseJoint::grabbedPoint(const RigidShape& shape) const {
    return shape.center() + toWorld(local_anchor_, shape.angle());
}

void MouseJoint::apply(ShapeList shapes, const WorldSettings& world) {
    if (body_ == 0) return;
    const auto held = std::find_if(shapes.begin(), shapes.end(), [&](const auto& s) { return s->id() == body_; });
    if (held == shapes.end() || !(*held)->isDynamic()) return release();  // removed, or made static by a key
    RigidShape& shape = **held;
    if (shape.sleep().asleep || !world.movement) return;

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

    const Vec2 arm = toWorld(local_anchor_, shape.angle());
    const Vec2 error = shape.center() + arm - target_;  // C, px
    // Implicitly, as the spring: dw/dt = -kSpinDamping w over h, solved for the end of the step.
    const double w = shape.angularVelocity() / (1.0 + h * kSpinDamping);
    const Vec2 point_velocity = shape.velocity() + Vec2{-w * arm.y, w * arm.x};
    // K + gamma 1: a unit impulse P at the arm r changes the point's velocity by P / m
    // and, through the turn (r x P) / I, by (r x P) / I times (-r.y, r.x).
    const double k11 = inv_mass + inv_inertia * arm.y * arm.y + gamma;
    const double k12 = -inv_inertia * arm.x * arm.y;
    const double k22 = inv_mass + inv_inertia * arm.x * arm.x + gamma;
    const double determinant = k11 * k22 - k12 * k12;  // > 0: K is positive semi-definite, gamma > 0
    const Vec2 wanted = (point_velocity + error * (beta / h)) * -1.0;
    Vec2 impulse{(k22 * wanted.x - k12 * wanted.y) / determinant, (k11 * wanted.y - k12 * wanted.x) / determinant};
    const double most = kMaxPullAcceleration * mass * h;
    if (impulse.length() > most) impulse = impulse * (most / impulse.length());

    shape.setVelocity(shape.velocity() + impulse * inv_mass);
    shape.setAngularVelocity(w + arm.cross(impulse) * inv_inertia);
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
