#include "canvas.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <utility>

#include "text.h"  // draw_text, the page's font

namespace browser {

namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

// The pen is 1 px wide. A pixel whose centre lies a distance d from the path has about
// 1 - d of its area under the pen: exactly so for horizontal and vertical lines (a line
// through pixel centres fills one row, a line along pixel edges half-fills two rows).
// So coverage falls linearly from 1 on the path to 0 one pixel away, and changes only
// a little when the path moves a little: a slowly turning shape does not flicker.
// On a canvas of scale K the pen is K device pixels wide, and its reach K of them.
constexpr double kPenReach = 1.0;

// Arcs are drawn as chords. A chord spanning the angle t lies at most r (1 - cos(t/2))
// inside its circle; we keep that gap below a fiftieth of a device pixel, so circles
// look round.
constexpr double kArcTolerance = 0.02;
constexpr int kMostArcChords = 4096;  // keeps absurd radii from costing absurd time

// Segments are cut to the canvas grown by this margin (in pen widths) before any pixel
// work: what lies farther out cannot reach a pixel, and coordinates near the canvas
// keep the distance arithmetic exact even when the caller passed 1e300.
constexpr double kClipMargin = 2.0;

struct Segment {
    double x0, y0, x1, y1;
};

struct Box {
    double left, top, right, bottom;
};

// Keeps the part of the segment (u0, v0)-(u1, v1) on the inner side of the line u = edge
// (u >= edge, or u <= edge); false when nothing is left. An end outside is moved along
// the segment onto the line. Its v follows from the slope, taken from the end inside
// (the one near the canvas), so a line parallel to an axis keeps its exact position
// even when its other end is at 1e300.
bool clip_side(double& u0, double& v0, double& u1, double& v1, double edge, bool keep_above) {
    const bool inside0 = keep_above ? u0 >= edge : u0 <= edge;
    const bool inside1 = keep_above ? u1 >= edge : u1 <= edge;
    if (!inside0 && !inside1) return false;
    if (inside0 && inside1) return true;
    // Halving before subtracting keeps differences of huge coordinates finite.
    const double slope = (0.5 * v1 - 0.5 * v0) / (0.5 * u1 - 0.5 * u0);
    if (inside0) {
        v1 = v0 + (edge - u0) * slope;
        u1 = edge;
    } else {
        v0 = v1 + (edge - u1) * slope;
        u0 = edge;
    }
    return true;
}

// The part of s inside the box, one side at a time, or nothing.
std::optional<Segment> clip(Segment s, const Box& box) {
    const bool kept =
        clip_side(s.x0, s.y0, s.x1, s.y1, box.left, true) && clip_side(s.x0, s.y0, s.x1, s.y1, box.right, false) &&
        clip_side(s.y0, s.x0, s.y1, s.x1, box.top, true) && clip_side(s.y0, s.x0, s.y1, s.x1, box.bottom, false);
    // Spans beyond the range of a double can still make a crossing overflow.
    if (!kept || !std::isfinite(s.x0 + s.y0 + s.x1 + s.y1)) return std::nullopt;
    return s;
}

// Pixel i has its centre at i + 0.5; these give the pixels whose centres lie in
// [low, high], cut to [0, size). Safe for any double, NaN included.
int first_pixel(double low, int size) {
    const double i = std::ceil(low - 0.5);
    return i > 0.0 ? static_cast<int>(std::min(i, static_cast<double>(size))) : 0;
}
int end_pixel(double high, int size) {  // one past the last
    const double i = std::floor(high - 0.5) + 1.0;
    return i > 0.0 ? static_cast<int>(std::min(i, static_cast<double>(size))) : 0;
}

// Angle the arc turns through, in [-2 pi, 2 pi]. As browsers do, an arc turns at most once
// round, and an end angle on the "wrong" side of the start is reached by carrying on
// round the circle in the asked direction.
double arc_sweep(double a0, double a1, bool counterclockwise) {
    if (!counterclockwise) {
        if (a1 - a0 >= kTwoPi) return kTwoPi;
        if (a0 > a1) return kTwoPi - std::fmod(a0 - a1, kTwoPi);
        return a1 - a0;
    }
    if (a0 - a1 >= kTwoPi) return -kTwoPi;
    if (a0 < a1) return -(kTwoPi - std::fmod(a1 - a0, kTwoPi));
    return a1 - a0;
}

std::uint8_t mix(std::uint8_t from, std::uint8_t to, double alpha) {
    return static_cast<std::uint8_t>(from + (to - from) * alpha + 0.5);  // rounded: never below 0
}

// A coverage mask over the pixels the pen can reach: for each, how much of it the
// stroke covers, from 0 to 1. Where segments meet, or an arc's short chords overlap, a
// pixel lies near several segments, but the pen passes over it once: each pixel keeps
// its largest coverage, not the sum.
struct CoverageMask {
    int i0 = 0, i1 = 0, j0 = 0, j1 = 0;  // the device pixels [i0, i1) x [j0, j1)
    std::vector<float> coverage;         // row by row; empty when the box is
    float* row(int j) { return &coverage[static_cast<std::size_t>(j - j0) * static_cast<std::size_t>(i1 - i0)]; }
    float at(int i, int j) const {
        return coverage[static_cast<std::size_t>(j - j0) * static_cast<std::size_t>(i1 - i0) +
                        static_cast<std::size_t>(i - i0)];
    }
};

// Raises the mask's pixels to the coverage of one segment of the path.
void cover_segment(CoverageMask& mask, const Segment& s, double reach, int device_width, int device_height) {
    const double dx = s.x1 - s.x0, dy = s.y1 - s.y0;
    const double length_squared = dx * dx + dy * dy;
    const int j0 = std::max(mask.j0, first_pixel(std::min(s.y0, s.y1) - reach, device_height));
    const int j1 = std::min(mask.j1, end_pixel(std::max(s.y0, s.y1) + reach, device_height));
    for (int j = j0; j < j1; ++j) {
        // Only the part of the segment within reach of this row's centre line can
        // light pixels of the row: find its x extent, so a long slanted segment costs
        // a few pixels per row rather than its whole bounding box.
        const double cy = j + 0.5;
        double t_low = 0.0, t_high = 1.0;
        if (dy != 0.0) {
            const double ta = (cy - reach - s.y0) / dy, tb = (cy + reach - s.y0) / dy;
            t_low = std::max(0.0, std::min(ta, tb));
            t_high = std::min(1.0, std::max(ta, tb));
            if (t_low > t_high) continue;
        }
        const double xa = s.x0 + t_low * dx, xb = s.x0 + t_high * dx;
        const int i0 = std::max(mask.i0, first_pixel(std::min(xa, xb) - reach, device_width));
        const int i1 = std::min(mask.i1, end_pixel(std::max(xa, xb) + reach, device_width));
        float* row = mask.row(j);
        for (int i = i0; i < i1; ++i) {
            // Distance from the pixel centre to the nearest point of the segment: project
            // onto the segment's line and stop at its ends. (So ends and joins come out
            // round, where the browser's are flat and mitred: for a 1 px pen the two
            // differ by less than half a pixel, at the very ends.)
            const double px = i + 0.5 - s.x0, py = cy - s.y0;
            const double t = std::clamp((px * dx + py * dy) / length_squared, 0.0, 1.0);
            const double ex = px - t * dx, ey = py - t * dy;
            const double distance_squared = ex * ex + ey * ey;
            if (distance_squared >= reach * reach) continue;
            const float c = static_cast<float>(1.0 - std::sqrt(distance_squared) / reach);
            float& cell = row[i - mask.i0];
            cell = std::max(cell, c);
        }
    }
}

// The mask of a whole path of (non-empty) segments, over their box grown by the reach.
CoverageMask coverage_mask(const std::vector<Segment>& segments, double reach, int device_width, int device_height) {
    double left = segments[0].x0, right = left, top = segments[0].y0, bottom = top;
    for (const Segment& s : segments) {
        left = std::min({left, s.x0, s.x1});
        right = std::max({right, s.x0, s.x1});
        top = std::min({top, s.y0, s.y1});
        bottom = std::max({bottom, s.y0, s.y1});
    }
    CoverageMask mask{.i0 = first_pixel(left - reach, device_width),
                      .i1 = end_pixel(right + reach, device_width),
                      .j0 = first_pixel(top - reach, device_height),
                      .j1 = end_pixel(bottom + reach, device_height)};
    if (mask.i0 >= mask.i1 || mask.j0 >= mask.j1) return mask;
    mask.coverage.assign(static_cast<std::size_t>(mask.i1 - mask.i0) * static_cast<std::size_t>(mask.j1 - mask.j0),
                         0.0f);
    for (const Segment& s : segments) cover_segment(mask, s, reach, device_width, device_height);
    return mask;
}

// Paints the pen's colour over each pixel once, in proportion to its coverage ("source
// over": the colour's own alpha scales the coverage).
void paint(Image& pixels, const CoverageMask& mask, Color pen) {
    for (int j = mask.j0; j < mask.j1; ++j) {
        for (int i = mask.i0; i < mask.i1; ++i) {
            const float c = mask.at(i, j);
            if (c <= 0.0f) continue;
            const double alpha = c * (pen.a / 255.0);
            const Color under = pixels.at(i, j);
            pixels.set(i, j,
                       {mix(under.r, pen.r, alpha), mix(under.g, pen.g, alpha), mix(under.b, pen.b, alpha),
                        mix(under.a, 255, alpha)});
        }
    }
}

}  // namespace

Canvas::Canvas(int width, int height, int scale) : width_(width), height_(height), scale_(1) { setScale(scale); }

void Canvas::setScale(int scale) {
    if (scale < 1 || scale > kMaxScale) throw std::invalid_argument("Canvas: scale must be 1 to 4");
    scale_ = scale;
    pixels_ = Image(width_ * scale, height_ * scale, colors::kWhite);
}

Canvas::Point Canvas::apply(double x, double y) const {
    const Transform& m = transform_;
    const double k = scale_;
    return {k * (m.a * x + m.c * y + m.e), k * (m.b * x + m.d * y + m.f)};
}

void Canvas::clearRect(double x, double y, double w, double h) {
    // Row by row: the horizontal line through the row's pixel centres is taken into the
    // rectangle's own coordinates (through the inverse transform), cut to the rectangle,
    // and what remains is taken back to tell which pixels of the row to erase.
    const Transform& m = transform_;
    const double determinant = m.a * m.d - m.b * m.c;
    if (!std::isfinite(determinant) || determinant == 0.0) return;  // such a transform covers no area
    const double k = scale_;
    auto to_rectangle = [&](double px, double py) {  // from device pixels
        px = px / k - m.e;
        py = py / k - m.f;
        return Point{(m.d * px - m.c * py) / determinant, (m.a * py - m.b * px) / determinant};
    };
    const int device_width = pixels_.width, device_height = pixels_.height;
    const Box rectangle{std::min(x, x + w), std::min(y, y + h), std::max(x, x + w), std::max(y, y + h)};
    for (int j = 0; j < device_height; ++j) {
        const Point from = to_rectangle(-kClipMargin * k, j + 0.5);
        const Point to = to_rectangle(device_width + kClipMargin * k, j + 0.5);
        const auto inside = clip({from.x, from.y, to.x, to.y}, rectangle);
        if (!inside) continue;
        const double xa = apply(inside->x0, inside->y0).x, xb = apply(inside->x1, inside->y1).x;
        const int i0 = first_pixel(std::min(xa, xb), device_width), i1 = end_pixel(std::max(xa, xb), device_width);
        // The run's bytes lie side by side, and white is 255 in each of them.
        static_assert(colors::kWhite == Color{255, 255, 255, 255});
        if (i0 < i1) {
            const auto row = pixels_.rgba.begin() + static_cast<std::ptrdiff_t>(j) * device_width * 4;
            std::fill(row + i0 * 4, row + i1 * 4, std::uint8_t{255});
        }
    }
}

void Canvas::beginPath() {
    subpaths_.clear();
    closed_.clear();
}

void Canvas::moveTo(double x, double y) {
    subpaths_.push_back({apply(x, y)});
    closed_.push_back(false);
}

void Canvas::lineTo(double x, double y) {
    if (subpaths_.empty()) {
        moveTo(x, y);  // with no current point, lineTo only moves there
        return;
    }
    subpaths_.back().push_back(apply(x, y));
}

void Canvas::arc(double cx, double cy, double r, double a0, double a1, bool counterclockwise) {
    for (double v : {cx, cy, r, a0, a1}) {
        if (!std::isfinite(v)) return;  // the browser ignores such a call
    }
    if (r < 0) return;  // the browser throws; drawing nothing is our equivalent

    const double sweep = arc_sweep(a0, a1, counterclockwise);
    if (!std::isfinite(sweep)) return;  // angles too far apart for a double to tell the end
    int chords = 1;
    const double device_r = r * scale_;
    if (device_r > kArcTolerance) {
        // For absurd radii the widest angle rounds to 0, and `needed` to infinity or NaN.
        const double widest_chord_angle = 2.0 * std::acos(1.0 - kArcTolerance / device_r);
        const double needed = std::ceil(std::abs(sweep) / widest_chord_angle);
        if (needed > 1.0) chords = static_cast<int>(std::min(needed, static_cast<double>(kMostArcChords)));
    }
    for (int k = 0; k <= chords; ++k) {
        const double angle = a0 + sweep * k / chords;
        const double x = cx + r * std::cos(angle), y = cy + r * std::sin(angle);
        // The first point is joined to the current point by a line, if there is one.
        if (k == 0 && subpaths_.empty()) moveTo(x, y);
        else lineTo(x, y);
    }
}

void Canvas::closePath() {
    if (subpaths_.empty()) return;
    closed_.back() = true;
    // Drawing goes on from where the closed subpath began, in a new subpath.
    const Point start = subpaths_.back().front();
    subpaths_.push_back({start});
    closed_.push_back(false);
}

void Canvas::stroke() {
    // 1. The path as straight segments, cut to the neighbourhood of the canvas. A segment
    //    with a NaN or infinite end has no place to draw; one of zero length has no
    //    direction, and the browser's flat-ended pen draws nothing for it.
    const double reach = kPenReach * scale_;  // in device pixels, as everything below
    const int device_width = pixels_.width, device_height = pixels_.height;
    const double margin = kClipMargin * scale_;
    const Box near_canvas{-margin, -margin, device_width + margin, device_height + margin};
    std::vector<Segment> segments;
    auto add = [&](Point a, Point b) {
        if (!std::isfinite(a.x) || !std::isfinite(a.y) || !std::isfinite(b.x) || !std::isfinite(b.y)) return;
        if (a.x == b.x && a.y == b.y) return;
        const auto part = clip({a.x, a.y, b.x, b.y}, near_canvas);
        // Cut to a sliver by rounding, a segment can end up a single point.
        if (part && (part->x0 != part->x1 || part->y0 != part->y1)) segments.push_back(*part);
    };
    for (std::size_t s = 0; s < subpaths_.size(); ++s) {
        const std::vector<Point>& points = subpaths_[s];
        for (std::size_t k = 1; k < points.size(); ++k) add(points[k - 1], points[k]);
        if (closed_[s] && points.size() > 2) add(points.back(), points.front());
    }
    if (segments.empty()) return;

    // 2. How much of each pixel within the pen's reach the path covers; 3. the paint.
    const CoverageMask mask = coverage_mask(segments, reach, device_width, device_height);
    if (!mask.coverage.empty()) paint(pixels_, mask, stroke_color_);
}

void Canvas::strokeRect(double x, double y, double w, double h) {
    // The rectangle is a path of its own: the current path is set aside and put back.
    auto subpaths = std::move(subpaths_);
    auto closed = std::move(closed_);
    beginPath();
    moveTo(x, y);
    lineTo(x + w, y);
    lineTo(x + w, y + h);
    lineTo(x, y + h);
    closePath();
    stroke();
    subpaths_ = std::move(subpaths);
    closed_ = std::move(closed);
}

void Canvas::fillRect(double x, double y, double w, double h) {
    const double k = scale_;
    const double left = k * (std::min(x, x + w) + transform_.e), right = k * (std::max(x, x + w) + transform_.e);
    const double top = k * (std::min(y, y + h) + transform_.f), bottom = k * (std::max(y, y + h) + transform_.f);
    const int i_end = end_pixel(right, pixels_.width), j_end = end_pixel(bottom, pixels_.height);
    for (int j = first_pixel(top, pixels_.height); j < j_end; ++j) {
        for (int i = first_pixel(left, pixels_.width); i < i_end; ++i) pixels_.set(i, j, fill_color_);
    }
}

void Canvas::fillText(std::string_view text, double x, double y) {
    const Point corner{scale_ * (x + transform_.e), scale_ * (y + transform_.f)};
    // Far-off or NaN corners would not fit an int; such text could show nothing anyway.
    constexpr double kReach = 1e6;
    if (!(std::abs(corner.x) < kReach && std::abs(corner.y) < kReach)) return;
    draw_text(pixels_, text, static_cast<int>(std::lround(corner.x)), static_cast<int>(std::lround(corner.y)),
              fill_color_, scale_);
}

void Canvas::save() { saved_.push_back({transform_, stroke_color_, fill_color_}); }

void Canvas::restore() {
    if (saved_.empty()) return;
    transform_ = saved_.back().transform;
    stroke_color_ = saved_.back().stroke_color;
    fill_color_ = saved_.back().fill_color;
    saved_.pop_back();
}

// translate and rotate multiply the current matrix on the right, so the newest call acts
// first on a point: after translate(vx, vy) then rotate(a), a point is turned about the
// origin and then moved to (vx, vy), which is how a page places a turned outline.
void Canvas::translate(double dx, double dy) {
    Transform& m = transform_;
    m.e += m.a * dx + m.c * dy;
    m.f += m.b * dx + m.d * dy;
}

void Canvas::rotate(double radians) {
    // Right-multiply by the rotation [cos -sin; sin cos] (+y down, so it turns clockwise
    // on screen).
    Transform& m = transform_;
    const double cos_a = std::cos(radians), sin_a = std::sin(radians);
    const Transform old = m;
    m.a = old.a * cos_a + old.c * sin_a;
    m.b = old.b * cos_a + old.d * sin_a;
    m.c = old.c * cos_a - old.a * sin_a;
    m.d = old.d * cos_a - old.b * sin_a;
}

}  // namespace browser
