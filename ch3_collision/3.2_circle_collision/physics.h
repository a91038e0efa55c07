#pragma once
// The physics component (the book's EngineCore/Physics.js). Once per fixed step the
// core hands it the world's shapes, and it finds the pairs that collide.
//
// Testing every pair is O(n^2): n shapes make n (n - 1) / 2 pairs. Each pair first goes
// through the cheap broad phase (do the bounding circles overlap?), and only pairs
// that pass it get the exact, costlier narrow phase (collisionTest), which also says
// how deep they overlap and in which direction.
//
// The book draws the collision info from inside the pass, over the picture the frame
// has just drawn. Here the pass only records what it found, and the core has it drawn
// over that picture once the frame's updates are done (core.cpp).

#include <cstddef>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "canvas.h"
#include "collision_info.h"
#include "rigid_shape.h"

namespace engine {

// The world's shapes, as the core keeps them.
using ShapeList = std::span<const std::unique_ptr<RigidShape>>;

// Two shapes the pass found colliding, by their places in the list; first < second.
struct Collision {
    std::size_t first;
    std::size_t second;
    CollisionInfo info;  // its normal points from the first shape towards the second
};

// Broad phase, then narrow phase. The info's normal is turned, where needed, to point
// from `a` towards `b`, whichever shape's test worked it out.
std::optional<CollisionInfo> findCollision(const RigidShape& a, const RigidShape& b);

class Physics {
public:
    // Tests every pair of shapes once and keeps the pairs that collide.
    void collision(ShapeList shapes);
    const std::vector<Collision>& collisions() const { return collisions_; }

    // Draws the collision info of every pair the latest pass found: an orange line
    // from start to end.
    void drawCollisions(browser::Canvas& context) const;

private:
    std::vector<Collision> collisions_;
};

}  // namespace engine
