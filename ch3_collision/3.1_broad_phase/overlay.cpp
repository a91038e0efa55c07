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
constexpr Color kBoundColor{150, 150, 150, 255};  // gray: the bounding circles
constexpr Color kPairColor{160, 0, 200, 255};     // purple: a pair the broad phase passed

// The broad phase: the bounding circle of every tested rectangle (a circle's is its own
// outline), then the pairs the last pass kept, centre to centre, with "distance <= sum
// of radii" beside the middle.
void drawBroadPhase(Sheet& sheet, const Core& core) {
    for (std::size_t i = Physics::kFirstTestedObject; i < core.objectCount(); ++i) {
        const RigidShape& shape = core.object(i);
        if (shape.type() == ShapeType::Rectangle)
            draw::ring(sheet.canvas, shape.center(), shape.boundRadius(), kBoundColor);
    }
    for (const Collision& pair : core.physics().collisions()) {
        const RigidShape& a = core.object(pair.first);
        const RigidShape& b = core.object(pair.second);
        draw::line(sheet.canvas, a.center(), b.center(), kPairColor);
        const std::string test = draw::fixed(a.center().distance(b.center()), 1) +
                                 " <= " + draw::fixed(a.boundRadius() + b.boundRadius(), 1) + " px";
        sheet.labels.place(sheet.canvas, (a.center() + b.center()) * 0.5 + Vec2{4, 2}, kPairColor, test);
    }
    const std::size_t tested =
        core.objectCount() > Physics::kFirstTestedObject ? core.objectCount() - Physics::kFirstTestedObject : 0;
    const std::size_t pairs = tested < 2 ? 0 : tested * (tested - 1) / 2;
    sheet.legend.push_back({kBoundColor, "bounding circle of a rectangle"});
    sheet.legend.push_back({kPairColor, "passed: distance <= r1 + r2"});
    sheet.legend.push_back({kPairColor, std::to_string(core.physics().collisions().size()) + " of " +
                                            std::to_string(pairs) + " pairs passed"});
}

}  // namespace

void drawOverlay(browser::Window& window, const Core& core) {
    std::vector<browser::LegendEntry>& legend = window.document.legend;
    legend.clear();
    window.document.legend_entries = window.every_layer_possible ? kLegendEntries : kOwnLegendEntries;
    if (!window.overlay) return;
    Sheet sheet{window.document.canvas, {}, legend};
    drawBroadPhase(sheet, core);
}

}  // namespace engine
