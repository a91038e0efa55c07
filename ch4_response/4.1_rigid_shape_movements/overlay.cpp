#include "overlay.h"

#include <numbers>
#include <string>
#include <vector>

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

}  // namespace

void drawOverlay(browser::Window& window, const Core& core) {
    std::vector<browser::LegendEntry>& legend = window.document.legend;
    legend.clear();
    window.document.legend_entries = window.every_layer_possible ? kLegendEntries : kOwnLegendEntries;
    if (!window.overlay) return;
    Sheet sheet{window.document.canvas, {}, legend};
    // 4.1's own layer is the motion; every layer adds chapter 3's bounding circles and
    // collision info.
    const bool all = window.overlay_all;
    if (all) {
        drawBounds(sheet, core);
        drawCollisionInfo(sheet, core);
    }
    drawMotion(sheet, core);
}

}  // namespace engine
