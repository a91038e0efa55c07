#include "contact_manifold.h"

#include <algorithm>
#include <array>
#include <cstddef>
#include <limits>

#include "polygon.h"
#include "polygon_sat.h"
#include "rectangle.h"

namespace engine {

namespace {

// The incident face on its way through the clipping: its two ends, each where it is
// now, its corner or, once a side line has cut the face, the point of the cut.
using Segment = std::array<Vec2, 2>;
// The key of the one point of a pair with a circle, and of the fallback point below.
constexpr std::uint32_t kSinglePoint = 0xFFFF;
// Where the faces sit in a key: bits 0-3 the point's end of the incident face (0 or
// 1), 4-7 the incident face, 8-11 the reference face, bit 12 set when the reference
// face is b's.
constexpr int kIncidentShift = 4;
constexpr int kReferenceShift = 8;
constexpr std::uint32_t kReferenceIsB = 1u << 12;
constexpr std::uint32_t kFaceMask = 0xF;

// The face of `box` whose outward normal lies nearest `direction` (largest dot).
std::size_t faceFacing(const Rectangle& box, Vec2 direction) {
    std::size_t best = 0;
    for (std::size_t face = 1; face < box.faceNormals().size(); ++face) {
        if (box.faceNormals()[face].dot(direction) > box.faceNormals()[best].dot(direction)) best = face;
    }
    return best;
}

// Keeps the part of the segment (two points) where dot(p, direction) <= limit: an end
// beyond the line is moved along the segment onto it, and stays the same end. The
// segment is never wholly beyond the line when the rectangles overlap (the incident
// face reaches over the reference face); if rounding says it is, nothing is kept.
std::size_t clip(Segment& segment, Vec2 direction, double limit) {
    const double beyond0 = segment[0].dot(direction) - limit;
    const double beyond1 = segment[1].dot(direction) - limit;
    if (beyond0 > 0 && beyond1 > 0) return 0;
    if (beyond0 <= 0 && beyond1 <= 0) return 2;
    // The line crosses the segment where the distances beyond it, one each side of 0,
    // interpolate to 0.
    const Vec2 crossing = segment[0] + (segment[1] - segment[0]) * (beyond0 / (beyond0 - beyond1));
    segment[beyond0 > 0 ? 0 : 1] = crossing;
    return 2;
}

// How far the corners of `corners_of` reach behind face `face` of `faces_of`: the
// overlap of the two measured along that face's normal (its deepest corner).
double depthBehind(const Rectangle& faces_of, std::size_t face, const Rectangle& corners_of) {
    double deepest = -std::numeric_limits<double>::infinity();
    for (Vec2 corner : corners_of.vertices()) {
        deepest = std::max(deepest, (faces_of.vertices()[face] - corner).dot(faces_of.faceNormals()[face]));
    }
    return deepest;
}

ContactPoint middleOfSegment(const CollisionInfo& info, std::uint32_t key) {
    return {info.start() + info.normal() * (info.depth() / 2), info.depth(), key};
}

// The two rectangles' points (see contact_manifold.h), and the normal of the face that
// made them, from a towards b.
struct Clipped {
    Vec2 normal;
    UpToTwo<ContactPoint> points;
};
Clipped clippedPoints(const Rectangle& a, const Rectangle& b, Vec2 normal, double tolerance) {
    // The separating axis test's normal is one of the faces' normals: a's face looking
    // along it, or b's looking against it. Those two faces are the candidates.
    const std::size_t face_a = faceFacing(a, normal);
    const std::size_t face_b = faceFacing(b, -normal);
    // The test takes whichever face the other shape reaches less deep behind. But where
    // two boxes lie face to face, the two depths are all but equal, and which is the
    // smaller turns on the last digits and on every small rocking of the pair. The
    // reference would swap from step to step, and with it every point's key (the key
    // names the reference): the solver would lose both points' warm start and rebuild
    // the pair's load from nothing, each time. In a pile that happens somewhere every
    // step, and the pile never comes to rest (bench/README.md, "Creep at rest"). So
    // a's face stays the reference unless b's is shallower by more than `tolerance`.
    // Either face is a true answer of the separating axis test, the one kept at most
    // that much deeper than the other.
    const bool b_is_reference = depthBehind(b, face_b, a) < depthBehind(a, face_a, b) - tolerance;
    const Rectangle& reference = b_is_reference ? b : a;
    const Rectangle& incident = b_is_reference ? a : b;
    const std::size_t reference_face = b_is_reference ? face_b : face_a;
    const Vec2 reference_normal = reference.faceNormals()[reference_face];

    // The incident face looks most against the reference normal. Face i runs from
    // corner i to corner i + 1 (rectangle.h).
    const std::size_t incident_face = faceFacing(incident, -reference_normal);
    const std::size_t incident_end = (incident_face + 1) % 4;
    Segment segment{incident.vertices()[incident_face], incident.vertices()[incident_end]};

    // The reference face runs from `first` to `second` along `along`: its side lines
    // are dot(p, along) = dot(first, along) and = dot(second, along).
    const Vec2 first = reference.vertices()[reference_face];
    const Vec2 second = reference.vertices()[(reference_face + 1) % 4];
    const Vec2 along = (second - first).normalize();
    Clipped clipped{b_is_reference ? -reference_normal : reference_normal, {}};
    if (clip(segment, -along, -first.dot(along)) == 0) return clipped;
    if (clip(segment, along, second.dot(along)) == 0) return clipped;

    // The key: who is the reference, which two faces, which end of the incident face.
    // The end, not what made it (the incident corner, or the cut of a side line): where
    // two faces of the same length lie one on the other, the corners sit right on the
    // side lines, and a shift of a hair either way turns a corner into a cut. The point
    // moves by that hair, no more, so it is the same point, and must keep its key (and
    // its impulses) as it goes.
    const std::uint32_t faces = (b_is_reference ? kReferenceIsB : 0u) |
                                static_cast<std::uint32_t>(reference_face) << kReferenceShift |
                                static_cast<std::uint32_t>(incident_face) << kIncidentShift;
    for (std::uint32_t end = 0; end < segment.size(); ++end) {
        // Behind the reference face by `depth`; the point itself goes halfway back to
        // the face, between the two outlines.
        const double depth = (first - segment[end]).dot(reference_normal);
        if (depth < 0) continue;  // in front of the face: not touching there
        clipped.points.push_back({segment[end] + reference_normal * (depth / 2), depth, faces | end});
    }
    return clipped;
}

// A pair with a polygon in it and no circle (5.8): the same clipping for n sides
// (polygon_sat.h), its keys in the same layout.
UpToTwo<ContactPoint> polygonPoints(const RigidShape& a, const RigidShape& b, Vec2 normal) {
    const ConvexPolygon first = cornersOf(a);
    const ConvexPolygon second = cornersOf(b);
    const std::optional<SatCollision> collision = satCollision(first, second);
    UpToTwo<ContactPoint> points;
    // The narrow phase's normal is this test's, unless it was turned to point from a to
    // b (narrow_phase.cpp): then the book's one point stands in.
    if (!collision || collision->normal.dot(normal) <= 0) return points;
    const PolygonManifold manifold = polygonManifold(first, second, *collision);
    for (std::size_t i = 0; i < manifold.count; ++i) {
        points.push_back({manifold.points[i].position, manifold.points[i].depth, manifold.points[i].key});
    }
    return points;
}

}  // namespace

ContactFeatures featuresOf(std::uint32_t key) {
    if (key == kSinglePoint) return {.single_point = true};
    return {.reference_is_b = (key & kReferenceIsB) != 0,
            .reference_face = (key >> kReferenceShift) & kFaceMask,
            .incident_face = (key >> kIncidentShift) & kFaceMask};
}

ContactManifold contactManifold(const RigidShape& a, const RigidShape& b, const CollisionInfo& info, double tolerance) {
    ContactManifold manifold{info.normal(), {}};
    if (a.type() == ShapeType::Rectangle && b.type() == ShapeType::Rectangle) {
        const Clipped clipped =
            clippedPoints(static_cast<const Rectangle&>(a), static_cast<const Rectangle&>(b), info.normal(), tolerance);
        if (!clipped.points.empty()) manifold = {clipped.normal, clipped.points};
    } else if (a.type() != ShapeType::Circle && b.type() != ShapeType::Circle) {
        manifold.points = polygonPoints(a, b, info.normal());
    }
    // A pair with a circle; or rectangles where rounding left no point behind the face
    // (they overlap, so the book's one point stands in).
    if (manifold.points.empty()) manifold.points.push_back(middleOfSegment(info, kSinglePoint));
    return manifold;
}

}  // namespace engine
