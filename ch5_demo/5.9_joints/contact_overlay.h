#pragma once
// 5.4's part of the overlay (overlay.h): what the sequential impulse solver
// worked on in the last step, drawn by the solver's own numbers.
//  - For two rectangles, the reference face (whose normal the separating axis test
//    chose), its two side lines, and the incident face they clip: what is left of the
//    incident face between the side lines, behind the reference face, gives the points.
//  - Each contact point (the pair's depth is the book's collision info's, drawn by
//    the layer under this one).
//  - The totals each point ended the step with, as forces on the second shape (the
//    impulse over the step's dt): the normal push and the friction along the tangent.
// With the book's solver it draws nothing: that solver keeps no contacts.

#include <vector>

#include "core.h"
#include "page.h"

namespace engine {

// How long a force's arrow is: px per unit of force (mass x px/s^2). A box of mass 1
// resting on the floor under the demo's gravity of 20 px/s^2 gets 10 px in all.
inline constexpr double kPxPerForce = 0.5;

void drawContacts(browser::Canvas& canvas, const Core& core, std::vector<browser::LegendEntry>& legend);

}  // namespace engine
