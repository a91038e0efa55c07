#include "islands_overlay.h"

#include <algorithm>
#include <array>
#include <cstdio>
#include <map>
#include <numbers>
#include <string>

#include "text.h"

namespace engine {
namespace {

using browser::Color;
namespace draw = browser::overlay;

// One colour an island, in turn: colours none of the book's drawing uses (blue for
// shapes, red for the selected one, gray for sleepers), strong enough to read on white.
constexpr std::array<Color, 8> kIslandColors{{{200, 0, 200, 255},
                                              {0, 160, 170, 255},
                                              {150, 90, 20, 255},
                                              {240, 100, 170, 255},
                                              {100, 170, 0, 255},
                                              {110, 60, 200, 255},
                                              {210, 160, 0, 255},
                                              {60, 100, 120, 255}}};
constexpr Color kAsleepColor = browser::colors::kGray;
// How far above its island's highest point a label's top is: a line of text and a gap.
constexpr double kLabelAbove = 16.0;  // px

// What the overlay gathers of one island from its shapes.
struct IslandView {
    std::size_t first = 0;  // its shape of the smallest index: islands are coloured in that order
    std::size_t shapes = 0;
    bool asleep = false;
    double least_rest_s = 0.0;
    Vec2 top;  // the highest point of its bounding circles, where its label goes
};

void strokeArc(browser::Canvas& canvas, Vec2 center, double radius, double from, double to, Color color) {
    canvas.save();
    canvas.setStrokeStyle(color);
    canvas.beginPath();
    canvas.arc(center.x, center.y, radius, from, to);
    canvas.stroke();
    canvas.restore();
}

std::string label(const IslandView& island, double time_to_sleep) {
    char text[64];
    if (island.asleep) {
        std::snprintf(text, sizeof text, "%zu shapes, asleep", island.shapes);
    } else {
        std::snprintf(text, sizeof text, "%zu shapes, rested %.2f of %.2f s", island.shapes,
                      std::min(island.least_rest_s, time_to_sleep), time_to_sleep);
    }
    return text;
}

}  // namespace

void drawIslands(browser::Canvas& canvas, draw::LabelLayout& labels, const Core& core,
                 std::vector<browser::LegendEntry>& legend) {
    const WorldSettings& world = core.settings();
    if (!world.sleep) return;
    // The islands by their names (a shape keeps the name of the island it was last
    // found in; one not yet stepped has none).
    std::map<std::uint64_t, IslandView> islands;
    for (std::size_t i = 0; i < core.objectCount(); ++i) {
        const RigidShape& shape = core.object(i);
        if (shape.isStatic() || shape.sleep().island == 0) continue;
        const Vec2 top = shape.center() - Vec2{0.0, shape.boundRadius()};
        const auto [at, is_new] = islands.try_emplace(
            shape.sleep().island, IslandView{i, 0, shape.sleep().asleep, shape.sleep().rested_s, top});
        IslandView& island = at->second;
        ++island.shapes;
        island.least_rest_s = std::min(island.least_rest_s, shape.sleep().rested_s);
        if (top.y < island.top.y) island.top = top;
    }
    // Colours in the order of each island's first shape, so that an island keeps its
    // colour from frame to frame while its shapes stay together.
    std::vector<const IslandView*> in_order;
    for (const auto& [name, island] : islands) in_order.push_back(&island);
    std::sort(in_order.begin(), in_order.end(), [](const auto* a, const auto* b) { return a->first < b->first; });
    std::map<std::uint64_t, Color> color_of;
    std::size_t asleep = 0;
    for (std::size_t k = 0; k < in_order.size(); ++k) {
        for (const auto& [name, island] : islands) {
            if (&island == in_order[k]) color_of[name] = kIslandColors[k % kIslandColors.size()];
        }
        asleep += in_order[k]->asleep ? 1 : 0;
    }

    for (std::size_t i = 0; i < core.objectCount(); ++i) {
        const RigidShape& shape = core.object(i);
        const auto found = color_of.find(shape.sleep().island);
        if (shape.isStatic() || found == color_of.end()) continue;
        canvas.save();
        canvas.setStrokeStyle(found->second);
        shape.draw(canvas);
        canvas.restore();
        // The rest timer, from the top (-pi/2) clockwise; full once it reaches the time to
        // sleep (at once when that is 0 and the shape rested).
        const double rested = shape.sleep().rested_s;
        const double full = world.time_to_sleep > 0.0 ? std::min(1.0, rested / world.time_to_sleep) : (rested > 0.0);
        const double radius = shape.boundRadius() + kRestRingGap;
        const double start = -std::numbers::pi / 2;
        if (shape.sleep().asleep) {
            strokeArc(canvas, shape.center(), radius, 0.0, 2 * std::numbers::pi, kAsleepColor);
        } else if (full > 0.0) {
            strokeArc(canvas, shape.center(), radius, start, start + 2 * std::numbers::pi * full, found->second);
        }
    }
    // Each label over its island, kept on the canvas.
    for (const auto& [name, island] : islands) {
        if (island.shapes < 2) continue;
        const std::string text = label(island, world.time_to_sleep);
        const double width = browser::text_width(text);
        const Vec2 at{std::clamp(island.top.x - width / 2, 0.0, std::max(0.0, core.width() - width)),
                      std::max(0.0, island.top.y - kLabelAbove)};
        labels.place(canvas, at, island.asleep ? kAsleepColor : color_of[name], text);
    }

    char ring[40];
    std::snprintf(ring, sizeof ring, "rest timer: a ring, full in %.2f s", world.time_to_sleep);
    legend.push_back({kIslandColors[0], "island: its shapes in one colour"});
    legend.push_back({kIslandColors[0], ring});
    legend.push_back({kAsleepColor, "asleep (gray ring): " + std::to_string(asleep) + " of " +
                                        std::to_string(islands.size()) + " islands"});
}

}  // namespace engine
