#include "pointer.h"

#include <algorithm>
#include <charconv>

namespace browser {
namespace {

// The whole of `text` as a whole number in [low, high], a minus sign allowed.
std::optional<int> whole(std::string_view text, int low, int high) {
    int value = 0;
    const char* end = text.data() + text.size();
    const auto [stop, error] = std::from_chars(text.data(), end, value);
    if (text.empty() || error != std::errc{} || stop != end || value < low || value > high) return std::nullopt;
    return value;
}

}  // namespace

std::optional<PointerEvent> Drag::eventAt(int at) const {
    if (at < frame || at > releaseFrame()) return std::nullopt;
    const auto k = static_cast<std::size_t>(at - frame);
    if (k == 0) return PointerEvent{PointerEvent::Kind::press, points.front()};
    if (k == points.size()) return PointerEvent{PointerEvent::Kind::release, points.back()};
    if (points[k] == points[k - 1]) return std::nullopt;  // held still: nothing happens
    return PointerEvent{PointerEvent::Kind::move, points[k]};
}

std::string drag_text(const Drag& drag) {
    std::string text = "drag:";
    std::size_t i = 0;
    while (i < drag.points.size()) {
        std::size_t same = i + 1;
        while (same < drag.points.size() && drag.points[same] == drag.points[i]) ++same;
        if (i > 0) text += '/';
        text += std::to_string(drag.points[i].x) + ',' + std::to_string(drag.points[i].y);
        if (same - i > 1) text += '*' + std::to_string(same - i);
        i = same;
    }
    return text;
}

DragPoints parse_drag_points(std::string_view text, std::size_t points_left) {
    DragPoints result;
    const auto refuse = [&](std::string reason) {
        result.points.clear();
        result.refusal = std::move(reason);
        return result;
    };
    if (text.empty()) return refuse("a drag needs at least one point, X,Y");
    std::size_t pos = 0;
    while (pos <= text.size()) {
        const std::size_t slash = std::min(text.find('/', pos), text.size());
        std::string_view point = text.substr(pos, slash - pos);
        pos = slash + 1;
        std::size_t repeat = 1;
        if (const auto star = point.find('*'); star != std::string_view::npos) {
            const auto count = whole(point.substr(star + 1), 1, static_cast<int>(points_left));
            if (!count) return refuse("a point's *N must be a whole number from 1 to the points left");
            repeat = static_cast<std::size_t>(*count);
            point = point.substr(0, star);
        }
        const std::size_t comma = point.find(',');
        const auto x = comma == std::string_view::npos
                           ? std::nullopt
                           : whole(point.substr(0, comma), -kMaxPointerCoordinate, kMaxPointerCoordinate);
        const auto y = comma == std::string_view::npos
                           ? std::nullopt
                           : whole(point.substr(comma + 1), -kMaxPointerCoordinate, kMaxPointerCoordinate);
        if (!x || !y) {
            return refuse("a point must be X,Y, two whole numbers of px from -" +
                          std::to_string(kMaxPointerCoordinate) + " to " + std::to_string(kMaxPointerCoordinate));
        }
        if (repeat > points_left - result.points.size()) {
            return refuse("the script drags for more than " + std::to_string(points_left) + " frames in all");
        }
        result.points.insert(result.points.end(), repeat, PointerPoint{*x, *y});
    }
    return result;
}

}  // namespace browser
