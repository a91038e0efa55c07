#include "overlay.h"

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
constexpr Color kStartColor{0, 150, 150, 255};   // teal: where the overlap starts
constexpr Color kEndColor{160, 0, 200, 255};     // purple: where it ends
constexpr Color kNormalColor{200, 0, 120, 255};  // crimson: the normal

// The normal is a unit vector: drawn this long, whatever the depth.
constexpr double kNormalLength = 20.0;  // px

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

}  // namespace

void drawOverlay(browser::Window& window, const Core& core) {
    std::vector<browser::LegendEntry>& legend = window.document.legend;
    legend.clear();
    if (!window.overlay) return;
    Sheet sheet{window.document.canvas, {}, legend};
    drawCollisionInfo(sheet, core);
}

}  // namespace engine
