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
constexpr Color kGapColor{190, 0, 60, 255};          // raspberry: the distance and closest points

// The inset: a square this large in the canvas's top-right corner, out of the way of
// the book's demo, which fills the floor and the middle. A - B lies round the origin,
// not where the shapes are, so it gets a frame of its own instead of the page's axes.
constexpr double kInsetSize = 200.0;    // px
constexpr double kInsetMargin = 8.0;    // px from the canvas's edge
constexpr double kInsetPadding = 14.0;  // px inside the frame, kept clear of the drawing
constexpr Color kInsetBackground = browser::colors::kWhite;
constexpr Color kInsetFrame{150, 150, 150, 255};
// The origin's cross is drawn this far each way: larger than a marker, so that it reads
// as the diagram's axes and not as a point GJK found.
constexpr double kOriginReach = 6.0;  // px

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

// Where a point of A - B goes in the inset: the difference's box (its rounded outline
// and the origin) scaled to fit inside the padding, centred, one scale for x and y so
// angles and the distance keep their shape.
struct InsetMap {
    Vec2 corner;         // the inset's top-left, canvas px
    Vec2 middle;         // the middle of what is drawn, A - B px
    double scale = 1.0;  // inset px per px of A - B
    Vec2 operator()(Vec2 p) const { return corner + Vec2{kInsetSize / 2, kInsetSize / 2} + (p - middle) * scale; }
};

InsetMap insetFor(const GjkDiagram& diagram, double canvas_width) {
    Vec2 low{0, 0};  // the origin is always in the picture
    Vec2 high{0, 0};
    for (const Vec2 p : diagram.difference) {
        low = {std::min(low.x, p.x - diagram.radius), std::min(low.y, p.y - diagram.radius)};
        high = {std::max(high.x, p.x + diagram.radius), std::max(high.y, p.y + diagram.radius)};
    }
    const double span = std::max({high.x - low.x, high.y - low.y, 1.0});
    return {.corner = {canvas_width - kInsetSize - kInsetMargin, kInsetMargin},
            .middle = (low + high) * 0.5,
            .scale = (kInsetSize - 2 * kInsetPadding) / span};
}

void originCross(browser::Canvas& canvas, Vec2 at) {
    draw::line(canvas, at + Vec2{-kOriginReach, 0}, at + Vec2{kOriginReach, 0}, kOriginColor);
    draw::line(canvas, at + Vec2{0, -kOriginReach}, at + Vec2{0, kOriginReach}, kOriginColor);
}

void drawInset(browser::Canvas& canvas, draw::LabelLayout& labels, const GjkDiagram& diagram) {
    const InsetMap to_inset = insetFor(diagram, canvas.width());
    canvas.save();
    canvas.setFillStyle(kInsetBackground);
    canvas.fillRect(to_inset.corner.x, to_inset.corner.y, kInsetSize, kInsetSize);
    canvas.setStrokeStyle(kInsetFrame);
    canvas.strokeRect(to_inset.corner.x, to_inset.corner.y, kInsetSize, kInsetSize);
    canvas.restore();
    // The core's outline, and for rounded shapes a ring of the radii round each corner:
    // the rounded A - B is the core swept by that ring, so the rings show its reach.
    const std::vector<Vec2>& hull = diagram.difference;
    for (std::size_t i = 0; i < hull.size(); ++i) {
        if (hull.size() > 1)
            draw::line(canvas, to_inset(hull[i]), to_inset(hull[(i + 1) % hull.size()]), kDifferenceColor);
        if (diagram.radius > 0.0)
            draw::ring(canvas, to_inset(hull[i]), diagram.radius * to_inset.scale, kDifferenceColor);
    }
    originCross(canvas, to_inset(Vec2{}));
    // The simplex's points are w = a - b; gjk.h keeps a and b relative to A's first
    // corner, and that offset cancels in the difference, so w is a point of A - B as is.
    const Simplex& simplex = diagram.gjk.simplex;
    for (std::size_t i = 0; i < simplex.count; ++i) {
        for (std::size_t j = i + 1; j < simplex.count; ++j)
            draw::line(canvas, to_inset(simplex.vertices[i].w), to_inset(simplex.vertices[j].w), kSimplexColor);
        draw::marker(canvas, to_inset(simplex.vertices[i].w), kSimplexColor);
    }
    // pA - pB is the point of the rounded A - B nearest the origin: the line to it is
    // the distance. When the shapes touch it is the origin itself and draws nothing.
    const Vec2 nearest = diagram.gjk.point_a - diagram.gjk.point_b;
    draw::line(canvas, to_inset(Vec2{}), to_inset(nearest), kGapColor);
    labels.place(canvas, to_inset.corner + Vec2{4, 2}, kDifferenceColor, "A - B, x" + draw::fixed(to_inset.scale, 2));
}

}  // namespace

std::optional<GjkDiagram> gjkDiagram(const Core& core) {
    if (core.objectCount() < 2) return std::nullopt;
    const std::size_t first = std::min(core.selectedIndex(), core.objectCount() - 1);
    const ConvexProxy a = gjkProxyOf(core.object(first));
    std::optional<GjkDiagram> best;
    // The nearest by GJK's own distance, not by centres: a long floor's centre is far
    // from a shape resting on it, yet the floor is what the shape touches.
    for (std::size_t i = 0; i < core.objectCount(); ++i) {
        if (i == first) continue;
        const ConvexProxy b = gjkProxyOf(core.object(i));
        const DistanceResult result = gjkDistance(a, b);
        if (best && result.distance >= best->gjk.distance) continue;
        GjkDiagram diagram{.first = first, .second = i, .radius = a.radius + b.radius, .gjk = result};
        std::vector<Vec2> differences;
        for (std::size_t p = 0; p < a.count; ++p)
            for (std::size_t q = 0; q < b.count; ++q) differences.push_back(a.points[p] - b.points[q]);
        diagram.difference = hullOfDifference(std::move(differences));
        best = std::move(diagram);
    }
    return best;
}

void drawGjk(browser::Canvas& canvas, draw::LabelLayout& labels, const Core& core,
             std::vector<browser::LegendEntry>& legend) {
    const std::optional<GjkDiagram> diagram = gjkDiagram(core);
    if (!diagram) {
        // The same four lines with nothing to draw: the legend keeps its length.
        legend.push_back({kDifferenceColor, "A - B: no pair (fewer than two shapes)"});
        legend.push_back({kOriginColor, "origin: in A - B exactly when they touch"});
        legend.push_back({kSimplexColor, "GJK's last simplex: none"});
        legend.push_back({kGapColor, "closest points: none"});
        return;
    }
    drawInset(canvas, labels, *diagram);
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
                                            std::to_string(diagram->second) + " (nearest)"});
    legend.push_back({kOriginColor, "origin: in A - B exactly when they touch"});
    legend.push_back({kSimplexColor, "GJK's last simplex: " + std::to_string(gjk.simplex.count) + " points, " +
                                         std::to_string(gjk.iterations) + " queries"});
    legend.push_back({kGapColor, gjk.distance > 0.0 ? "closest points, distance " + distance
                                                    : "touching or overlapping: distance 0 (EPA's turn)"});
}

}  // namespace engine
