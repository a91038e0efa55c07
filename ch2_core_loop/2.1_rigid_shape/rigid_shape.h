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

#include "canvas.h"
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

    virtual void draw(browser::Canvas& context) const = 0;

protected:
    RigidShape(ShapeType type, Vec2 center);
    RigidShape(const RigidShape&) = default;
    RigidShape& operator=(const RigidShape&) = default;

    ShapeType type_;
    Vec2 center_;
    double angle_ = 0.0;
};

}  // namespace engine
