// The narrow phase for a rectangle (the book's RigidBody/Rectangle_collision.js).
//
// Two rectangles: the separating axis theorem, with support points. Two convex shapes
// are apart exactly when some line, square to one of their sides, has their shadows
// apart; for rectangles that leaves the four face normals of each to try.
//
// A face's support point (Figure 3-14) is the other rectangle's corner that lies
// deepest behind that face, measured against its outward normal. A face with no corner
// behind it at all is a separating axis: the whole other rectangle lies in front of
// it, and the test can stop. When every face of both rectangles has a support point,
// they overlap, and the face whose support point is shallowest (the axis of least
// penetration, Figure 3-15) gives the smallest move that parts them: its depth is the
// collision depth, its normal the collision normal, and the support point one end of
// the collision segment.

#include <array>
#include <cstddef>
#include <optional>

#include "rectangle.h"

namespace engine {

namespace {

struct SupportPoint {
    Vec2 corner;
    double depth;  // how far behind the face, always > 0
};

// The corner farthest behind the face that passes through `on_face` with outward
// normal `normal`, or nothing when no corner is behind it. A corner exactly on the
// face is not behind it: rectangles that only touch do not collide.
std::optional<SupportPoint> findSupportPoint(const std::array<Vec2, 4>& corners, Vec2 normal, Vec2 on_face) {
    std::optional<SupportPoint> deepest;
    for (Vec2 corner : corners) {
        const double depth = (on_face - corner).dot(normal);
        if (depth > 0 && (!deepest || depth > deepest->depth)) deepest = SupportPoint{corner, depth};
    }
    return deepest;
}

struct Penetration {
    double depth;
    Vec2 normal;         // the face's outward normal: from its rectangle towards the other
    Vec2 support_point;  // the other rectangle's corner, `depth` behind the face
};

// Of all the faces of `faces_of`, the one that `corners_of` goes least deep behind,
// or nothing when one of the faces separates the two.
std::optional<Penetration> findAxisLeastPenetration(const Rectangle& faces_of, const Rectangle& corners_of) {
    std::optional<Penetration> least;
    for (std::size_t face = 0; face < faces_of.faceNormals().size(); ++face) {
        const Vec2 normal = faces_of.faceNormals()[face];
        // Face i starts at vertex i (see rectangle.h), so that vertex is on it.
        const auto support = findSupportPoint(corners_of.vertices(), normal, faces_of.vertices()[face]);
        if (!support) return std::nullopt;
        if (!least || support->depth < least->depth) least = Penetration{support->depth, normal, support->corner};
    }
    return least;
}

}  // namespace

std::optional<CollisionInfo> Rectangle::collisionTest(const RigidShape& other) const {
    if (other.type() == ShapeType::Rectangle) return collidedRectRect(static_cast<const Rectangle&>(other));
    return std::nullopt;  // a rectangle and a circle: not in this project yet
}

// Both rectangles' faces must be tried: the other's corners behind this one's faces,
// then this one's corners behind the other's. The shallower answer wins.
std::optional<CollisionInfo> Rectangle::collidedRectRect(const Rectangle& other) const {
    const auto into_this = findAxisLeastPenetration(*this, other);
    if (!into_this) return std::nullopt;
    const auto into_other = findAxisLeastPenetration(other, *this);
    if (!into_other) return std::nullopt;

    if (into_this->depth < into_other->depth) {
        // This rectangle's face: its normal already points from this towards other. The
        // segment runs from other's corner out to this face.
        return CollisionInfo(into_this->depth, into_this->normal, into_this->support_point);
    }
    // The other's face (ties too): its normal points from other towards this, so it is
    // turned round. The segment runs from the other's face in to this rectangle's corner.
    const Penetration& face_of_other = *into_other;
    return CollisionInfo(face_of_other.depth, -face_of_other.normal,
                         face_of_other.support_point + face_of_other.normal * face_of_other.depth);
}

}  // namespace engine
