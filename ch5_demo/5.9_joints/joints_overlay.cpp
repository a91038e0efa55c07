#include "joints_overlay.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <tuple>

#include "kinematic_drawing.h"
#include "mouse_joint.h"

namespace engine {

namespace {

using browser::Color;
namespace draw = browser::overlay;

// Colours none of the page (blue, red, green, orange, gray) nor the other layers use.
constexpr Color kLinkColor{0, 110, 160, 255};    // cerulean: anchors, links, rods
constexpr Color kLimitColor{200, 60, 170, 255};  // orchid: limits
constexpr Color kErrorColor{150, 0, 0, 255};     // maroon: a joint's error

// A revolute's arc is drawn round its pin as far as most of the second body's link, and
// its needle as long, within these (a ragdoll's pins are close together; a long arm's
// arc may reach farther); the ends of a range get ticks this long across it.
constexpr double kLongestArc = 20.0;  // px
constexpr double kShortestArc = 8.0;  // px
constexpr double kArcShare = 0.8;     // of the link
constexpr double kTickReach = 4.0;    // px each way
// A slider with no limit: its axis drawn this far past its anchors either way.
constexpr double kFreeAxisMargin = 30.0;  // px
// A link shorter than this is no line to draw: the anchor is the centre (a wheel's pin).
constexpr double kShortestLine = 1.0;  // px
// A spring's zigzag: this many teeth, this far either side of the line.
constexpr int kSpringTeeth = 8;
constexpr double kSpringReach = 3.0;  // px
// A joint past kShownError gets a ring this large round its anchor; the largest few of
// them get their error written beside it too: a bridge under a heavy load has every pin
// a pixel or two apart, and fifty labels would bury it.
constexpr double kErrorRing = 5.0;  // px

// The shape of id `id`, or none. The list holds its shapes in the order the world took
// them in, and ids only go up (rigid_shape.h), so it is sorted by id.
const RigidShape* bodyWithId(const Core& core, BodyId id) {
    std::size_t low = 0, high = core.objectCount();
    while (low < high) {
        const std::size_t middle = (low + high) / 2;
        if (core.object(middle).id() < id) {
            low = middle + 1;
        } else {
            high = middle;
        }
    }
    if (low == core.objectCount() || core.object(low).id() != id) return nullptr;
    return &core.object(low);
}

Vec2 heading(double angle) { return {std::cos(angle), std::sin(angle)}; }
double angleOf(Vec2 v) { return std::atan2(v.y, v.x); }

// A short line across `along` at `at`: the end of a range.
void tick(browser::Canvas& canvas, Vec2 at, Vec2 along, Color color) {
    const Vec2 across = Vec2{-along.y, along.x} * kTickReach;
    draw::line(canvas, at - across, at + across, color);
}

void arc(browser::Canvas& canvas, Vec2 center, double radius, JointRange angles, Color color) {
    canvas.save();
    canvas.setStrokeStyle(color);
    canvas.beginPath();
    canvas.moveTo(center.x + radius * std::cos(angles.lower), center.y + radius * std::sin(angles.lower));
    canvas.arc(center.x, center.y, radius, angles.lower, angles.upper);
    canvas.stroke();
    canvas.restore();
}

// A spring from `from` to `to`: a zigzag, so that it does not read as a rod.
void zigzag(browser::Canvas& canvas, Vec2 from, Vec2 to, Color color) {
    const double length = from.distance(to);
    if (length < kShortestLine) return;
    const Vec2 along = (to - from) * (1.0 / length);
    const Vec2 across{-along.y, along.x};
    Vec2 last = from;
    for (int tooth = 0; tooth < kSpringTeeth; ++tooth) {
        const double side = tooth % 2 == 0 ? kSpringReach : -kSpringReach;
        const Vec2 next = from + along * (length * (tooth + 0.5) / kSpringTeeth) + across * side;
        draw::line(canvas, last, next, color);
        last = next;
    }
    draw::line(canvas, last, to, color);
}

JointMark markOf(const JointDefinition& joint, const RigidShape& a, const RigidShape& b) {
    JointMark mark{.type = joint.type, .center_a = a.center(), .center_b = b.center()};
    std::tie(mark.anchor_a, mark.anchor_b) = anchorsOf(joint, a, b);
    mark.separation = separationOf(joint, a, b);
    const double position = positionOf(joint, a, b);
    switch (joint.type) {
        case JointType::revolute:
            if (joint.limit) {
                // The needle turns with b; where the joint's angle would be 0 it points
                // `position` less far round, and the limits are angles from there.
                const Vec2 link = mark.center_b - mark.anchor_b;
                mark.needle = link.length() >= kShortestLine ? angleOf(link) : b.angle();
                const double zero = mark.needle - position;
                mark.arc = JointRange{zero + joint.limit->lower, zero + joint.limit->upper};
            }
            break;
        case JointType::prismatic:
            mark.axis = toWorld(joint.local_axis, a.angle());
            if (joint.limit) {
                mark.travel = *joint.limit;
                mark.travel_limited = true;
            } else {
                mark.travel = {std::min(position, 0.0) - kFreeAxisMargin, std::max(position, 0.0) + kFreeAxisMargin};
            }
            break;
        case JointType::distance:
            mark.spring = joint.hertz > 0.0;
            if (joint.length_range) mark.rope = joint.length_range;
            break;
        case JointType::weld: break;
    }
    return mark;
}

void drawMark(browser::Canvas& canvas, const JointMark& mark) {
    // The links: each centre to its anchor.
    if (mark.center_a.distance(mark.anchor_a) >= kShortestLine)
        draw::line(canvas, mark.center_a, mark.anchor_a, kLinkColor);
    if (mark.center_b.distance(mark.anchor_b) >= kShortestLine)
        draw::line(canvas, mark.center_b, mark.anchor_b, kLinkColor);
    draw::marker(canvas, mark.anchor_a, kLinkColor);
    if (mark.anchor_a.distance(mark.anchor_b) >= kShortestLine) draw::marker(canvas, mark.anchor_b, kLinkColor);
    const Vec2 gap = mark.anchor_b - mark.anchor_a;
    if (mark.type == JointType::distance) {
        if (mark.spring) {
            zigzag(canvas, mark.anchor_a, mark.anchor_b, kLinkColor);
        } else {
            draw::line(canvas, mark.anchor_a, mark.anchor_b, kLinkColor);
        }
    }
    // The limits.
    if (mark.arc) {
        const double radius = std::clamp(kArcShare * mark.center_b.distance(mark.anchor_b), kShortestArc, kLongestArc);
        arc(canvas, mark.anchor_b, radius, *mark.arc, kLimitColor);
        for (const double end : {mark.arc->lower, mark.arc->upper}) {
            const Vec2 out = heading(end);
            draw::line(canvas, mark.anchor_b + out * (radius - kTickReach), mark.anchor_b + out * (radius + kTickReach),
                       kLimitColor);
        }
        draw::line(canvas, mark.anchor_b, mark.anchor_b + heading(mark.needle) * radius, kLimitColor);
    }
    if (mark.type == JointType::prismatic) {
        const Vec2 from = mark.anchor_a + mark.axis * mark.travel.lower;
        const Vec2 to = mark.anchor_a + mark.axis * mark.travel.upper;
        draw::line(canvas, from, to, kLimitColor);
        if (mark.travel_limited) {
            tick(canvas, from, mark.axis, kLimitColor);
            tick(canvas, to, mark.axis, kLimitColor);
        }
    }
    if (mark.rope && gap.length() >= kShortestLine) {
        const Vec2 along = gap.normalize();
        if (mark.rope->lower > 0.0) tick(canvas, mark.anchor_a + along * mark.rope->lower, along, kLimitColor);
        tick(canvas, mark.anchor_a + along * mark.rope->upper, along, kLimitColor);
    }
    // The error: the gap a rigid joint should not have, and a ring that finds it.
    if (mark.separation > kShownError) {
        if (mark.type != JointType::distance) draw::line(canvas, mark.anchor_a, mark.anchor_b, kErrorColor);
        draw::ring(canvas, mark.anchor_b, kErrorRing, kErrorColor);
    }
}

}  // namespace

std::vector<JointMark> jointMarks(const Core& core) {
    std::vector<JointMark> marks;
    for (const Joint& joint : core.joints().all()) {
        const RigidShape* a = bodyWithId(core, joint.definition.body_a);
        const RigidShape* b = bodyWithId(core, joint.definition.body_b);
        if (a && b) marks.push_back(markOf(joint.definition, *a, *b));
    }
    return marks;
}

void drawJoints(browser::Canvas& canvas, draw::LabelLayout& labels, const Core& core,
                std::vector<browser::LegendEntry>& legend) {
    const std::vector<JointMark> marks = jointMarks(core);
    std::array<std::size_t, 4> kinds{};
    std::size_t past = 0;
    double largest = 0.0;
    std::vector<std::size_t> labelled;
    for (std::size_t k = 0; k < marks.size(); ++k) {
        const JointMark& mark = marks[k];
        drawMark(canvas, mark);
        ++kinds[static_cast<std::size_t>(mark.type)];
        if (mark.separation > kShownError) {
            ++past;
            labelled.push_back(k);
        }
        largest = std::max(largest, mark.separation);
    }
    // The largest errors written beside their joints, the largest first (the first of
    // equals), so that it is the one that gets its place when labels crowd.
    std::stable_sort(labelled.begin(), labelled.end(),
                     [&](std::size_t p, std::size_t q) { return marks[p].separation > marks[q].separation; });
    if (labelled.size() > kLabelledErrors) labelled.resize(kLabelledErrors);
    for (const std::size_t k : labelled) {
        labels.place(canvas, marks[k].anchor_b + Vec2{kErrorRing, kErrorRing}, kErrorColor,
                     draw::fixed(marks[k].separation, 2) + " px");
    }
    // The count of each kind on two lines: on one it is wider than a column of the legend.
    // First, so that the two stay in one column of the band, the own layer's 7 entries in
    // rows of 4 and every layer's 43 in rows of 22 (overlay.h).
    const auto count = [&](JointType type) { return std::to_string(kinds[static_cast<std::size_t>(type)]); };
    legend.push_back({kLinkColor, "joints " + std::to_string(marks.size()) + ": revolute " +
                                      count(JointType::revolute) + ", distance " + count(JointType::distance) + ","});
    legend.push_back({kLinkColor, "  weld " + count(JointType::weld) + ", prismatic " + count(JointType::prismatic)});
    legend.push_back({kLinkColor, "anchor x, link centre to anchor, rod"});
    legend.push_back({kLimitColor, "limit: angle arc, slider's range, rope"});
    legend.push_back({kErrorColor, "error > " + draw::fixed(kShownError, 0) + " px (ring): " + std::to_string(past) +
                                       ", largest " + draw::fixed(largest, 2) + " px"});
    // What the page itself draws beyond the book's blue, red, gray and green, named here
    // where a reader of the joints looks for colours: the kinematic bodies and the mouse.
    legend.push_back(
        {kKinematicColor, "kinematic body; arrows: its motion in " + draw::fixed(kKinematicMotionShown, 0) + " s"});
    legend.push_back({MouseJoint::kLineColor, "mouse joint: grabbed point to pointer"});
}

}  // namespace engine
