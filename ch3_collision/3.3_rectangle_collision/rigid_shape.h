#pragma once
// RigidShape: what every simulated object has, whatever its outline (the book's
// RigidBody/RigidShape.js). Rectangle and Circle build on it.
//
// Why a class hierarchy: the book builds Rectangle and Circle on a RigidShape
// prototype, and the engine walks one list of shapes calling draw (later update, move,
// rotate) without asking which kind each one is. A base class with virtual functions
// says exactly that, so every chapter's change lands in the same file as in the book.
// Where the two kinds must be told apart (the collision tests of chapter 3), type()
// plays the role of the book's mType. The Core owns its shapes through unique_ptr.
//
// Each fixed step of the engine loop calls update() on every shape. Nothing moves by
// itself in chapter 3, so it does nothing yet; chapter 4 puts motion there.
//
// The broad phase of collision detection (Figure 3-4): every shape is wrapped in a
// bounding circle about its centre, and two shapes can only touch when their bounding
// circles do. That test costs one distance, whatever the shapes are.
//
// The narrow phase, collisionTest, is exact, and its answer depends on both kinds of
// shape: each kind implements it in its own file (circle_collision.cpp,
// rectangle_collision.cpp) and asks the other shape's type() which test applies.

#include <optional>

#include "canvas.h"
#include "collision_info.h"
#include "vec2.h"

namespace engine {

using lib::Vec2;

enum class ShapeType { Rectangle, Circle };

class RigidShape {
public:
    virtual ~RigidShape() = default;

    ShapeType type() const { return type_; }
    Vec2 center() const { return center_; }
    double angle() const { return angle_; }  // radians; turns clockwise on screen (y down)

    // Radius of the smallest circle about the centre that holds the whole shape.
    double boundRadius() const { return bound_radius_; }
    // True when the two bounding circles overlap or touch: the shapes *may* collide.
    bool boundTest(const RigidShape& other) const;
    // The exact test: the collision info when the two shapes overlap, nothing when not.
    virtual std::optional<CollisionInfo> collisionTest(const RigidShape& other) const = 0;

    virtual void move(Vec2 offset) = 0;
    // Turns the shape about its centre by `angle` radians (clockwise on screen).
    virtual void rotate(double angle) = 0;
    void update();

    virtual void draw(browser::Canvas& context) const = 0;

protected:
    RigidShape(ShapeType type, Vec2 center, double bound_radius);
    RigidShape(const RigidShape&) = default;
    RigidShape& operator=(const RigidShape&) = default;

    ShapeType type_;
    Vec2 center_;
    double angle_ = 0.0;
    double bound_radius_;
};

}  // namespace engine
