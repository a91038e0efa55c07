// The book's SAT and 5.4's clipping, with the rectangle's "4" replaced by the polygon's
// count of sides. What changes with more sides, and what does not:
//   - the support point and the axis of least penetration are the book's, face by face;
//     there are simply more faces (at most 8 + 8 to try, each against up to 8 corners);
//   - the incident face is still the one that looks most against the reference normal,
//     chosen among n faces; on a rectangle it is one of two candidates, the opposite face
//     or a side, on a polygon it is any face;
//   - the clipping is unchanged: a segment cut by two lines.

#include "polygon_sat.h"

namespace engine {

namespace {

struct DeepestCorner {
    std::size_t corner = 0;
    double depth = 0.0;  // how far behind the face; > 0 when there is one
};

// The book's support point: the corner of `corners_of` deepest behind face `face` of
// `faces_of`. A depth of 0 or less means none is behind: the face separates them.
DeepestCorner deepestBehind(const ConvexPolygon& faces_of, std::size_t face, const ConvexPolygon& corners_of) {
    const Vec2 normal = faces_of.normals[face];
    const Vec2 on_face = faces_of.vertices[face];
    DeepestCorner deepest;
    for (std::size_t i = 0; i < corners_of.count; ++i) {
        const double depth = (on_face - corners_of.vertices[i]).dot(normal);
        if (depth > deepest.depth) deepest = {i, depth};
    }
    return deepest;
}

struct LeastPenetration {
    std::size_t face = 0;
    DeepestCorner support;
};

// The book's findAxisLeastPenetration over every face of `faces_of`, or nothing when
// one of them separates.
std::optional<LeastPenetration> leastPenetrationInto(const ConvexPolygon& faces_of, const ConvexPolygon& corners_of) {
    std::optional<LeastPenetration> least;
    for (std::size_t face = 0; face < faces_of.count; ++face) {
        const DeepestCorner support = deepestBehind(faces_of, face, corners_of);
        if (support.depth <= 0.0) return std::nullopt;
        if (!least || support.depth < least->support.depth) least = LeastPenetration{face, support};
    }
    return least;
}

// The face of `polygon` whose normal looks most along `direction`.
std::size_t mostAlong(const ConvexPolygon& polygon, Vec2 direction) {
    std::size_t best = 0;
    for (std::size_t face = 1; face < polygon.count; ++face) {
        if (polygon.normals[face].dot(direction) > polygon.normals[best].dot(direction)) best = face;
    }
    return best;
}

struct ClipEnd {
    Vec2 point;
    std::uint32_t feature;
};

// Keeps the part of the segment where dot(p, direction) <= limit; an end beyond the line
// moves along the segment onto it and takes the line's feature. False when the whole
// segment is beyond (round-off only: overlapping polygons' incident face reaches over
// the reference face).
bool keepBelow(std::array<ClipEnd, 2>& segment, Vec2 direction, double limit, std::uint32_t line) {
    const double beyond0 = segment[0].point.dot(direction) - limit;
    const double beyond1 = segment[1].point.dot(direction) - limit;
    if (beyond0 > 0.0 && beyond1 > 0.0) return false;
    if (beyond0 <= 0.0 && beyond1 <= 0.0) return true;
    const Vec2 crossing = segment[0].point + (segment[1].point - segment[0].point) * (beyond0 / (beyond0 - beyond1));
    segment[beyond0 > 0.0 ? 0 : 1] = ClipEnd{crossing, line};
    return true;
}

// Where the features sit in a key (polygon_sat.h).
constexpr int kIncidentFaceShift = 4;
constexpr int kReferenceFaceShift = 8;
constexpr std::uint32_t kReferenceFaceIsB = 1u << 12;
constexpr std::uint32_t kLoneContactKey = 0xFFFF;  // 5.4's key for the book's one point

}  // namespace

std::optional<SatCollision> satCollision(const ConvexPolygon& a, const ConvexPolygon& b) {
    const auto into_a = leastPenetrationInto(a, b);
    if (!into_a) return std::nullopt;
    const auto into_b = leastPenetrationInto(b, a);
    if (!into_b) return std::nullopt;
    if (into_a->support.depth < into_b->support.depth) {
        // A's face: its normal points from A towards B; the segment starts at B's corner.
        return SatCollision{into_a->support.depth, a.normals[into_a->face], b.vertices[into_a->support.corner], false,
                            into_a->face};
    }
    // B's face (ties too, as the book's): its normal turned round points from A to B; the
    // segment runs from B's face in to A's corner.
    const double depth = into_b->support.depth;
    const Vec2 normal = -b.normals[into_b->face];
    return SatCollision{depth, normal, a.vertices[into_b->support.corner] - normal * depth, true, into_b->face};
}

PolygonManifold polygonManifold(const ConvexPolygon& a, const ConvexPolygon& b, const SatCollision& collision) {
    const ConvexPolygon& reference = collision.reference_is_b ? b : a;
    const ConvexPolygon& incident = collision.reference_is_b ? a : b;
    const std::size_t reference_face = collision.face;
    const Vec2 reference_normal = reference.normals[reference_face];

    const std::size_t incident_face = mostAlong(incident, -reference_normal);
    const std::size_t incident_end = (incident_face + 1) % incident.count;
    std::array<ClipEnd, 2> segment{ClipEnd{incident.vertices[incident_face], static_cast<std::uint32_t>(incident_face)},
                                   ClipEnd{incident.vertices[incident_end], static_cast<std::uint32_t>(incident_end)}};

    const Vec2 first = reference.vertices[reference_face];
    const Vec2 second = reference.corner(reference_face + 1);
    const Vec2 along = (second - first).normalize();
    PolygonManifold manifold{collision.normal, {}, 0};
    const bool kept = keepBelow(segment, -along, -first.dot(along), kClippedAtStart) &&
                      keepBelow(segment, along, second.dot(along), kClippedAtEnd);
    const std::uint32_t faces = (collision.reference_is_b ? kReferenceFaceIsB : 0u) |
                                static_cast<std::uint32_t>(reference_face) << kReferenceFaceShift |
                                static_cast<std::uint32_t>(incident_face) << kIncidentFaceShift;
    for (const ClipEnd& end : segment) {
        if (!kept) break;
        const double depth = (first - end.point).dot(reference_normal);
        if (depth < 0.0) continue;
        manifold.points[manifold.count++] = {end.point + reference_normal * (depth / 2), depth, faces | end.feature};
    }
    if (manifold.count == 0) {
        manifold.points[0] = {collision.start + collision.normal * (collision.depth / 2), collision.depth,
                              kLoneContactKey};
        manifold.count = 1;
    }
    return manifold;
}

}  // namespace engine
