#pragma once
// The pointer: a mouse (or a finger) pressed on the canvas, moved while held, and let
// go. The browser reports each as an event at a point of the canvas, in the canvas's
// own units (the px the page draws in, whatever --scale), rounded to whole px, so that
// what a live window reports and what a replay reports are the same numbers. What a
// press does is the page's (PageScripts::onPointer); the browser knows no shape.
//
// In a key script (keys.h) a drag is one token, one point a frame:
//     drag:X,Y[*N]/X,Y[*N]/...[@FRAME]
// The pointer is pressed at the first point before frame FRAME, is at the k-th point
// (counting each point N times) before frame FRAME + k, and is let go, where it last
// was, before frame FRAME + (the number of points). Before each frame at which it is
// somewhere new it moves there; where it stays, nothing happens. So "drag:100,50*3/
// 120,50@10" presses at (100, 50) before frame 10, moves to (120, 50) before frame 13
// and lets go before frame 14. A drag ends before the next one starts.

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace browser {

// A point of the canvas, whole px from its top-left corner (y down).
struct PointerPoint {
    int x = 0;
    int y = 0;
    friend bool operator==(PointerPoint, PointerPoint) = default;
};

struct PointerEvent {
    enum class Kind { press, move, release };
    Kind kind = Kind::press;
    PointerPoint point;
    friend bool operator==(const PointerEvent&, const PointerEvent&) = default;
};

// One drag: where the pointer is before each frame from `frame` on, pressed at the
// first point and let go one frame after the last.
struct Drag {
    int frame = 0;
    std::vector<PointerPoint> points;  // one a frame; never empty
    // The frame before which it is let go.
    int releaseFrame() const { return frame + static_cast<int>(points.size()); }
    // What happens before `at`, if anything: a press, a move or a release.
    std::optional<PointerEvent> eventAt(int at) const;
    friend bool operator==(const Drag&, const Drag&) = default;
};

// Points in a script are whole numbers in [-kMaxPointerCoordinate, kMaxPointerCoordinate].
inline constexpr int kMaxPointerCoordinate = 100'000;

// The token's text without its frame ("drag:100,50*3/120,50"), points that repeat
// written once with *N.
std::string drag_text(const Drag& drag);
// The points of a token's text between "drag:" and the '@' ("100,50*3/120,50"), each
// repeat counted; `points_left` is how many more the script may hold. The reason it is
// refused, or the points.
struct DragPoints {
    std::vector<PointerPoint> points;
    std::string refusal;  // empty when the points are good
};
DragPoints parse_drag_points(std::string_view text, std::size_t points_left);

}  // namespace browser
