#pragma once
// Area, centroid and moment of inertia of a convex polygon of even density. Not in the
// book, but by its rule for the other shapes: a scene gives the mass, and the shape
// gives the moment of inertia as mass times a length squared that depends only on its
// outline (circle.cpp: m r^2 / 2; rectangle.cpp: m (w^2 + h^2) / 12). For a polygon that
// length squared is inertia_per_mass below, and its rotationalInertia(mass) is
// mass * inertia_per_mass, as the rectangle's is mass * (w^2 + h^2) / 12.
//
// The centroid matters as much: a body turns about its centre of mass, which for an
// even density is the centroid of the area. A polygon's centroid is in general not the
// average of its corners (a triangle's is; a trapezium's is not), so the stage moves
// the hull so that its centroid is the body's centre.

#include <span>

#include "convex_polygon.h"

namespace engine {

struct PolygonMass {
    double area = 0.0;              // px^2
    Vec2 centroid;                  // the area's centre, px
    double inertia_per_mass = 0.0;  // px^2: the moment of inertia about the centroid, per unit of mass
};

// For a convex polygon's corners in counter-clockwise order (convexHull's), three or more.
PolygonMass polygonMass(std::span<const Vec2> ccw_corners);

}  // namespace engine
