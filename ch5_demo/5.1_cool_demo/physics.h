#pragma once
// The physics component (the book's EngineCore/Physics.js). Once per fixed step the
// core hands it the world's shapes, and it finds the pairs that collide, pushes them
// apart and changes their velocities.
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
// Collision impulses (4.3): each pair the pass resolves also has its velocities
// changed, by an impulse along the normal (the bounce) and one along the tangent
// (friction), so that shapes bounce, slow down and come to rest.
//
// Angular impulses (4.4): an impulse that does not act through a shape's centre also
// turns it, so the impulses act at the contact point, on the velocities of the two
// shapes there, and change their angular velocities too.
//
// The world's knobs (scene_file.h) trade speed against accuracy; their defaults are the
// book. broad_phase picks which pairs reach the narrow phase: "bounding_circle" (the
// book) tests every pair's bounding circles first; "all_pairs" skips that test and
// sends every pair to the narrow phase; "grid" (spatial_grid.h) tests only pairs
// that share a cell of a grid. All three find the same pairs, in the same order, so
// the world moves bit for bit the same; only the time differs. (all_pairs can part
// from the others where a narrow test finds two shapes touching, to the last digit,
// that the bounding circles put a last digit apart: corners meeting a circle or
// another corner exactly on the line of a diagonal.) friction_model picks the
// tangent impulse (the book's or Coulomb's), friction: false drops it, and rotation:
// false drops every angular term of the response.
//
// From 4.3 on the book's pass no longer draws the collision info. Ours still records
// what the last relaxation pass found, for the tests to read.

#include <cstddef>
#include <optional>
#include <vector>

#include "collision_info.h"
#include "rigid_shape.h"
#include "scene_file.h"
#include "spatial_grid.h"

namespace engine {

// The book's relaxation: 15 passes per step, each removing 80% of every overlap it
// finds, so an overlap left alone shrinks to 0.2^15 (3e-11) of its depth in one step.
inline constexpr int kRelaxationCount = 15;
inline constexpr double kPosCorrectionRate = 0.8;

// Two shapes the pass found colliding, by their places in the list; first < second.
struct Collision {
    std::size_t first;
    std::size_t second;
    CollisionInfo info;  // its normal points from the first shape towards the second
};

// The narrow phase. The info's normal is turned, where needed, to point from `a`
// towards `b`, whichever shape's test worked it out.
std::optional<CollisionInfo> narrowPhase(const RigidShape& a, const RigidShape& b);
// The book's broad phase, the bounding circles, then the narrow phase.
std::optional<CollisionInfo> findCollision(const RigidShape& a, const RigidShape& b);

class Physics {
public:
    // world.relaxation_iterations passes, each testing every pair of shapes once and
    // resolving each pair that collides (a pair of two static shapes is tested too, as
    // in the book; only its resolution leaves it as it is).
    void collision(ShapeList shapes, const browser::WorldSettings& world);
    const std::vector<Collision>& collisions() const { return collisions_; }

    // What the last collision() call (one step, or one sub-step) did, summed over its
    // passes: the pairs the broad phase handed on for a closer look (every pair,
    // except with the grid), and how many of them reached the narrow phase.
    long candidatePairs() const { return candidate_pairs_; }
    long narrowPhaseTests() const { return narrow_phase_tests_; }

private:
    void relaxationPass(ShapeList shapes, const browser::WorldSettings& world);
    void gridRow(ShapeList shapes, std::size_t i, const browser::WorldSettings& world);
    // Tests the pair and, when it collides, records and resolves it; true if it did.
    bool testAndResolve(ShapeList shapes, std::size_t i, std::size_t j, const browser::WorldSettings& world);

    std::vector<Collision> collisions_;
    SpatialGrid grid_;
    long candidate_pairs_ = 0;
    long narrow_phase_tests_ = 0;
};

}  // namespace engine
