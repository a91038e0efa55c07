#include "kinematic_drawing.h"

#include <numbers>

#include "overlay_draw.h"

namespace engine {

void drawKinematicMotion(browser::Canvas& context, const RigidShape& shape) {
    namespace draw = browser::overlay;
    const Vec2 center = shape.center();
    draw::ring(context, center, kKinematicCenterDot, kKinematicColor);
    draw::arrow(context, center, center + shape.velocity() * kKinematicMotionShown, kKinematicColor);
    // From the top of the ring (-pi/2 on the canvas, y down), as the overlay's spins start.
    draw::turn_arrow(context, center, shape.boundRadius() * kKinematicTurnRadius, -std::numbers::pi / 2,
                     shape.angularVelocity() * kKinematicMotionShown, kKinematicColor);
}

}  // namespace engine
