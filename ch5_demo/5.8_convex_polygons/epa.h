#pragma once
// How deep two overlapping convex shapes go into each other, by the expanding polytope
// algorithm (EPA; van den Bergen, 2001). Not in the book.
//
// GJK stops when its simplex holds the origin: the shapes overlap, but by how much it
// does not say. The depth is the distance from the origin to the nearest side of the
// Minkowski difference A - B (gjk.h): moving B that far, along that side's outward
// normal, brings the origin onto the outline, and the shapes just touch. EPA finds that
// side from the inside: it starts from a polygon of support points around the origin
// (GJK's last simplex), takes its side nearest the origin, and asks A - B for its support
// point along that side's normal. If A - B reaches no farther, the side is a side of
// A - B itself, and the answer; otherwise the new point is put in, the polygon grows
// towards the outline there, and the search goes on.
//
// SAT answers the same question for polygons (polygon_sat.h), by trying every face
// normal; EPA is the method that works for any convex shape with a support point, and
// the two must agree (epa_test.cpp: 10,000 random overlapping pairs).

#include <optional>
#include <vector>

#include "gjk.h"

namespace engine {

// A cap on the support queries. A - B of two 8-gons has at most 16 corners and each
// query adds a new one, so 32 is never reached by a real run; the answer says whether
// it converged.
inline constexpr int kMaxEpaIterations = 32;
// When to stop: the support point along the nearest side's normal reaches no more than
// this beyond the side, relative to the shapes' size (so 1e-10 px for shapes of 100 px).
// The depth found is then within this of the true depth (the proof is in epa.cpp).
inline constexpr double kEpaRelativeTolerance = 1e-12;

struct EpaPenetration {
    double depth = 0.0;  // px, >= 0; 0 when the cores only touch
    Vec2 normal;         // unit, from A towards B: moving B by depth * normal parts them
    Vec2 point_a;        // A's deepest point into B along the normal (the witness on A)
    Vec2 point_b;        // B's deepest point into A: point_a - normal * depth
    int iterations = 0;  // support queries after GJK's
    bool converged = true;
};

// The penetration of the cores of two proxies (radii are not counted); nothing when
// they are apart (GJK's distance > 0). With `polygon`, the corners of the polygon EPA
// ended on (points w of A - B, in order round it) are put there for the overlay's
// diagram (gjk_overlay.h); its side nearest the origin is the answer's.
std::optional<EpaPenetration> epaPenetration(const ConvexProxy& a, const ConvexProxy& b,
                                             std::vector<Vec2>* polygon = nullptr);

}  // namespace engine
