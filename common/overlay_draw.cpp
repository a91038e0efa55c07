#include "overlay_draw.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "text.h"

namespace browser::overlay {

using lib::Vec2;

namespace {

constexpr double kShortestArrow = 0.01;   // px
constexpr double kSmallestSweep = 0.001;  // rad

// The two strokes of a head at `head` for a shaft pointing along `direction` (unit).
void head_strokes(Canvas& canvas, Vec2 head, Vec2 direction, double length) {
    for (const double side : {+kHeadAngle, -kHeadAngle}) {
        const Vec2 back = direction.rotate(Vec2{}, side).scale(-length);
        canvas.moveTo(head.x, head.y);
        canvas.lineTo(head.x + back.x, head.y + back.y);
    }
}

// Runs `draw` on a fresh path in `color` and strokes it, the canvas's styles kept.
template <class Draw>
void stroked(Canvas& canvas, Color color, Draw draw) {
    canvas.save();
    canvas.setStrokeStyle(color);
    canvas.beginPath();
    draw();
    canvas.stroke();
    canvas.beginPath();
    canvas.restore();
}

}  // namespace

std::string fixed(double value, int decimals) {
    if (std::isnan(value)) return "nan";
    if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
    char text[400];  // the largest double has 309 digits before the point
    std::snprintf(text, sizeof text, "%.*f", std::clamp(decimals, 0, 6), value);
    std::string shown(text);
    // A tiny negative rounds to "-0.00": the sign says nothing a reader can see.
    if (shown.front() == '-' && shown.find_first_not_of("-0.") == std::string::npos) shown.erase(0, 1);
    return shown;
}

void line(Canvas& canvas, Vec2 from, Vec2 to, Color color) {
    stroked(canvas, color, [&] {
        canvas.moveTo(from.x, from.y);
        canvas.lineTo(to.x, to.y);
    });
}

void arrow(Canvas& canvas, Vec2 tail, Vec2 head, Color color) {
    const Vec2 shaft = head - tail;
    const double length = shaft.length();
    if (!(length >= kShortestArrow) || !std::isfinite(length)) return;
    stroked(canvas, color, [&] {
        canvas.moveTo(tail.x, tail.y);
        canvas.lineTo(head.x, head.y);
        head_strokes(canvas, head, shaft.scale(1.0 / length), std::min(kHeadLength, 0.4 * length));
    });
}

void marker(Canvas& canvas, Vec2 at, Color color, std::string_view text) {
    stroked(canvas, color, [&] {
        canvas.moveTo(at.x - kMarkerReach, at.y - kMarkerReach);
        canvas.lineTo(at.x + kMarkerReach, at.y + kMarkerReach);
        canvas.moveTo(at.x - kMarkerReach, at.y + kMarkerReach);
        canvas.lineTo(at.x + kMarkerReach, at.y - kMarkerReach);
    });
    if (!text.empty()) label(canvas, at + kLabelOffset, color, text);
}

void ring(Canvas& canvas, Vec2 center, double r, Color color) {
    stroked(canvas, color, [&] {
        canvas.moveTo(center.x + r, center.y);
        canvas.arc(center.x, center.y, r, 0.0, 2.0 * std::numbers::pi);
    });
}

void turn_arrow(Canvas& canvas, Vec2 center, double r, double start, double sweep, Color color) {
    if (!(std::abs(sweep) >= kSmallestSweep) || !std::isfinite(sweep) || !(r > 0.0)) return;
    const double end = start + sweep;
    const Vec2 tip = center + Vec2(std::cos(end), std::sin(end)).scale(r);
    // Along the ring at the tip, in the direction of travel.
    const Vec2 along = Vec2(-std::sin(end), std::cos(end)).scale(sweep > 0 ? 1.0 : -1.0);
    stroked(canvas, color, [&] {
        canvas.moveTo(center.x + r * std::cos(start), center.y + r * std::sin(start));
        canvas.arc(center.x, center.y, r, start, end, sweep < 0);
        head_strokes(canvas, tip, along, std::min(kHeadLength, 0.4 * r * std::abs(sweep)));
    });
}

void label(Canvas& canvas, Vec2 at, Color color, std::string_view text) {
    canvas.save();
    canvas.setFillStyle(color);
    canvas.fillText(text, at.x, at.y);
    canvas.restore();
}

void LabelLayout::place(Canvas& canvas, Vec2 at, Color color, std::string_view text) {
    const double width = text_width(text), height = text_line_height();
    // On the canvas: its left and top edges win where the label is wider or taller.
    const double left = std::max(kLabelMargin, std::min(at.x, canvas.width() - kLabelMargin - width));
    const double asked_top = std::max(kLabelMargin, std::min(at.y, canvas.height() - kLabelMargin - height));
    const double lowest_top = canvas.height() - kLabelMargin - height;
    const auto at_top = [&](double top) { return Box{left, top, left + width, top + height}; };
    const auto crossed = [this](const Box& box) {
        return std::find_if(placed_.begin(), placed_.end(), [&box](const Box& other) {
            return box.left < other.right + kLabelGap && other.left < box.right + kLabelGap && box.top < other.bottom &&
                   other.top < box.bottom;
        });
    };
    // Down past each label it crosses, while it stays on the canvas; each move clears at
    // least the box it crossed, so this ends within placed_.size() moves. Then up.
    Box box = at_top(asked_top);
    for (auto other = crossed(box); other != placed_.end() && box.top <= lowest_top; other = crossed(box)) {
        box = at_top(other->bottom);
    }
    if (box.top > lowest_top) {
        box = at_top(asked_top);
        for (auto other = crossed(box); other != placed_.end() && box.top >= kLabelMargin; other = crossed(box)) {
            box = at_top(other->top - height);
        }
        if (box.top < kLabelMargin) box = at_top(asked_top);
    }
    placed_.push_back(box);
    label(canvas, {box.left, box.top}, color, text);
}

}  // namespace browser::overlay
