#include "gjk_overlay.h"

#include <algorithm>
#include <string>

#include "circle.h"
#include "polygon.h"
#include "rectangle.h"

namespace engine {

namespace {

using browser::Color;
namespace draw = browser::overlay;

// Colours none of the page (blue, red, green, orange, gray) nor the layers under this
// one use, so the diagram reads as GJK's alone when every layer is on.
constexpr Color kDifferenceColor{90, 50, 170, 255};  // indigo: A - B
constexpr Color kOriginColor{0, 0, 0, 255};          // black: the origin, the one fixed point
constexpr Color kSimplexColor{215, 160, 0, 255};     // gold: GJK's simplex
constexpr Color kGapColor{190, 0, 60, 255};          // raspberry: the answer: distance or EPA

// Inside each panel: room for its label across the top, a margin on the other sides.
constexpr double kPanelLabelRoom = 18.0;  // px
constexpr double kPanelPadding = 8.0;     // px
constexpr Color kPanelBackground = browser::colors::kWhite;
constexpr Color kPanelFrame{150, 150, 150, 255};
// The origin's cross is drawn this far each way: larger than a marker, so that it reads
// as the diagram's axes and not as a point GJK found.
constexpr double kOriginReach = 5.0;  // px
// A search direction is drawn this long, whatever its length in the loop: only where it
// points matters. EPA's normal too, a unit vector.
constexpr double kDirectionShown = 22.0;  // px
// The ring round the support point a pass found.
constexpr double kSupportRing = 3.5;  // px

// What GJK sees of a shape: a rectangle's or a polygon's corners, a circle's centre and
// radius (gjk.h's rounded shapes).
ConvexProxy gjkProxyOf(const RigidShape& shape) {
    switch (shape.type()) {
        case ShapeType::Rectangle: return makeProxy(static_cast<const Rectangle&>(shape).vertices());
        case ShapeType::Polygon: return makeProxy(static_cast<const Polygon&>(shape).outline().corners());
        case ShapeType::Circle: {
            const Circle& circle = static_cast<const Circle&>(shape);
            const Vec2 center = circle.center();
            return makeProxy(std::span<const Vec2>(&center, 1), circle.radius());
        }
    }
    return {};
}

// The hull of `points` in order round it (Andrew's monotone chain): sorted by x then y,
// a lower and an upper chain, each dropping the point that makes no turn the chain's
// way. A - B has up to 8 x 8 = 64 candidates and 16 corners, more than convex_hull.h's
// polygon holds, so the diagram keeps its own. Points that repeat or lie on a side are
// dropped; one point (two circles) stays one point.
std::vector<Vec2> hullOfDifference(std::vector<Vec2> points) {
    std::sort(points.begin(), points.end(), [](Vec2 p, Vec2 q) { return p.x < q.x || (p.x == q.x && p.y < q.y); });
    points.erase(std::unique(points.begin(), points.end(), [](Vec2 p, Vec2 q) { return p.x == q.x && p.y == q.y; }),
                 points.end());
    if (points.size() < 3) return points;
    std::vector<Vec2> hull(2 * points.size());
    std::size_t k = 0;
    const auto turns = [&](std::size_t floor, Vec2 next) {
        return k >= floor + 2 && (hull[k - 1] - hull[k - 2]).cross(next - hull[k - 2]) <= 0.0;
    };
    for (const Vec2 p : points) {
        while (turns(0, p)) --k;
        hull[k++] = p;
    }
    const std::size_t lower = k - 1;
    for (std::size_t i = points.size() - 1; i-- > 0;) {
        while (turns(lower, points[i])) --k;
        hull[k++] = points[i];
    }
    hull.resize(k - 1);  // the last point is the first again
    return hull;
}

// Where a point of A - B goes in a panel: the difference's box (its rounded outline and
// the origin) scaled to fit the panel below its label, centred, one scale for x and y so
// angles and the distance keep their shape. Every panel has the same map but its corner.
// Every point GJK and EPA visit is a point of A - B, so the box holds them all.
struct PanelMap {
    Vec2 middle;         // the middle of what is drawn, A - B px
    double scale = 1.0;  // panel px per px of A - B
    Vec2 corner;         // the panel's top-left, canvas px
    Vec2 operator()(Vec2 p) const {
        const Vec2 centre{kGjkPanelWidth / 2, (kPanelLabelRoom + kGjkPanelHeight - kPanelPadding) / 2};
        return corner + centre + (p - middle) * scale;
    }
    PanelMap at(Vec2 panel_corner) const { return {middle, scale, panel_corner}; }
};

PanelMap mapFor(const GjkDiagram& diagram) {
    Vec2 low{0, 0};  // the origin is always in the picture
    Vec2 high{0, 0};
    for (const Vec2 p : diagram.difference) {
        low = {std::min(low.x, p.x - diagram.radius), std::min(low.y, p.y - diagram.radius)};
        high = {std::max(high.x, p.x + diagram.radius), std::max(high.y, p.y + diagram.radius)};
    }
    const double width = kGjkPanelWidth - 2 * kPanelPadding;
    const double height = kGjkPanelHeight - kPanelLabelRoom - kPanelPadding;
    const double scale = std::min(width / std::max(high.x - low.x, 1.0), height / std::max(high.y - low.y, 1.0));
    return {.middle = (low + high) * 0.5, .scale = scale};
}

// A panel's frame, A - B in it, and the origin: what every panel shows.
void drawPanel(browser::Canvas& canvas, const PanelMap& to_panel, const GjkDiagram& diagram) {
    canvas.save();
    canvas.setFillStyle(kPanelBackground);
    canvas.fillRect(to_panel.corner.x, to_panel.corner.y, kGjkPanelWidth, kGjkPanelHeight);
    canvas.setStrokeStyle(kPanelFrame);
    canvas.strokeRect(to_panel.corner.x, to_panel.corner.y, kGjkPanelWidth, kGjkPanelHeight);
    canvas.restore();
    // The core's outline, and for rounded shapes a ring of the radii round each corner:
    // the rounded A - B is the core swept by that ring, so the rings show its reach.
    const std::vector<Vec2>& hull = diagram.difference;
    for (std::size_t i = 0; i < hull.size(); ++i) {
        if (hull.size() > 1)
            draw::line(canvas, to_panel(hull[i]), to_panel(hull[(i + 1) % hull.size()]), kDifferenceColor);
        if (diagram.radius > 0.0)
            draw::ring(canvas, to_panel(hull[i]), diagram.radius * to_panel.scale, kDifferenceColor);
    }
    const Vec2 origin = to_panel(Vec2{});
    draw::line(canvas, origin + Vec2{-kOriginReach, 0}, origin + Vec2{kOriginReach, 0}, kOriginColor);
    draw::line(canvas, origin + Vec2{0, -kOriginReach}, origin + Vec2{0, kOriginReach}, kOriginColor);
}

// The simplex's points are w = a - b; gjk.h keeps a and b relative to A's first corner,
// and that offset cancels in the difference, so w is a point of A - B as it is.
void drawSimplex(browser::Canvas& canvas, const PanelMap& to_panel, const Simplex& simplex) {
    for (std::size_t i = 0; i < simplex.count; ++i) {
        for (std::size_t j = i + 1; j < simplex.count; ++j)
            draw::line(canvas, to_panel(simplex.vertices[i].w), to_panel(simplex.vertices[j].w), kSimplexColor);
        draw::marker(canvas, to_panel(simplex.vertices[i].w), kSimplexColor);
    }
}

// One pass of the loop (the file's header): its simplex, where it looked, what it found.
void drawStep(browser::Canvas& canvas, draw::LabelLayout& labels, const PanelMap& to_panel, const GjkDiagram& diagram,
              std::size_t number) {
    const GjkStep& step = diagram.steps[number - 1];
    drawPanel(canvas, to_panel, diagram);
    drawSimplex(canvas, to_panel, step.simplex);
    if (!step.holds_origin && step.direction.length() > 0.0) {
        const Vec2 from = to_panel(step.nearest);
        draw::arrow(canvas, from, from + step.direction.normalize() * kDirectionShown, kSimplexColor);
    }
    if (step.queried) draw::ring(canvas, to_panel(step.support.w), kSupportRing, kSimplexColor);
    std::string label = std::to_string(number);
    if (step.holds_origin) {
        label += ": inside";
    } else if (!step.queried) {
        label += ": cap";  // kMaxGjkIterations queries: the answer so far
    } else if (!step.kept) {
        label += ": no nearer";
    }
    labels.place(canvas, to_panel.corner + Vec2{4, 2}, kSimplexColor, label);
}

// The answer: the distance from the origin to A - B, or EPA's polygon, normal and depth.
void drawAnswer(browser::Canvas& canvas, draw::LabelLayout& labels, const PanelMap& to_panel,
                const GjkDiagram& diagram) {
    drawPanel(canvas, to_panel, diagram);
    const Vec2 origin = to_panel(Vec2{});
    std::string label;
    if (diagram.epa) {
        const std::vector<Vec2>& polygon = diagram.epa_polygon;
        for (std::size_t i = 0; i < polygon.size(); ++i)
            draw::line(canvas, to_panel(polygon[i]), to_panel(polygon[(i + 1) % polygon.size()]), kGapColor);
        draw::arrow(canvas, origin, origin + diagram.epa->normal * kDirectionShown, kGapColor);
        label = draw::fixed(diagram.depth, 2) + " px deep";
    } else {
        drawSimplex(canvas, to_panel, diagram.gjk.simplex);
        // pA - pB is the point of the rounded A - B nearest the origin: the line to it is
        // the distance. When the shapes touch it is the origin itself and draws nothing.
        draw::line(canvas, origin, to_panel(diagram.gjk.point_a - diagram.gjk.point_b), kGapColor);
        label = diagram.gjk.distance > 0.0 ? draw::fixed(diagram.gjk.distance, 2) + " px"
                                           : draw::fixed(diagram.depth, 2) + " px deep";
    }
    labels.place(canvas, to_panel.corner + Vec2{4, 2}, kGapColor, label);
}

}  // namespace

std::optional<GjkDiagram> gjkDiagram(const Core& core) {
    if (core.objectCount() < 2) return std::nullopt;
    const std::size_t first = std::min(core.selectedIndex(), core.objectCount() - 1);
    const ConvexProxy a = gjkProxyOf(core.object(first));
    // The nearest by GJK's own distance, not by centres: a long floor's centre is far
    // from a shape resting on it, yet the floor is what the shape touches.
    std::optional<std::size_t> nearest;
    double nearest_distance = 0.0;
    for (std::size_t i = 0; i < core.objectCount(); ++i) {
        if (i == first) continue;
        const double distance = gjkDistance(a, gjkProxyOf(core.object(i))).distance;
        if (nearest && distance >= nearest_distance) continue;
        nearest = i;
        nearest_distance = distance;
    }
    const ConvexProxy b = gjkProxyOf(core.object(*nearest));
    GjkDiagram diagram{.first = first, .second = *nearest, .radius = a.radius + b.radius};
    // The same call again, now with its trace: the panels draw the walk that gave the answer.
    diagram.gjk = gjkDistance(a, b, {}, &diagram.steps);
    std::vector<Vec2> differences;
    for (std::size_t p = 0; p < a.count; ++p)
        for (std::size_t q = 0; q < b.count; ++q) differences.push_back(a.points[p] - b.points[q]);
    diagram.difference = hullOfDifference(std::move(differences));
    if (diagram.gjk.distance == 0.0) {
        diagram.epa = epaPenetration(a, b, &diagram.epa_polygon);
        if (diagram.epa) {
            // EPA measures the cores; a circle's radius reaches that much deeper.
            diagram.depth = diagram.epa->depth + diagram.radius;
        } else {
            // Rounded shapes whose cores are apart: GJK's last nearest point is the cores'.
            diagram.depth = diagram.radius - diagram.steps.back().nearest.length();
        }
    }
    return diagram;
}

std::vector<Vec2> gjkPanelCorners(std::size_t panels, double canvas_width) {
    const double across = kGjkPanelWidth + kGjkPanelGap, down = kGjkPanelHeight + kGjkPanelGap;
    const double room = canvas_width - 2 * kGjkPanelMargin + kGjkPanelGap;
    const std::size_t per_row = std::max<std::size_t>(1, static_cast<std::size_t>(room / across));
    const std::size_t first_row = std::min(panels, per_row);
    const double left = canvas_width - kGjkPanelMargin - (static_cast<double>(first_row) * across - kGjkPanelGap);
    std::vector<Vec2> corners;
    for (std::size_t i = 0; i < panels; ++i) {
        const auto row = static_cast<double>(i / per_row), column = static_cast<double>(i % per_row);
        corners.push_back({left + column * across, kGjkPanelMargin + row * down});
    }
    return corners;
}

std::vector<CanvasBox> shapeBoxes(const Core& core) {
    std::vector<CanvasBox> boxes;
    for (std::size_t i = 0; i < core.objectCount(); ++i) {
        const ConvexProxy proxy = gjkProxyOf(core.object(i));
        CanvasBox box{proxy.points[0], proxy.points[0]};
        for (std::size_t p = 1; p < proxy.count; ++p) {
            box.low = {std::min(box.low.x, proxy.points[p].x), std::min(box.low.y, proxy.points[p].y)};
            box.high = {std::max(box.high.x, proxy.points[p].x), std::max(box.high.y, proxy.points[p].y)};
        }
        boxes.push_back({box.low - Vec2{proxy.radius, proxy.radius}, box.high + Vec2{proxy.radius, proxy.radius}});
    }
    return boxes;
}

std::vector<Vec2> gjkPanelCorners(std::size_t panels, double canvas_width, double canvas_height,
                                  const std::vector<CanvasBox>& occupied) {
    const std::vector<Vec2> top_right = gjkPanelCorners(panels, canvas_width);
    if (top_right.empty()) return top_right;
    // The block's box in the top right, and how far it moves to each other corner.
    CanvasBox block{top_right.front(), top_right.front()};
    for (const Vec2 corner : top_right) {
        block.low = {std::min(block.low.x, corner.x), std::min(block.low.y, corner.y)};
        block.high = {std::max(block.high.x, corner.x + kGjkPanelWidth),
                      std::max(block.high.y, corner.y + kGjkPanelHeight)};
    }
    const double to_left = kGjkPanelMargin - block.low.x;
    const double to_bottom = canvas_height - kGjkPanelMargin - block.high.y;
    const Vec2 moves[] = {{0, 0}, {to_left, 0}, {0, to_bottom}, {to_left, to_bottom}};
    // How much of the shapes' boxes the block covers there, px^2: a floor under a whole
    // corner counts for more than the tip of a plank.
    const auto covered = [&](Vec2 move) {
        const Vec2 low = block.low + move, high = block.high + move;
        double area = 0.0;
        for (const CanvasBox& box : occupied) {
            const double across = std::min(high.x, box.high.x) - std::max(low.x, box.low.x);
            const double down = std::min(high.y, box.high.y) - std::max(low.y, box.low.y);
            if (across > 0.0 && down > 0.0) area += across * down;
        }
        return area;
    };
    Vec2 best = moves[0];
    for (const Vec2 move : moves) {
        if (covered(move) < covered(best)) best = move;
    }
    std::vector<Vec2> corners;
    for (const Vec2 corner : top_right) corners.push_back(corner + best);
    return corners;
}

void drawGjk(browser::Canvas& canvas, draw::LabelLayout& labels, const Core& core,
             std::vector<browser::LegendEntry>& legend) {
    const std::optional<GjkDiagram> diagram = gjkDiagram(core);
    if (!diagram) {
        // The same four lines with nothing to draw: the legend keeps its length.
        legend.push_back({kDifferenceColor, "A - B: no pair (fewer than two shapes)"});
        legend.push_back({kOriginColor, "origin: in A - B exactly when they touch"});
        legend.push_back({kSimplexColor, "GJK's passes: none"});
        legend.push_back({kGapColor, "closest points: none"});
        return;
    }
    const PanelMap map = mapFor(*diagram);
    const std::vector<Vec2> corners =
        gjkPanelCorners(diagram->steps.size() + 1, canvas.width(), canvas.height(), shapeBoxes(core));
    for (std::size_t i = 0; i < diagram->steps.size(); ++i)
        drawStep(canvas, labels, map.at(corners[i]), *diagram, i + 1);
    drawAnswer(canvas, labels, map.at(corners.back()), *diagram);

    const DistanceResult& gjk = diagram->gjk;
    const std::string distance = draw::fixed(gjk.distance, 2) + " px";
    if (gjk.distance > 0.0) {
        draw::line(canvas, gjk.point_a, gjk.point_b, kGapColor);
        draw::marker(canvas, gjk.point_a, kGapColor);
        draw::marker(canvas, gjk.point_b, kGapColor);
        // Under the line, not over it: above, it would cross the line's own markers.
        labels.place(canvas, (gjk.point_a + gjk.point_b) * 0.5 + Vec2{-20, 6}, kGapColor, distance);
    }
    legend.push_back({kDifferenceColor, "A - B: " + std::to_string(diagram->first) + " (selected) - " +
                                            std::to_string(diagram->second) + " (nearest), x" +
                                            draw::fixed(map.scale, 2)});
    legend.push_back({kOriginColor, "origin: in A - B exactly when they touch"});
    legend.push_back(
        {kSimplexColor, "GJK, " + std::to_string(gjk.iterations) + " queries: simplex, direction, new point"});
    const std::string depth = draw::fixed(diagram->depth, 2) + " px";
    if (gjk.distance > 0.0) {
        legend.push_back({kGapColor, "closest points, distance " + distance});
    } else if (diagram->epa) {
        legend.push_back({kGapColor, "EPA's polygon and normal: depth " + depth});
    } else {
        legend.push_back({kGapColor, "rounded overlap: depth " + depth + " (radii - gap)"});
    }
}

}  // namespace engine
