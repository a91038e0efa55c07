#include "grid_overlay.h"

#include <cmath>
#include <string>

#include "overlay_draw.h"

namespace engine {
namespace {

using browser::Color;
namespace draw = browser::overlay;

// Colours none of the book's drawing uses, nor the overlays of the stages before.
constexpr Color kCellColor{215, 215, 215, 255};     // light gray: the grid's cells
constexpr Color kCoveredColor{120, 170, 220, 255};  // pale blue-gray: a cell a shape's box reaches
constexpr Color kCandidateColor{200, 120, 0, 255};  // amber: a candidate pair on the list

void strokeCell(browser::Canvas& canvas, double size, double column, double row, Color color) {
    canvas.save();
    canvas.setStrokeStyle(color);
    canvas.strokeRect(column * size, row * size, size, size);
    canvas.restore();
}

// The lines between the cells, over the whole canvas.
void drawCells(browser::Canvas& canvas, const Core& core, double size) {
    for (double x = size; x < core.width(); x += size) draw::line(canvas, {x, 0}, {x, core.height()}, kCellColor);
    for (double y = size; y < core.height(); y += size) draw::line(canvas, {0, y}, {core.width(), y}, kCellColor);
}

}  // namespace

void drawGrid(browser::Canvas& canvas, const Core& core, std::vector<browser::LegendEntry>& legend) {
    if (core.settings().broad_phase != BroadPhaseKind::grid) return;
    const SpatialGrid& grid = core.physics().broadPhase().grid();
    // The list belongs to the shapes of the last step; shapes removed or added since
    // leave it to the next step.
    const std::size_t count = core.objectCount();
    if (grid.listedCount() != count || count == 0) return;

    const double size = grid.cellSize();
    drawCells(canvas, core, size);
    for (std::size_t i = 0; i < count; ++i) {
        if (grid.isOversize(i)) continue;
        const Vec2 at = grid.listedAt(i);
        const double reach = grid.reach(i);
        for (double row = std::floor((at.y - reach) / size); row <= std::floor((at.y + reach) / size); ++row) {
            for (double column = std::floor((at.x - reach) / size); column <= std::floor((at.x + reach) / size);
                 ++column) {
                strokeCell(canvas, size, column, row, kCoveredColor);
            }
        }
    }
    for (std::size_t i = 0; i < count; ++i) {
        for (std::size_t k = grid.rowBegin(i); k < grid.rowEnd(i); ++k) {
            const std::size_t j = grid.partner(k);
            if (grid.isOversize(i) || grid.isOversize(j)) continue;
            // Passed over asleep (broad_phase.h): a sleeping shape and a resting one.
            const RigidShape& a = core.object(i);
            const RigidShape& b = core.object(j);
            if (a.isResting() && b.isResting() && (a.sleep().asleep || b.sleep().asleep)) continue;
            draw::line(canvas, core.object(i).center(), core.object(j).center(), kCandidateColor);
        }
    }

    // Every pass walks the list; the book's loop walks every pair.
    const std::size_t listed = grid.rowBegin(count);
    const std::size_t every_pair = count * (count - 1) / 2;
    legend.push_back({kCellColor, "grid cell, " + std::to_string(std::lround(size)) + " px"});
    legend.push_back({kCoveredColor, "cell a shape's widened box reaches"});
    legend.push_back({kCandidateColor, "candidate pair (oversize: not drawn)"});
    legend.push_back(
        {kCandidateColor, "pair tests a pass: " + std::to_string(listed) + " of " + std::to_string(every_pair)});
    legend.push_back({kCandidateColor, "saved a pass: " + std::to_string(every_pair - listed)});
}

}  // namespace engine
