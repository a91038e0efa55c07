#include "rigid_shape.h"

#include <cmath>
#include <sstream>
#include <string>

namespace engine {

namespace {
// Gravity is the only force in the book, and nothing applies a torque: the angular
// acceleration is always 0. update() still adds it, to show that turning takes the
// same two steps as moving.
constexpr double kAngularAcceleration = 0.0;  // rad/s^2

[[noreturn]] void refuse(std::string_view name, std::string_view rule, double got) {
    std::ostringstream message;
    message << name << " must be " << rule << " (got " << got << ")";
    throw InvalidShape(message.str());
}

void check(bool accepted, std::string_view name, std::string_view rule, double got) {
    if (!accepted) refuse(name, rule, got);
}

std::string_view nameOf(ShapeType type) {
    switch (type) {
        case ShapeType::Rectangle: return "rectangle";
        case ShapeType::Circle: return "circle";
        case ShapeType::Polygon: return "polygon";
    }
    return "shape";
}
}  // namespace

double RigidShape::checkedSize(double size, std::string_view name) {
    check(std::isfinite(size) && size > 0.0, name, "a finite number > 0", size);
    return size;
}

// Every shape starts unturned and at rest; angle_ keeps count of the turns that follow.
RigidShape::RigidShape(ShapeType type, Vec2 center, double bound_radius, PhysicalAttributes attributes)
    : type_(type),
      center_(center),
      bound_radius_(bound_radius),
      inv_mass_(attributes.mass > 0.0 ? 1.0 / attributes.mass : 0.0),
      friction_(attributes.friction),
      restitution_(attributes.restitution) {
    std::string shape(nameOf(type));
    check(std::isfinite(center.x), shape + " center x", "a finite number", center.x);
    check(std::isfinite(center.y), shape + " center y", "a finite number", center.y);
    check(std::isfinite(attributes.mass) && attributes.mass >= 0.0, shape + " mass", "a finite number >= 0",
          attributes.mass);
    check(std::isfinite(attributes.friction) && attributes.friction >= 0.0, shape + " friction", "a finite number >= 0",
          attributes.friction);
    check(attributes.restitution >= 0.0 && attributes.restitution <= 1.0, shape + " restitution", "a number in [0, 1]",
          attributes.restitution);
}

bool RigidShape::boundTest(const RigidShape& other) const {
    // Two circles overlap exactly when their centres are no farther apart than their
    // radii added up; at exactly that distance they touch, which counts.
    return center_.distance(other.center_) <= bound_radius_ + other.bound_radius_;
}

// One step of Newton's second law, by the world's integrator (Figure 4-2). Both take
// the same new velocity, v += a dt; they differ in which velocity moves the shape.
// Symplectic Euler (the book's) moves with the *new* one, p += v_new dt; explicit
// Euler with the one from before, p += v_old dt. Under constant gravity, after n steps
// of a fall from rest, symplectic Euler has fallen g dt^2 n (n + 1) / 2 and explicit
// Euler g dt^2 n (n - 1) / 2, either side of the exact g (n dt)^2 / 2. The angle
// follows the same two steps with the angular velocity, unless the world turns
// rotation off.
void RigidShape::update(const WorldSettings& world) {
    if (!world.movement) return;
    const double dt = world.dt;
    const bool symplectic = world.integrator == Integrator::symplectic;
    // F = m a with gravity's force m g gives a = g for every mass; a static body has no
    // acceleration at all, and a kinematic one (5.9) moves by its velocity alone.
    const Vec2 acceleration = isDynamic() ? world.gravity : Vec2{};
    const Vec2 new_velocity = velocity_ + acceleration * dt;
    move((symplectic ? new_velocity : velocity_) * dt);
    velocity_ = new_velocity;
    if (!world.rotation) return;
    const double new_angular_velocity = angular_velocity_ + kAngularAcceleration * dt;
    rotate((symplectic ? new_angular_velocity : angular_velocity_) * dt);
    angular_velocity_ = new_angular_velocity;
}

void RigidShape::updateMass(double delta) {
    if (kinematic_) return;  // 5.9: infinite, whatever the keys say
    const double mass = this->mass() + delta;
    if (mass <= 0.0) {
        inv_mass_ = 0.0;
        velocity_ = Vec2{};
        angular_velocity_ = 0.0;
    } else {
        inv_mass_ = 1.0 / mass;
    }
    updateInertia();
}

void RigidShape::updateInertia() { inv_inertia_ = inv_mass_ == 0.0 ? 0.0 : 1.0 / rotationalInertia(mass()); }

void RigidShape::makeKinematic() {
    kinematic_ = true;
    inv_mass_ = 0.0;
    inv_inertia_ = 0.0;
}

// Falling asleep stops the shape dead: the little speed it rested with would otherwise
// carry it on when it wakes, after any time asleep.
void RigidShape::fallAsleep(std::uint64_t island) {
    sleep_.asleep = true;
    sleep_.island = island;
    setVelocity(Vec2{});
    setAngularVelocity(0.0);
}

}  // namespace engine
