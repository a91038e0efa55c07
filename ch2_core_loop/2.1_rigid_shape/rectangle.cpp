#include "rectangle.h"

namespace engine {

Rectangle::Rectangle(Vec2 center, double width, double height)
    : RigidShape(ShapeType::Rectangle, center), width_(width), height_(height) {
    const double half_w = width / 2;
    const double half_h = height / 2;
    vertex_ = {
        Vec2{center.x - half_w, center.y - half_h},  // 0 top-left (y grows downwards)
        Vec2{center.x + half_w, center.y - half_h},  // 1 top-right
        Vec2{center.x + half_w, center.y + half_h},  // 2 bottom-right
        Vec2{center.x - half_w, center.y + half_h},  // 3 bottom-left
    };
    computeFaceNormals();
}

void Rectangle::computeFaceNormals() {
    // The side that ends where face i starts runs perpendicular to face i; followed
    // backwards it points straight out of face i (see the figure in rectangle.h).
    for (int i = 0; i < 4; ++i) {
        const Vec2 from = vertex_[(i + 2) % 4];
        const Vec2 to = vertex_[(i + 1) % 4];
        face_normal_[i] = to.subtract(from).normalize();
    }
}

void Rectangle::draw(browser::Canvas& context) const {
    // The canvas can only stroke axis-aligned rectangles, so turn the canvas instead:
    // put the origin on vertex 0, turn the axes by the rectangle's angle, and stroke an
    // upright width x height rectangle from there.
    context.save();
    context.translate(vertex_[0].x, vertex_[0].y);
    context.rotate(angle_);
    context.strokeRect(0, 0, width_, height_);
    context.restore();
}

}  // namespace engine
