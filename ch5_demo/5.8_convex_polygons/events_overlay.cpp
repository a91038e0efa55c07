#include "events_overlay.h"

#include <string>

namespace engine {

namespace {

using browser::Color;
namespace draw = browser::overlay;

// Colours none of the page (blue, red, green, orange, gray) nor the other layers use.
constexpr Color kEventBeginColor{220, 0, 220, 255};  // magenta
constexpr Color kEventEndColor{140, 70, 0, 255};     // brown
constexpr Color kEventHitColor{0, 90, 200, 255};     // steel blue

// A fresh event is drawn this large; an old one shrinks towards kOldEventSize.
constexpr double kFreshEventSize = 9.0;  // px
constexpr double kOldEventSize = 3.0;    // px
constexpr double kHitRingGap = 4.0;      // px, outside its begin's ring

// How large an event of `age` steps is drawn: from kFreshEventSize when new down to kOldEventSize.
double eventSize(long age) {
    const double share = 1.0 - static_cast<double>(age) / static_cast<double>(kShownSteps);
    return kOldEventSize + (kFreshEventSize - kOldEventSize) * share;
}

void eventCross(browser::Canvas& canvas, Vec2 at, double reach, Color color) {
    draw::line(canvas, at + Vec2{-reach, -reach}, at + Vec2{reach, reach}, color);
    draw::line(canvas, at + Vec2{-reach, reach}, at + Vec2{reach, -reach}, color);
}

}  // namespace

void drawEvents(browser::Canvas& canvas, draw::LabelLayout& labels, const Core& core,
                std::vector<browser::LegendEntry>& legend) {
    const ContactEvents& events = core.events();
    int begins = 0, ends = 0, hits = 0;
    for (const ContactEvent& event : events.recent()) {
        const double size = eventSize(events.step() - event.step);
        switch (event.kind) {
            case EventKind::begin:
                draw::ring(canvas, event.point, size, kEventBeginColor);
                ++begins;
                break;
            case EventKind::end:
                eventCross(canvas, event.point, size * 0.7, kEventEndColor);
                ++ends;
                break;
            case EventKind::hit:
                draw::ring(canvas, event.point, size + kHitRingGap, kEventHitColor);
                labels.place(canvas, event.point + draw::kLabelOffset, kEventHitColor,
                             draw::fixed(event.speed, 0) + " px/s");
                ++hits;
                break;
        }
    }
    for (std::size_t i = 0; i < core.objectCount(); ++i) {
        const RigidShape& shape = core.object(i);
        if (shape.isSensor()) labels.place(canvas, shape.center(), kEventBeginColor, "sensor");
    }
    legend.push_back({kEventBeginColor, "begin: a pair starts touching"});
    legend.push_back({kEventEndColor, "end: it stops (x)"});
    legend.push_back({kEventHitColor, "hit: a begin faster than " + draw::fixed(kHitSpeed, 0) + " px/s"});
    legend.push_back({kEventBeginColor, "in 0.5 s: begins " + std::to_string(begins) + ", ends " +
                                            std::to_string(ends) + ", hits " + std::to_string(hits) + "; touching " +
                                            std::to_string(events.touchingCount())});
}

}  // namespace engine
