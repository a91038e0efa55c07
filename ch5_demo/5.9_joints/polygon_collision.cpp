// The narrow phase for a polygon (5.8). Every pair with a polygon in it is one of the
// book's two tests, carried over to n sides:
//  - with a polygon or a rectangle: the separating axis test with support points
//    (polygon_sat.h), the rectangle taken as the 4-gon of its corners;
//  - with a circle: the book's rectangle-circle test (rectangle_collision.cpp), which
//    needs of the rectangle only its faces, their normals and their ends.

#include <cstddef>
#include <limits>

#include "circle.h"
#include "polygon.h"
#include "polygon_sat.h"
#include "rectangle.h"

namespace engine {

namespace {

std::optional<CollisionInfo> infoOf(const std::optional<SatCollision>& collision) {
    if (!collision) return std::nullopt;
    return CollisionInfo(collision->depth, collision->normal, collision->start);
}

// The circle's centre `distance` along `normal` from the polygon's nearest point:
// moving the circle radius - distance further along the normal parts them; the segment
// starts on the circle's rim, at its deepest point.
CollisionInfo circleOut(Vec2 normal, double distance, const Circle& circle) {
    return CollisionInfo(circle.radius() - distance, normal, circle.center() - normal * circle.radius());
}

std::optional<CollisionInfo> circleOnCorner(Vec2 corner, const Circle& circle) {
    const Vec2 from_corner = circle.center() - corner;
    const double distance = from_corner.length();
    if (distance > circle.radius()) return std::nullopt;
    return circleOut(from_corner.normalize(), distance, circle);
}

}  // namespace

std::optional<CollisionInfo> polygonCircleCollision(const ConvexPolygon& polygon, const Circle& circle) {
    const Vec2 center = circle.center();
    // The face nearest the centre: the first with the centre in front of it, or, for a
    // centre inside, the one it lies least far behind (Figure 3-19, step A).
    std::size_t face = 0;
    double distance = -std::numeric_limits<double>::infinity();
    bool outside = false;
    for (std::size_t i = 0; i < polygon.count; ++i) {
        const double d = (center - polygon.vertices[i]).dot(polygon.normals[i]);
        if (d > 0) {
            face = i;
            distance = d;
            outside = true;
            break;
        }
        if (d > distance) {
            face = i;
            distance = d;
        }
    }
    const Vec2 normal = polygon.normals[face];
    if (!outside) return circleOut(normal, distance, circle);  // step C: inside, out through the nearest face
    // Past one end of the face: the corner is nearest (R1, R2); in front of it: the face (R3).
    const Vec2 start = polygon.corner(face);
    const Vec2 end = polygon.corner(face + 1);
    if ((center - start).dot(end - start) < 0) return circleOnCorner(start, circle);
    if ((center - end).dot(start - end) < 0) return circleOnCorner(end, circle);
    if (distance < circle.radius()) return circleOut(normal, distance, circle);
    return std::nullopt;
}

std::optional<CollisionInfo> Polygon::collisionTest(const RigidShape& other) const {
    switch (other.type()) {
        case ShapeType::Circle: return polygonCircleCollision(outline_, static_cast<const Circle&>(other));
        case ShapeType::Rectangle:
            return infoOf(satCollision(outline_, outlineOf(static_cast<const Rectangle&>(other))));
        case ShapeType::Polygon: return infoOf(satCollision(outline_, static_cast<const Polygon&>(other).outline_));
    }
    return std::nullopt;
}

}  // namespace engine
