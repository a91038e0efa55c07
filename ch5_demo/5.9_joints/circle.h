#pragma once
// A rigid circle (the book's RigidBody/Circle.js). A circle looks the same at every
// angle, so it carries a reference point on its rim, drawn as a spoke to the centre,
// that makes its rotation visible.

#include "rigid_shape.h"

namespace engine {

class Circle : public RigidShape {
public:
    Circle(Vec2 center, double radius, PhysicalAttributes attributes = {});

    double radius() const { return radius_; }
    // The rim point the spoke is drawn to: straight above the centre before any rotation.
    Vec2 startpoint() const { return startpoint_; }

    // In circle_collision.cpp.
    std::optional<CollisionInfo> collisionTest(const RigidShape& other) const override;

    void move(Vec2 offset) override;
    void rotate(double angle) override;
    void draw(browser::Canvas& context) const override;

private:
    double rotationalInertia(double mass) const override;
    std::optional<CollisionInfo> collidedCircCirc(const Circle& other) const;

    double radius_;
    Vec2 startpoint_;
};

}  // namespace engine
