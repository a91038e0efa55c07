#pragma once
// The physics component (the book's EngineCore/Physics.js). Once per fixed step the
// core hands it the world's shapes, and it finds the pairs that collide.
//
// Testing every pair is O(n^2): n shapes make n (n - 1) / 2 pairs. This project does
// only the cheap first half of collision detection, the broad phase: two shapes are
// reported when their bounding circles overlap. That never misses a real collision,
// but it reports some shapes that do not touch at all (a turned rectangle next to a
// circle, Figure 3-5): the exact test that removes those comes in the next projects.
//
// The book draws the colliding shapes in green from inside the pass, over the picture
// the frame has just drawn. Here the pass only records what it found, and the core has
// it drawn over that picture once the frame's updates are done (core.cpp).

#include <cstddef>
#include <memory>
#include <span>
#include <vector>

#include "canvas.h"
#include "rigid_shape.h"

namespace engine {

// The world's shapes, as the core keeps them.
using ShapeList = std::span<const std::unique_ptr<RigidShape>>;

// Two shapes the pass found colliding, by their places in the list; first < second.
struct Collision {
    std::size_t first;
    std::size_t second;
};

class Physics {
public:
    // my_game puts the cursor and the four borders first. A border's bounding circle
    // is as wide as the canvas, so it would overlap every shape: the pass leaves those
    // five out.
    static constexpr std::size_t kFirstTestedObject = 5;

    // Tests every pair of shapes once and keeps the pairs that collide.
    void collision(ShapeList shapes);
    const std::vector<Collision>& collisions() const { return collisions_; }

    // Draws both shapes of every pair the latest pass found again, in green.
    void drawCollisions(browser::Canvas& context, ShapeList shapes) const;

private:
    std::vector<Collision> collisions_;
};

}  // namespace engine
