#include "contact_overlay.h"

#include <string>

#include "overlay_draw.h"
#include "polygon.h"
#include "rectangle.h"

namespace engine {
namespace {

using browser::Color;
namespace draw = browser::overlay;

// Colours none of the book's drawing uses, nor the overlays of the stages before.
constexpr Color kReferenceColor{70, 70, 70, 255};    // dark gray: the reference face
constexpr Color kSideLineColor{175, 150, 210, 255};  // lavender: its side lines
constexpr Color kIncidentColor{0, 170, 220, 255};    // sky blue: the incident face
constexpr Color kPointColor{0, 0, 0, 255};           // black: a contact point
constexpr Color kNormalColor{150, 80, 0, 255};       // brown: the normal push
constexpr Color kFrictionColor{110, 130, 0, 255};    // olive: friction

// How far a side line reaches each way from the reference face's end.
constexpr double kSideLineReach = 12.0;  // px

struct Face {
    Vec2 from, to;
};
Face faceOf(const ConvexPolygon& outline, std::size_t face) { return {outline.corner(face), outline.corner(face + 1)}; }

// The reference face, its side lines, and the incident face, for a contact of two
// shapes with corners whose points were clipped (their first point's key names the faces).
void drawFaces(browser::Canvas& canvas, const RigidShape& a, const RigidShape& b, const ContactFeatures& features) {
    const ConvexPolygon reference = cornersOf(features.reference_is_b ? b : a);
    const ConvexPolygon incident = cornersOf(features.reference_is_b ? a : b);
    if (features.reference_face >= reference.count || features.incident_face >= incident.count) return;
    const Face face = faceOf(reference, features.reference_face);
    const Vec2 normal = reference.normals[features.reference_face];
    for (const Vec2 end : {face.from, face.to}) {
        draw::line(canvas, end + normal * kSideLineReach, end - normal * kSideLineReach, kSideLineColor);
    }
    draw::line(canvas, face.from, face.to, kReferenceColor);
    const Face cut = faceOf(incident, features.incident_face);
    draw::line(canvas, cut.from, cut.to, kIncidentColor);
}

// The shape the solver met at `index` as `id`, if it is still there: a shape that left
// after the step (out of bounds, the R key) has moved those after it up the list.
const RigidShape* stillAt(const Core& core, std::size_t index, BodyId id) {
    if (index >= core.objectCount() || core.object(index).id() != id) return nullptr;
    return &core.object(index);
}

}  // namespace

void drawContacts(browser::Canvas& canvas, const Core& core, std::vector<browser::LegendEntry>& legend) {
    if (core.settings().solver != SolverKind::sequential_impulse) return;
    const double dt = core.settings().dt / core.settings().substeps;
    for (const ContactSolver::Contact& contact : core.physics().contactSolver().contacts()) {
        const ContactFeatures features = featuresOf(contact.points[0].contact.key);
        const RigidShape* a = stillAt(core, contact.a, contact.id_a);
        const RigidShape* b = stillAt(core, contact.b, contact.id_b);
        if (!features.single_point && a && b) drawFaces(canvas, *a, *b, features);
        for (const ContactSolver::Point& point : contact.points) {
            const Vec2 at = point.contact.position;
            draw::arrow(canvas, at, at + contact.normal * (point.normal_impulse / dt * kPxPerForce), kNormalColor);
            draw::arrow(canvas, at, at + contact.tangent * (point.tangent_impulse / dt * kPxPerForce), kFrictionColor);
            draw::marker(canvas, at, kPointColor);
        }
    }
    const ContactSolver& solver = core.physics().contactSolver();
    legend.push_back({kReferenceColor, "reference face; normal = the axis"});
    legend.push_back({kSideLineColor, "side lines of the reference face"});
    legend.push_back({kIncidentColor, "incident face, clipped by them"});
    legend.push_back({kPointColor, "contact point"});
    legend.push_back({kNormalColor, "normal push on 2nd shape, 2 units/px"});
    legend.push_back({kFrictionColor, "friction on the 2nd shape"});
    legend.push_back({kPointColor, std::to_string(solver.pointCount()) + " points, " +
                                       std::to_string(solver.persistedPointCount()) + " warm started"});
}

}  // namespace engine
