#pragma once
// The physics component (the book's EngineCore/Physics.js). Once per fixed step the
// core hands it the world's shapes, and it finds the pairs that collide, pushes them
// apart and changes their velocities.
//
// Testing every pair is O(n^2): n shapes make n (n - 1) / 2 pairs. Each pair first goes
// through the cheap broad phase (do the bounding circles overlap?), and only pairs
// that pass it get the exact, costlier narrow phase (collisionTest), which also says
// how deep they overlap and in which direction. Which pairs the pass looks at, and
// which of them reach the narrow phase, the world's broad phase decides
// (broad_phase.h): the book's bounding circles, or a grid that skips far-apart pairs.
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
// 5.4 adds a second way to resolve the contacts (world.solver): the sequential
// impulse solver of contact_solver.h, in place of the relaxation passes. 5.5 lets
// resting shapes sleep (islands.h): a pair of two sleeping or static shapes is not
// even tested, and every touching pair found is reported to the islands, which wake a
// sleeping shape that an awake one reaches.
//
// From 4.3 on the book's pass no longer draws the collision info. Ours still records
// what the last relaxation pass found, for the tests to read.

#include <map>
#include <utility>
#include <vector>

#include "broad_phase.h"
#include "contact_events.h"
#include "contact_solver.h"
#include "islands.h"
#include "joints.h"
#include "narrow_phase.h"
#include "rigid_shape.h"
#include "world_settings.h"

namespace engine {

// What one step's relaxation passes did to a pair, added up over the passes. The book's
// method needs none of it: the overlay shows it (overlay.h), and the physics keeps it
// only while the overlay asks (keepResponses).
struct PairResponse {
    Vec2 moved_first;      // how far positional correction moved the first shape
    Vec2 moved_second;     // and the second: the other way, in proportion to the inverse masses
    Vec2 normal_impulse;   // jN n: the second shape got it, the first the same turned round
    Vec2 tangent_impulse;  // jT t, friction's, given the same way
    Vec2 contact;          // where the impulses act (the last pass's contact point)
    Vec2 arm_first;        // the lever arms to it from the centres, in the last pass
    Vec2 arm_second;
    double spin_first = 0.0;  // how much the impulses changed each angular velocity, rad/s
    double spin_second = 0.0;
};

// A pair by the places of its shapes in the list, first < second.
using PairKey = std::pair<std::size_t, std::size_t>;

class Physics {
public:
    // world.relaxation_iterations passes, each resolving every pair of shapes that
    // collides, exactly as the book's passes do; but a pair whose answer is already
    // known is not tested again (broad_phase.h), and a pass that changed nothing is the
    // step's last (physics.cpp). With the sequential impulse solver: one look at every
    // pair, then the solver (contact_solver.h).
    // 5.9: the sequential impulses also solve the mouse's pull, `mouse`, in their
    // iterations (the book's passes leave it to the core, which pulls before them).
    void collision(ShapeList shapes, const WorldSettings& world, MouseJoint* mouse = nullptr);
    const std::vector<Collision>& collisions() const { return collisions_; }

    // The overlay's record. While it is kept, each step adds up what its passes did to
    // every pair they resolved; while it is not, a step keeps no record at all and does
    // no bookkeeping for it. The core keeps it while the overlay is on (core.cpp).
    void keepResponses(bool keep);
    // What the last step's passes did to every pair any of them resolved; empty while
    // the record is not kept.
    const std::map<PairKey, PairResponse>& responses() const { return responses_; }
    // For the core, when it takes shapes out of the list: the record's places no
    // longer name the shapes the step worked on.
    void forgetResponses() { responses_.clear(); }
    // The pairs the broad phase handed out over the last collision() call.
    const PairStatistics& pairStatistics() const { return broad_phase_.statistics(); }
    const BroadPhase& broadPhase() const { return broad_phase_; }
    const ContactSolver& contactSolver() const { return contact_solver_; }
    Islands& islands() { return islands_; }
    // 5.7's collision events: each pair the step finds touching is reported to them, in
    // either solver, before anything resolves it (contact_events.h).
    ContactEvents& events() { return events_; }
    const ContactEvents& events() const { return events_; }
    // 5.9's joints (joints.h), solved by the sequential impulse solver. The book's passes
    // do not solve them: a scene with joints must choose that solver (scene_io.cpp).
    Joints& joints() { return joints_; }
    const Joints& joints() const { return joints_; }

private:
    // The overlay's record of `pair`, or nullptr while it keeps none.
    PairResponse* responseOf(PairKey pair);

    std::vector<Collision> collisions_;
    bool keep_responses_ = false;
    std::map<PairKey, PairResponse> responses_;
    BroadPhase broad_phase_;
    ContactSolver contact_solver_;
    Islands islands_;
    ContactEvents events_;
    Joints joints_;
};

}  // namespace engine
