#include "overlay.h"

#include <numbers>
#include <string>
#include <vector>

#include "contact_overlay.h"
#include "events_overlay.h"
#include "gjk_overlay.h"
#include "grid_overlay.h"
#include "islands_overlay.h"
#include "joints_overlay.h"
#include "overlay_draw.h"

namespace engine {
namespace {

using browser::Color;
namespace draw = browser::overlay;

// What every part of the overlay draws on: the canvas, the labels placed so far (so that
// no label covers another) and the legend.
struct Sheet {
    browser::Canvas& canvas;
    draw::LabelLayout labels;
    std::vector<browser::LegendEntry>& legend;
};

// Colours none of the book's drawing uses (blue, red, green, orange), so the overlay
// never reads as the page's own.
constexpr Color kBoundColor{150, 150, 150, 255};  // gray: the bounding circles

constexpr Color kStartColor{0, 150, 150, 255};   // teal: where the overlap starts
constexpr Color kEndColor{160, 0, 200, 255};     // purple: where it ends
constexpr Color kNormalColor{200, 0, 120, 255};  // crimson: the normal

constexpr Color kVelocityColor{0, 140, 60, 255};  // dark green: velocity and spin

constexpr Color kCorrectionColor{230, 100, 0, 255};  // dark orange: positional correction

constexpr Color kNormalImpulseColor{0, 0, 140, 255};     // navy: the normal impulse
constexpr Color kTangentImpulseColor{120, 120, 0, 255};  // olive: the tangent impulse

constexpr Color kLeverColor{110, 110, 110, 255};  // gray: lever arms and spin changes

constexpr Color kSweepColor{120, 220, 0, 255};  // lime: the sweep of a fast shape

// The normal is a unit vector: drawn this long, whatever the depth.
constexpr double kNormalLength = 20.0;  // px

// 3.1's layer, under every later one: the bounding circle of every rectangle (a
// circle's is its own outline), which the broad phase compares before a pair gets the
// exact test.
void drawBounds(Sheet& sheet, const Core& core) {
    for (std::size_t i = 0; i < core.objectCount(); ++i) {
        const RigidShape& shape = core.object(i);
        if (shape.type() == ShapeType::Rectangle)
            draw::ring(sheet.canvas, shape.center(), shape.boundRadius(), kBoundColor);
    }
    sheet.legend.push_back({kBoundColor, "bounding circle of a rectangle"});
}

// The collision info of every pair the last pass found: start, end, the normal from the
// start, and the depth beside the end.
void drawCollisionInfo(Sheet& sheet, const Core& core) {
    for (const Collision& pair : core.physics().collisions()) {
        const CollisionInfo& info = pair.info;
        draw::arrow(sheet.canvas, info.start(), info.start() + info.normal() * kNormalLength, kNormalColor);
        draw::marker(sheet.canvas, info.start(), kStartColor);
        draw::marker(sheet.canvas, info.end(), kEndColor);
        sheet.labels.place(sheet.canvas, info.end() + draw::kLabelOffset, kEndColor,
                           "depth " + draw::fixed(info.depth(), 2) + " px");
    }
    sheet.legend.push_back({kStartColor, "start: where the overlap starts"});
    sheet.legend.push_back({kEndColor, "end = start + normal * depth"});
    sheet.legend.push_back({kNormalColor, "normal (first to second), 20 px"});
    sheet.legend.push_back({kEndColor, "colliding pairs: " + std::to_string(core.physics().collisions().size())});
}

// Motion is drawn as the way it goes in this much time: long enough to see at the
// speeds of the book's scenes (tens of px/s, a few rad/s), short enough to stay near
// the shape.
constexpr double kMotionShown = 0.5;  // s
// The curved arrow of a spin runs this far outside the shape's bounding circle.
constexpr double kSpinGap = 4.0;  // px

// Every moving shape's velocity and angular velocity, as far as they carry it in
// kMotionShown seconds. A static shape never moves and shows nothing.
void drawMotion(Sheet& sheet, const Core& core) {
    for (std::size_t i = 0; i < core.objectCount(); ++i) {
        const RigidShape& shape = core.object(i);
        if (shape.isStatic()) continue;
        draw::arrow(sheet.canvas, shape.center(), shape.center() + shape.velocity() * kMotionShown, kVelocityColor);
        draw::turn_arrow(sheet.canvas, shape.center(), shape.boundRadius() + kSpinGap, -std::numbers::pi / 2,
                         shape.angularVelocity() * kMotionShown, kVelocityColor);
    }
    sheet.legend.push_back({kVelocityColor, "velocity, spin: motion in 0.5 s"});
}

// A step's correction is often a fraction of a pixel: it is drawn this many times longer.
// Shapes created inside each other are pushed out by tens of pixels in a step: their
// arrows are cut to kLongestCorrection, so they do not cover the page.
constexpr double kCorrectionMagnified = 10.0;
constexpr double kLongestCorrection = 60.0;  // px

// The arrow of a move `moved` from `center`, magnified and cut.
void correctionArrow(browser::Canvas& canvas, Vec2 center, Vec2 moved) {
    Vec2 shown = moved * kCorrectionMagnified;
    if (shown.length() > kLongestCorrection) shown = shown.normalize() * kLongestCorrection;
    draw::arrow(canvas, center, center + shown, kCorrectionColor);
}

// How far the last step's relaxation passes moved each shape of each pair they
// corrected, magnified (and cut at kLongestCorrection).
void drawCorrection(Sheet& sheet, const Core& core) {
    for (const auto& [pair, response] : core.physics().responses()) {
        correctionArrow(sheet.canvas, core.object(pair.first).center(), response.moved_first);
        correctionArrow(sheet.canvas, core.object(pair.second).center(), response.moved_second);
    }
    sheet.legend.push_back({kCorrectionColor, "correction, last step, x10 (<= 60 px)"});
}

// Impulses (mass x px/s) are drawn this many px a unit: a shape of mass 20 resting on
// another under the book's gravity gets about 20 x 10 / 60 = 3.3 a step, 6.7 px.
// Collisions at speed give hundreds: those arrows are cut at kLongestImpulse.
constexpr double kPxPerImpulse = 2.0;
constexpr double kLongestImpulse = 60.0;  // px

void impulseArrow(browser::Canvas& canvas, Vec2 at, Vec2 impulse, Color color) {
    Vec2 shown = impulse * kPxPerImpulse;
    if (shown.length() > kLongestImpulse) shown = shown.normalize() * kLongestImpulse;
    draw::arrow(canvas, at, at + shown, color);
}

// The normal and tangent impulses of the last step at each resolved pair's contact,
// with "jN / jT" in numbers beside it.
void drawImpulses(Sheet& sheet, const Core& core) {
    for (const auto& [pair, response] : core.physics().responses()) {
        const double normal = response.normal_impulse.length(), tangent = response.tangent_impulse.length();
        if (normal == 0.0 && tangent == 0.0) continue;
        impulseArrow(sheet.canvas, response.contact, response.normal_impulse, kNormalImpulseColor);
        impulseArrow(sheet.canvas, response.contact, response.tangent_impulse, kTangentImpulseColor);
        sheet.labels.place(sheet.canvas, response.contact + Vec2{6, 4}, kNormalImpulseColor,
                           draw::fixed(normal, 2) + " / " + draw::fixed(tangent, 2));
    }
    sheet.legend.push_back({kNormalImpulseColor, "normal impulse jN, 2 px a unit"});
    sheet.legend.push_back({kTangentImpulseColor, "tangent impulse jT (label: jN / jT)"});
}

// The curved arrow of a spin change runs this far outside the shape's bounding circle,
// outside the spin's own.
constexpr double kSpinChangeGap = 10.0;  // px

// Each resolved pair's lever arms, centre to contact, and the change of spin its
// impulses gave each shape, as far as that change turns it in kMotionShown.
void drawLeverArms(Sheet& sheet, const Core& core) {
    for (const auto& [pair, response] : core.physics().responses()) {
        if (response.normal_impulse.length() == 0.0 && response.tangent_impulse.length() == 0.0) continue;
        const RigidShape& first = core.object(pair.first);
        const RigidShape& second = core.object(pair.second);
        draw::line(sheet.canvas, response.contact - response.arm_first, response.contact, kLeverColor);
        draw::line(sheet.canvas, response.contact - response.arm_second, response.contact, kLeverColor);
        draw::turn_arrow(sheet.canvas, first.center(), first.boundRadius() + kSpinChangeGap, -std::numbers::pi / 2,
                         response.spin_first * kMotionShown, kLeverColor);
        draw::turn_arrow(sheet.canvas, second.center(), second.boundRadius() + kSpinChangeGap, -std::numbers::pi / 2,
                         response.spin_second * kMotionShown, kLeverColor);
    }
    sheet.legend.push_back({kLeverColor, "lever arms; spin change (0.5 s)"});
}

// Continuous collision (continuous.h): each fast shape's path in the last step, from
// where its centre started to where its motion would have taken it, and a marker where
// the sweep stopped it (its centre at the time of impact).
void drawSweeps(Sheet& sheet, const Core& core) {
    for (const Sweep& sweep : core.continuous().sweeps()) {
        draw::line(sheet.canvas, sweep.from, sweep.to, kSweepColor);
        if (sweep.impact) draw::marker(sheet.canvas, sweep.from + (sweep.to - sweep.from) * *sweep.impact, kSweepColor);
    }
    // Always in the legend, the count with it: "0 swept" says the sweep ran and found no
    // shape fast enough, where a missing line would say nothing.
    sheet.legend.push_back({kSweepColor, "fast shape: path, where stopped"});
    sheet.legend.push_back({kSweepColor, "swept this step: " + std::to_string(core.continuous().sweeps().size()) +
                                             (core.settings().continuous ? "" : " (continuous off)")});
}

}  // namespace

void drawOverlay(browser::Window& window, const Core& core) {
    std::vector<browser::LegendEntry>& legend = window.document.legend;
    legend.clear();
    window.document.legend_entries = window.every_layer_possible ? kLegendEntries : kOwnLegendEntries;
    window.document.legend_text_width = kLegendTextWidth;
    if (!window.overlay) return;
    Sheet sheet{window.document.canvas, {}, legend};
    // 5.9's own layer is its joints (joints_overlay.h). Every layer adds the bounding
    // circles, the grid, 5.5's islands, chapter 3's and 4's layers, 5.4's contacts,
    // 5.6's sweeps, 5.7's events and 5.8's GJK.
    const bool all = window.overlay_all;
    if (all) {
        drawBounds(sheet, core);
        drawGrid(sheet.canvas, core, legend);
        drawIslands(sheet.canvas, sheet.labels, core, legend);
        drawCollisionInfo(sheet, core);
        drawMotion(sheet, core);
        drawCorrection(sheet, core);
        drawImpulses(sheet, core);
        drawLeverArms(sheet, core);
        drawContacts(sheet.canvas, core, legend);
        drawSweeps(sheet, core);
        drawEvents(sheet.canvas, sheet.labels, core, legend);
        drawGjk(sheet.canvas, sheet.labels, core, legend);
    }
    // Last, so that no layer covers the joints, GJK's panels included.
    drawJoints(sheet.canvas, sheet.labels, core, legend);
}

}  // namespace engine
