#pragma once
// 5.9's part of the overlay (overlay.h): the joints (joints.h), each drawn by its own
// numbers, over the book's shapes, which the page draws as ever (a pin is no shape):
//  - its anchors, a cross where each body holds it, and its links: a line from each
//    body's centre to its anchor, the lever the joint's impulses turn the body by; a
//    distance joint's rod, spring (a zigzag) or rope from anchor to anchor;
//  - its limits: a revolute's range of angles as an arc round the pin, with a needle
//    that turns with the second body and stays inside the arc while the limit holds; a
//    slider's axis, with a tick at each end of its range; a rope's shortest and longest
//    length as ticks along it (a slack rope's longest lies beyond its anchor);
//  - its error (joints.h's separationOf): past kShownError px, the gap between the two
//    anchors drawn and a ring round it, and for the kLabelledErrors largest, the size in
//    px written beside it;
//  - in the legend, how many joints of each kind, how many are past kShownError and the
//    largest error of all; and the two colours the page draws for 5.9 whatever the
//    overlay: a kinematic body's (kinematic_drawing.h) and the mouse joint's line.

#include <cstddef>
#include <optional>
#include <vector>

#include "core.h"
#include "joints.h"
#include "overlay_draw.h"
#include "page.h"

namespace engine {

// An error is shown past this: a rigid joint's gap at rest is hundredths of a px
// (README.md's tests), so a whole pixel, a gap the picture can show, is a joint that
// is working hard, and the quiet ones stay unmarked. The largest kLabelledErrors of
// those get their size written.
inline constexpr double kShownError = 1.0;  // px
inline constexpr std::size_t kLabelledErrors = 4;

// What the layer draws of one joint, worked out apart from the drawing so a test can
// check it. Angles are the canvas's (+y down: a growing angle turns clockwise).
struct JointMark {
    JointType type = JointType::revolute;
    Vec2 center_a, center_b;  // the bodies' centres
    Vec2 anchor_a, anchor_b;  // where each holds the joint now
    double separation = 0.0;  // px (joints.h's separationOf)
    bool spring = false;      // a distance joint with its own hertz
    // A revolute with a limit: the needle (from the pin, along the second body's link,
    // or its own direction when its centre is the pin) and the range it may sweep.
    double needle = 0.0;            // rad
    std::optional<JointRange> arc;  // rad
    // A prismatic: its axis (a unit vector) and where along it, from anchor_a, the range
    // ends (px), or, with no limit, as far as anchor_b and a little more either way.
    Vec2 axis;
    JointRange travel;
    bool travel_limited = false;
    // A rope: its shortest and longest length (px), as ticks from anchor_a toward anchor_b.
    std::optional<JointRange> rope;
};

// Every joint whose two bodies are in the world, in the order of core.joints().all().
std::vector<JointMark> jointMarks(const Core& core);

void drawJoints(browser::Canvas& canvas, browser::overlay::LabelLayout& labels, const Core& core,
                std::vector<browser::LegendEntry>& legend);

}  // namespace engine
