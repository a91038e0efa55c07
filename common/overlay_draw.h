#pragma once
// The drawing words of the stages' overlays (--overlay, key t): what the engine computed
// drawn over the page, in canvas coordinates, each in one colour that the page's legend
// (page.h's Document::legend) names. Every word keeps the canvas's styles and transform
// as it found them, so the page's own drawing after it is unchanged.

#include <string>
#include <string_view>
#include <vector>

#include "canvas.h"
#include "image.h"
#include "vec2.h"

namespace browser::overlay {

// How big an arrow's head is: each of its two strokes is this long, or 40 % of the
// arrow when that is shorter, and this far off the shaft's direction.
inline constexpr double kHeadLength = 7.0;  // px
inline constexpr double kHeadAngle = 0.45;  // rad, about 26 degrees

// How far a marker's cross reaches each way from its point, and where its label goes.
inline constexpr double kMarkerReach = 3.0;           // px
inline constexpr lib::Vec2 kLabelOffset{5.0, -16.0};  // px, from the point to the label's top-left

// An overlay's number as a reader compares it across a picture: always `decimals`
// digits after the point, never exponent notation, never "-0": a resting contact's
// depth reads "0.00", not "3.19e-10", and a hard hit's impulse "2520.00", not "2.52e+3".
// A number that is not finite reads "nan" or "inf".
std::string fixed(double value, int decimals);

// A straight line from `from` to `to` (a pair, a lever arm).
void line(Canvas& canvas, lib::Vec2 from, lib::Vec2 to, Color color);

// A straight arrow from `tail` to `head`. An arrow shorter than a hundredth of a pixel
// has no direction and draws nothing.
void arrow(Canvas& canvas, lib::Vec2 tail, lib::Vec2 head, Color color);

// A cross at `at`, with `label` (one line; "" for none) just above to its right.
void marker(Canvas& canvas, lib::Vec2 at, Color color, std::string_view label = {});

// A ring `r` px around `center` (a bound, a reach).
void ring(Canvas& canvas, lib::Vec2 center, double r, Color color);

// A curved arrow along the ring `r` px around `center`, from the angle `start`
// turning by `sweep` (rad; positive turns clockwise on screen, as angles do in canvas
// coordinates), its head at the end: a spin, or a turn one impulse gives. A sweep under
// a thousandth of a radian draws nothing.
void turn_arrow(Canvas& canvas, lib::Vec2 center, double r, double start, double sweep, Color color);

// A label with its top-left corner at `at`.
void label(Canvas& canvas, lib::Vec2 at, Color color, std::string_view text);

// Labels that must stay readable where what they label crowds together (a pile of
// shapes) or lies at the canvas's edge (a border, a corner): each goes where it is asked
// to, moved in just enough to stand wholly on the canvas, kLabelMargin inside its edge;
// then, if it would cross a label placed before it, as many lines lower as it takes to
// clear them, with kLabelGap to spare on either side, so two labels on one line never run
// into each other; or, where that would take it off the canvas's foot, as many lines
// higher. Only a canvas too full for either keeps it where it was asked, over another.
// One layout a frame.
inline constexpr double kLabelGap = 6.0;     // px between two labels side by side
inline constexpr double kLabelMargin = 2.0;  // px between a label and the canvas's edge (its frame is 1 px)

class LabelLayout {
public:
    void place(Canvas& canvas, lib::Vec2 at, Color color, std::string_view text);

private:
    struct Box {
        double left, top, right, bottom;
    };
    std::vector<Box> placed_;
};

}  // namespace browser::overlay
