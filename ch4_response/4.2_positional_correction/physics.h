#pragma once
// The physics component (the book's EngineCore/Physics.js). Once per fixed step the
// core hands it the world's shapes, and it finds the pairs that collide and pushes
// them apart.
//
// Testing every pair is O(n^2): n shapes make n (n - 1) / 2 pairs. Each pair first goes
// through the cheap broad phase (do the bounding circles overlap?), and only pairs
// that pass it get the exact, costlier narrow phase (collisionTest), which also says
// how deep they overlap and in which direction.
//
// Positional correction (4.2): an overlap is undone by moving the two shapes apart
// along the collision normal, the lighter one further (a static one not at all). One
// pair's correction can push a shape into a third one, so the pass runs several times
// per step (relaxation), each pass correcting every pair it finds at once, and each
// only part of the overlap, so that shapes in a pile settle in small moves rather than
// jumping back and forth.
//
// The book draws the collision info from inside the pass, in every relaxation pass,
// over the picture the frame has just drawn. Here the pass only records what it found,
// and the core has what the last relaxation pass still found drawn over that picture
// once the frame's updates are done (core.cpp).

#include <cstddef>
#include <map>
#include <memory>
#include <optional>
#include <span>
#include <utility>
#include <vector>

#include "canvas.h"
#include "collision_info.h"
#include "rigid_shape.h"
#include "world_settings.h"

namespace engine {

// The world's shapes, as the core keeps them.
using ShapeList = std::span<const std::unique_ptr<RigidShape>>;

// Two shapes the pass found colliding, by their places in the list; first < second.
struct Collision {
    std::size_t first;
    std::size_t second;
    CollisionInfo info;  // its normal points from the first shape towards the second
};

// What one step's relaxation passes did to a pair, added up over the passes. The book's
// method needs none of it: the overlay shows it (overlay.h), and the physics keeps it
// only while the overlay asks (keepResponses).
struct PairResponse {
    Vec2 moved_first;   // how far positional correction moved the first shape
    Vec2 moved_second;  // and the second: the other way, in proportion to the inverse masses
};

// A pair by the places of its shapes in the list, first < second.
using PairKey = std::pair<std::size_t, std::size_t>;

// Broad phase, then narrow phase. The info's normal is turned, where needed, to point
// from `a` towards `b`, whichever shape's test worked it out.
std::optional<CollisionInfo> findCollision(const RigidShape& a, const RigidShape& b);

class Physics {
public:
    // world.relaxation_iterations passes, each testing every pair of shapes once and
    // resolving each pair that collides (a pair of two static shapes is tested too, as
    // in the book; only its resolution leaves it as it is).
    void collision(ShapeList shapes, const WorldSettings& world);
    const std::vector<Collision>& collisions() const { return collisions_; }

    // The overlay's record. While it is kept, each step adds up what its passes did to
    // every pair they resolved; while it is not, a step keeps no record at all and does
    // no bookkeeping for it. The core keeps it while the overlay is on (core.cpp).
    void keepResponses(bool keep);
    // What the last step's passes did to every pair any of them resolved; empty while
    // the record is not kept.
    const std::map<PairKey, PairResponse>& responses() const { return responses_; }

    // Draws the collision info of every pair the last pass found: an orange line
    // from start to end.
    void drawCollisions(browser::Canvas& context) const;

private:
    void relaxationPass(ShapeList shapes, const WorldSettings& world);
    // The overlay's record of `pair`, or nullptr while it keeps none.
    PairResponse* responseOf(PairKey pair);

    std::vector<Collision> collisions_;
    bool keep_responses_ = false;
    std::map<PairKey, PairResponse> responses_;
};

}  // namespace engine
