#pragma once
// 5.9: how the page draws a kinematic body (rigid_shape.h's isKinematic: a moving
// platform, a turntable), so that a reader can tell it from the shapes it carries
// without the overlay. It moves by its own velocity and nothing else, so that velocity
// is the one thing about it worth a picture: its outline is drawn in kKinematicColor,
// and over it, in the same colour, a dot at its centre (what it turns about), an arrow
// from there to where its velocity takes the centre in kKinematicMotionShown, and a
// curved arrow inside its outline, turning the way it turns, as far as it turns in that
// time. A still one gets the colour and the dot only. The overlay's legend names the
// colour (joints_overlay.h), and so does the band under the panel (core.cpp).

#include "canvas.h"
#include "rigid_shape.h"

namespace engine {

// Purple: none of the page's colours (blue, red for the selected shape, gray asleep,
// green a sensor, orange what the game paints and the mouse's line).
inline constexpr browser::Color kKinematicColor{170, 0, 170, 255};

// The motion drawn is the motion of this much time: a platform at 60 px/s gets an arrow
// 60 px long, a turntable at 0.3 rad/s an arc of 0.3 rad (17 degrees).
inline constexpr double kKinematicMotionShown = 1.0;  // s

// The turn's curved arrow runs round the centre at this share of the body's bounding
// radius: inside a round body's outline, and long enough to read at a slow turn (0.3
// rad at 0.75 of a 110 px turntable's bound is 25 px of arc).
inline constexpr double kKinematicTurnRadius = 0.75;

// The centre's dot, px.
inline constexpr double kKinematicCenterDot = 2.0;

// The dot and the arrows over a kinematic body (its outline is drawn by the page, in
// kKinematicColor unless it is the selected shape).
void drawKinematicMotion(browser::Canvas& context, const RigidShape& shape);

}  // namespace engine
