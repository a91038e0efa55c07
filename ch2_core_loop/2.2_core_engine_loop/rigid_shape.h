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
// Each fixed step of the engine loop calls update() on every shape. In this project
// that is a stand-in for physics, there only to show the loop running: a shape that is
// not fixed sinks 1 px per update until its centre reaches the bottom of the canvas.
// Chapter 4 replaces it with real motion. The book's shape reads the canvas height from
// the global engine (gEngine.Core.mHeight); here the core hands it over, so a shape
// needs nothing of the core that holds it, and core.h includes rigid_shape.h, not the
// other way round as well.

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

    // A fixed shape ignores the sinking of update() (the book's mFix == 0); H toggles it.
    bool isFixed() const { return fixed_; }
    void setFixed(bool fixed) { fixed_ = fixed; }

    virtual void move(Vec2 offset) = 0;
    // Turns the shape about its centre by `angle` radians (clockwise on screen).
    virtual void rotate(double angle) = 0;
    void update(double canvas_height);

    virtual void draw(browser::Canvas& context) const = 0;

protected:
    RigidShape(ShapeType type, Vec2 center, bool fixed);
    RigidShape(const RigidShape&) = default;
    RigidShape& operator=(const RigidShape&) = default;

    ShapeType type_;
    Vec2 center_;
    double angle_ = 0.0;
    bool fixed_;
};

}  // namespace engine
