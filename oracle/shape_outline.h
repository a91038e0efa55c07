#pragma once
// An engine shape as the collision oracle (collision_oracle.h) sees it: worked out from
// its centre, size and angle only, so that overlaps are judged without the engine's own
// collision tests. Include it where one stage's headers are on the include path: it
// reads that stage's engine::Rectangle and engine::Circle, whichever stage it is.

#include "circle.h"
#include "collision_oracle.h"
#include "rectangle.h"

namespace oracle {

inline Shape outline(const engine::RigidShape& shape) {
    if (shape.type() == engine::ShapeType::Rectangle) {
        const auto& box = static_cast<const engine::Rectangle&>(shape);
        return Box{box.center(), box.width(), box.height(), box.angle()};
    }
    return Disc{shape.center(), static_cast<const engine::Circle&>(shape).radius()};
}

// > 0: the two shapes overlap by that much; < 0: they are apart.
inline double depth(const engine::RigidShape& a, const engine::RigidShape& b) { return depth(outline(a), outline(b)); }

}  // namespace oracle
