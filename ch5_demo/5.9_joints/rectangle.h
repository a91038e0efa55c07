#pragma once
// A rigid rectangle (the book's RigidBody/Rectangle.js). Besides its centre and size it
// keeps its four corners and the outward unit normal of each side, because the
// collision tests of chapter 3 work on exactly those.
//
//          face 0 (top), normal up
//      v0 ------------------- v1
//       |                     |
//  face |        center       | face 1 (right),
//  3    |          +          | normal right
//       |                     |
//      v3 ------------------- v2
//          face 2 (bottom), normal down
//
// Face i runs from vertex i to vertex i+1. Its outward normal points the way the
// neighbouring side runs *towards* face i: face 0's normal is the direction from v2 to
// v1. Numbering is before any rotation; the numbers turn with the rectangle.

#include <array>

#include "rigid_shape.h"

namespace engine {

class Circle;

class Rectangle : public RigidShape {
public:
    Rectangle(Vec2 center, double width, double height, PhysicalAttributes attributes = {});

    double width() const { return width_; }
    double height() const { return height_; }
    const std::array<Vec2, 4>& vertices() const { return vertex_; }
    const std::array<Vec2, 4>& faceNormals() const { return face_normal_; }

    // In rectangle_collision.cpp.
    std::optional<CollisionInfo> collisionTest(const RigidShape& other) const override;
    // Public because a circle's collisionTest asks the rectangle too. The normal points
    // from this rectangle towards the circle.
    std::optional<CollisionInfo> collidedRectCirc(const Circle& circle) const;

    void move(Vec2 offset) override;
    void rotate(double angle) override;
    void draw(browser::Canvas& context) const override;

private:
    double rotationalInertia(double mass) const override;
    void computeFaceNormals();
    std::optional<CollisionInfo> collidedRectRect(const Rectangle& other) const;

    double width_;
    double height_;
    std::array<Vec2, 4> vertex_;
    std::array<Vec2, 4> face_normal_;
};

}  // namespace engine
