#pragma once
// A rigid convex polygon (5.8, beyond the book: its "Further Exploration" names GJK as
// the way to "many-sided convex polygons"). The book's two shapes are the circle and the
// rectangle; a polygon of up to kMaxPolygonVertices corners is the rectangle's method
// carried over: its corners and each face's outward normal (convex_polygon.h), turned
// and moved with the shape, for the same separating axis test (polygon_sat.h).
//
// A scene gives its corners in the body's own frame, around "center", in any order and
// either winding: the polygon is their convex hull (convex_hull.h), moved so that the
// centre of its area lies on "center". The centre of mass must be the centre of area
// for a shape of even density to fall and turn as it should; a rectangle's is its
// middle, so the book never had to say it.
//
// Its mass is given, as every shape's is; its rotational inertia follows from its area
// (polygon_mass.h), as the rectangle's I = m (w^2 + h^2) / 12 does from its sides.

#include <span>
#include <vector>

#include "convex_polygon.h"
#include "random.h"
#include "rigid_shape.h"

namespace engine {

class Circle;

class Polygon : public RigidShape {
public:
    // `corners` in the body's frame (px from `center`, y down). Throws InvalidShape,
    // with the hull's one-line reason, when they make no convex polygon.
    Polygon(Vec2 center, std::span<const Vec2> corners, PhysicalAttributes attributes = {});

    // Its corners and face normals where it stands now, counter-clockwise.
    const ConvexPolygon& outline() const { return outline_; }
    // The same in its own frame, about its centre of area, unturned.
    const ConvexPolygon& bodyOutline() const { return body_; }

    // In polygon_collision.cpp. The normal points from this polygon towards `other`.
    std::optional<CollisionInfo> collisionTest(const RigidShape& other) const override;

    void move(Vec2 offset) override;
    void rotate(double angle) override;
    void draw(browser::Canvas& context) const override;

private:
    Polygon(Vec2 center, const ConvexPolygon& body, PhysicalAttributes attributes);
    double rotationalInertia(double mass) const override;

    ConvexPolygon body_;     // about the centre of area, unturned
    ConvexPolygon outline_;  // turned by angle_ and moved to center_
    double inertia_per_mass_ = 0.0;
};

// The corners of a rectangle as a polygon sees them (rectangle.h's order is already
// counter-clockwise in the sense convex_polygon.h uses), for the tests between the two.
ConvexPolygon outlineOf(const class Rectangle& rectangle);

// A shape with corners (a rectangle or a polygon, never a circle) as a polygon: the
// rectangle as the 4-gon of its corners. The clipping and the contact overlay see both
// kinds through it.
ConvexPolygon cornersOf(const RigidShape& shape);

// The corners of a random convex polygon about the origin, for the demo's polygons and
// the key that drops one (user_control.h): 3 to 8 corners round a circle of radius 12
// to 30 px, each at a random angle within the middle 70 % of its own share of the turn,
// so that no two bunch up and the hull keeps every one. Drawn in this order: the count,
// the radius, the first share's start, then each corner's place in its share.
std::vector<Vec2> randomCorners(browser::Random& random);

// The book's rectangle-circle test (Figure 3-17) for any convex polygon: the face
// nearest the circle's centre, then the centre in front of the face or past one of its
// ends. The normal points from the polygon towards the circle.
std::optional<CollisionInfo> polygonCircleCollision(const ConvexPolygon& polygon, const Circle& circle);

}  // namespace engine
