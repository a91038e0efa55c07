// The polygon cut into triangles that share one point, a fan, and each triangle's area,
// centroid and second moment summed.
//
// The shared point is the average of the corners, which lies inside a convex polygon,
// and every corner is measured from it. The textbook formula measures from the origin
// instead, and its sums then cancel: for a 10 px square with a corner at (1e5, 1e5) it
// adds signed triangle areas of about 1e6 px^2 to get 100, and second moments of about
// 1e16 px^4 to get 1.7e3, each term carrying round-off of its own size. Its moment of
// inertia per unit mass comes out 16.634 px^2 instead of 16.667: three good digits of
// sixteen. Measured from a point inside, every triangle lies inside the polygon, its
// terms are the polygon's own size and all of one sign, nothing cancels, and the answer
// does not depend on where the polygon is (16.666666666666668 there; mass_test.cpp
// moves a pentagon 1e5 px away).
//
// One triangle, corners r, r + e1, r + e2 (e1 and e2 measured from the shared point r):
//   area        A = cross(e1, e2) / 2
//   centroid    r + (e1 + e2) / 3
//   the second moment of its area about r, the integral of |p - r|^2 over it,
//               J = A (e1.e1 + e1.e2 + e2.e2) / 6.
// The polygon's: the sums of A, of A x centroid (then divided by the total area), and
// of J. J is about r, and the body turns about the centroid c; the parallel axis rule
// moves it there: J_c = J_r - area |c - r|^2. Divided by the area, J_c is the moment of
// inertia per unit of mass for an even density, which the mass multiplies.

#include "polygon_mass.h"

namespace engine {

namespace {
// The fan's constants, from the integrals over a triangle (see above): its area is half
// the parallelogram's, its centroid the average of its three corners, and its second
// moment about the shared corner A/6 (e1.e1 + e1.e2 + e2.e2).
constexpr double kTriangleOfParallelogram = 2.0;
constexpr double kCornersOfTriangle = 3.0;
constexpr double kSecondMomentDivisor = 6.0;
}  // namespace

PolygonMass polygonMass(std::span<const Vec2> ccw_corners) {
    Vec2 inside;
    for (Vec2 corner : ccw_corners) inside = inside + corner;
    inside = inside * (1.0 / static_cast<double>(ccw_corners.size()));

    double area = 0.0;
    Vec2 first_moment;  // the sum of each triangle's area x its centroid, from `inside`
    double second_moment = 0.0;
    for (std::size_t i = 0; i < ccw_corners.size(); ++i) {
        const Vec2 e1 = ccw_corners[i] - inside;
        const Vec2 e2 = ccw_corners[(i + 1) % ccw_corners.size()] - inside;
        const double triangle = e1.cross(e2) / kTriangleOfParallelogram;
        area += triangle;
        first_moment = first_moment + (e1 + e2) * (triangle / kCornersOfTriangle);
        second_moment += triangle * (e1.dot(e1) + e1.dot(e2) + e2.dot(e2)) / kSecondMomentDivisor;
    }
    const Vec2 offset = first_moment * (1.0 / area);  // centroid - inside
    const double about_centroid = second_moment - area * offset.dot(offset);
    return {area, inside + offset, about_centroid / area};
}

}  // namespace engine
