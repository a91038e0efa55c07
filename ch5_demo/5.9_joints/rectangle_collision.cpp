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
//
// A rectangle and a circle: a circle has no corners to serve as support points. The
// test asks instead where the circle's centre lies: which face it is nearest, and
// whether it is straight in front of that face or past one of its ends.

#include <array>
#include <cstddef>
#include <limits>
#include <optional>

#include "circle.h"
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
    // Starting at depth 0, one comparison both keeps out the corners not behind the
    // face and picks the deepest: the same corner as asking the two apart, one branch less.
    SupportPoint deepest{on_face, 0.0};
    for (Vec2 corner : corners) {
        const double depth = (on_face - corner).dot(normal);
        if (depth > deepest.depth) deepest = SupportPoint{corner, depth};
    }
    if (deepest.depth > 0) return deepest;
    return std::nullopt;
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

struct NearestEdge {
    std::size_t face;
    double distance;  // of the point in front of the face's line; negative behind it
    bool outside;     // the point is in front of this face, so outside the rectangle
};

// Step A (Figure 3-19): the face nearest to a point. A point inside is behind every
// face, and the nearest face is the one it is least far behind. A point outside is in
// front of one or two faces; the first one found will do (see collidedRectCirc).
NearestEdge findNearestEdge(const Rectangle& box, Vec2 point) {
    NearestEdge nearest{0, -std::numeric_limits<double>::infinity(), false};
    for (std::size_t face = 0; face < box.faceNormals().size(); ++face) {
        const double distance = (point - box.vertices()[face]).dot(box.faceNormals()[face]);
        if (distance > 0) return {face, distance, true};
        if (distance > nearest.distance) nearest = {face, distance, false};
    }
    return nearest;
}

// The circle's centre lies `distance` along `normal` from the rectangle's nearest
// point (behind it when negative). Moving the circle radius - distance further along
// the normal leaves it just touching. The segment runs from the circle's deepest point,
// its rim at centre - normal * radius, to that nearest point.
CollisionInfo circleOutAlong(Vec2 normal, double distance, const Circle& circle) {
    return CollisionInfo(circle.radius() - distance, normal, circle.center() - normal * circle.radius());
}

// Steps B1 and B2 (Figure 3-20): the centre is nearest to a corner of the rectangle.
std::optional<CollisionInfo> collideWithCorner(Vec2 corner, const Circle& circle) {
    const Vec2 from_corner = circle.center() - corner;
    const double distance = from_corner.length();
    if (distance > circle.radius()) return std::nullopt;
    return circleOutAlong(from_corner.normalize(), distance, circle);
}

}  // namespace

std::optional<CollisionInfo> Rectangle::collisionTest(const RigidShape& other) const {
    if (other.type() == ShapeType::Circle) return collidedRectCirc(static_cast<const Circle&>(other));
    if (other.type() == ShapeType::Polygon)
        return turnedRound(other.collisionTest(*this));  // 5.8's polygon_collision.cpp
    return collidedRectRect(static_cast<const Rectangle&>(other));
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

// Figure 3-17: the outside of a face splits into three regions along the lines of its
// two neighbouring faces: R1 beyond the corner where the face starts, R2 beyond the
// corner where it ends, and R3 straight in front of it. In R3 the face is the nearest
// part of the rectangle, in R1 and R2 the corner. If the centre is outside, the face
// found first has it in front; a centre in front of two faces lies beyond their common
// corner, which is R1 or R2 of either face, so the first face gives the right answer.
std::optional<CollisionInfo> Rectangle::collidedRectCirc(const Circle& circle) const {
    const Vec2 center = circle.center();
    const NearestEdge edge = findNearestEdge(*this, center);
    const Vec2 normal = face_normal_[edge.face];
    // Step C: a centre inside always collides; out through the nearest face.
    if (!edge.outside) return circleOutAlong(normal, edge.distance, circle);

    const Vec2 face_start = vertex_[edge.face];
    const Vec2 face_end = vertex_[(edge.face + 1) % vertex_.size()];
    // R1 and R2: the centre is past one end of the face, measured along the face.
    if ((center - face_start).dot(face_end - face_start) < 0) return collideWithCorner(face_start, circle);
    if ((center - face_end).dot(face_start - face_end) < 0) return collideWithCorner(face_end, circle);
    // R3: only the distance to the face's line counts. A circle just touching the face
    // does not collide here (a circle just touching a corner does, with depth 0).
    if (edge.distance < circle.radius()) return circleOutAlong(normal, edge.distance, circle);
    return std::nullopt;
}

}  // namespace engine
