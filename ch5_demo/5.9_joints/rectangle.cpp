#include "rectangle.h"

#include <cmath>

namespace engine {

namespace {
// A plate's moment of inertia about its centre sums m r^2 over the whole area; for a
// w x h rectangle it comes to I = m (w^2 + h^2) / 12.
constexpr double kRectangleInertiaDivisor = 12.0;
}  // namespace

// The corners are the points farthest from the centre, half a diagonal away, so the
// bounding circle has half the diagonal as its radius.
Rectangle::Rectangle(Vec2 center, double width, double height, PhysicalAttributes attributes)
    : RigidShape(ShapeType::Rectangle, center,
                 std::hypot(checkedSize(width, "rectangle width"), checkedSize(height, "rectangle height")) / 2,
                 attributes),
      width_(width),
      height_(height) {
    const double half_w = width / 2;
    const double half_h = height / 2;
    vertex_ = {
        Vec2{center.x - half_w, center.y - half_h},  // 0 top-left (y grows downwards)
        Vec2{center.x + half_w, center.y - half_h},  // 1 top-right
        Vec2{center.x + half_w, center.y + half_h},  // 2 bottom-right
        Vec2{center.x - half_w, center.y + half_h},  // 3 bottom-left
    };
    computeFaceNormals();
    updateInertia();
}

double Rectangle::rotationalInertia(double mass) const {
    return mass * (width_ * width_ + height_ * height_) / kRectangleInertiaDivisor;
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

void Rectangle::move(Vec2 offset) {
    for (Vec2& vertex : vertex_) vertex = vertex.add(offset);
    center_ = center_.add(offset);
}

void Rectangle::rotate(double angle) {
    // Turning the corners is all it takes; the normals are rebuilt from them, so they
    // stay unit length and perpendicular to the sides however many turns pile up.
    angle_ += angle;
    for (Vec2& vertex : vertex_) vertex = vertex.rotate(center_, angle);
    computeFaceNormals();
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
