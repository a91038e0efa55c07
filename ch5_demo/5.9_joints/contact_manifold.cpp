#include "contact_manifold.h"

#include <array>
#include <cstddef>

#include "polygon.h"
#include "polygon_sat.h"
#include "rectangle.h"

namespace engine {

namespace {

// A point of the incident face on its way through the clipping, with the key of the
// feature it stands for: one of the incident rectangle's corners (0 to 3) or, once a
// side line has cut the face, that side line (kCutAtStart, kCutAtEnd).
struct Tagged {
    Vec2 point;
    std::uint32_t feature;
};
constexpr std::uint32_t kCutAtStart = 4;  // the side line through the reference face's first corner
constexpr std::uint32_t kCutAtEnd = 5;    // ... through its second corner
// The key of the one point of a pair with a circle, and of the fallback point below.
constexpr std::uint32_t kSinglePoint = 0xFFFF;
// Where the faces sit in a key: bits 0-3 the point's feature, 4-7 the incident face,
// 8-11 the reference face, bit 12 set when the reference face is b's.
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

// Keeps the part of the segment (two points) where dot(p, direction) <= limit: a point
// beyond the line is moved along the segment onto it, and takes the line's key. The
// segment is never wholly beyond the line when the rectangles overlap (the incident
// face reaches over the reference face); if rounding says it is, nothing is kept.
std::size_t clip(std::array<Tagged, 2>& segment, Vec2 direction, double limit, std::uint32_t line) {
    const double beyond0 = segment[0].point.dot(direction) - limit;
    const double beyond1 = segment[1].point.dot(direction) - limit;
    if (beyond0 > 0 && beyond1 > 0) return 0;
    if (beyond0 <= 0 && beyond1 <= 0) return 2;
    // The line crosses the segment where the distances beyond it, one each side of 0,
    // interpolate to 0.
    const Vec2 crossing = segment[0].point + (segment[1].point - segment[0].point) * (beyond0 / (beyond0 - beyond1));
    segment[beyond0 > 0 ? 0 : 1] = Tagged{crossing, line};
    return 2;
}

ContactPoint middleOfSegment(const CollisionInfo& info, std::uint32_t key) {
    return {info.start() + info.normal() * (info.depth() / 2), info.depth(), key};
}

// The two rectangles' points (see contact_manifold.h).
UpToTwo<ContactPoint> clippedPoints(const Rectangle& a, const Rectangle& b, Vec2 normal) {
    // The separating axis test's normal is one of the faces' normals: a's face looking
    // along it, or b's looking against it. Whichever matches better is the reference.
    const std::size_t face_a = faceFacing(a, normal);
    const std::size_t face_b = faceFacing(b, -normal);
    const bool b_is_reference = b.faceNormals()[face_b].dot(-normal) > a.faceNormals()[face_a].dot(normal);
    const Rectangle& reference = b_is_reference ? b : a;
    const Rectangle& incident = b_is_reference ? a : b;
    const std::size_t reference_face = b_is_reference ? face_b : face_a;
    const Vec2 reference_normal = reference.faceNormals()[reference_face];

    // The incident face looks most against the reference normal. Face i runs from
    // corner i to corner i + 1 (rectangle.h).
    const std::size_t incident_face = faceFacing(incident, -reference_normal);
    const std::size_t incident_end = (incident_face + 1) % 4;
    std::array<Tagged, 2> segment{Tagged{incident.vertices()[incident_face], static_cast<std::uint32_t>(incident_face)},
                                  Tagged{incident.vertices()[incident_end], static_cast<std::uint32_t>(incident_end)}};

    // The reference face runs from `first` to `second` along `along`: its side lines
    // are dot(p, along) = dot(first, along) and = dot(second, along).
    const Vec2 first = reference.vertices()[reference_face];
    const Vec2 second = reference.vertices()[(reference_face + 1) % 4];
    const Vec2 along = (second - first).normalize();
    if (clip(segment, -along, -first.dot(along), kCutAtStart) == 0) return {};
    if (clip(segment, along, second.dot(along), kCutAtEnd) == 0) return {};

    // The key: who is the reference, which two faces, which feature of the point.
    const std::uint32_t faces = (b_is_reference ? kReferenceIsB : 0u) |
                                static_cast<std::uint32_t>(reference_face) << kReferenceShift |
                                static_cast<std::uint32_t>(incident_face) << kIncidentShift;
    UpToTwo<ContactPoint> points;
    for (const Tagged& end : segment) {
        // Behind the reference face by `depth`; the point itself goes halfway back to
        // the face, between the two outlines.
        const double depth = (first - end.point).dot(reference_normal);
        if (depth < 0) continue;  // in front of the face: not touching there
        points.push_back({end.point + reference_normal * (depth / 2), depth, faces | end.feature});
    }
    return points;
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

ContactManifold contactManifold(const RigidShape& a, const RigidShape& b, const CollisionInfo& info) {
    ContactManifold manifold{info.normal(), {}};
    if (a.type() == ShapeType::Rectangle && b.type() == ShapeType::Rectangle) {
        manifold.points =
            clippedPoints(static_cast<const Rectangle&>(a), static_cast<const Rectangle&>(b), info.normal());
    } else if (a.type() != ShapeType::Circle && b.type() != ShapeType::Circle) {
        manifold.points = polygonPoints(a, b, info.normal());
    }
    // A pair with a circle; or rectangles where rounding left no point behind the face
    // (they overlap, so the book's one point stands in).
    if (manifold.points.empty()) manifold.points.push_back(middleOfSegment(info, kSinglePoint));
    return manifold;
}

}  // namespace engine
