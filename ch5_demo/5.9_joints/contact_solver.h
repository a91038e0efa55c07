#pragma once
// The sequential impulse solver (not in the book: its "Further Exploration" points to
// Box2D, and this is the method of Erin Catto's talks on it, in our own code). It takes
// the place of the book's relaxation passes when a scene says "solver":
// "sequential_impulse" (README.md has the whole story, with the equations).
//
// What it changes in the book's method, one fault each:
//  - The book applies each impulse once, to one point per pair, and forgets it. Here a
//    pair touches at up to two points (contact_manifold.h), and each point keeps the
//    *total* impulse it has applied over the step. Every iteration works out the
//    impulse that would make the point's velocity right, adds it to the total, and
//    clamps the total: along the normal never below 0 (a contact can push, never
//    pull), along the tangent within mu times the normal total (Coulomb's cone). Only
//    the change of the clamped total is applied. An iteration may so take back part of
//    what an earlier one gave, which a one-shot impulse never can: that is what lets
//    the impulses of a pile agree with each other, whatever the order they are met in.
//  - The book forgets every contact at the end of a pass. Here a contact point that is
//    found again in the next step (same pair, same key) starts from its last totals
//    (warm starting): a resting pile needs the same impulses step after step, so the
//    iterations start at the answer instead of at 0.
//  - The book makes every contact bounce by e. Here a contact meeting slower than the
//    restitution threshold does not bounce: the little approach gravity gives a resting
//    shape in each step is not bounced back, and piles come to rest.
//  - The book removes overlap by moving shapes in relaxation passes, whatever their
//    masses say about how hard the contact pushes. Here overlap is removed by impulses
//    too, through the same effective masses (position_method: split impulses, the
//    default; Baumgarte; or Baumgarte relaxed), and only the part past a small slop,
//    so that resting contacts stay touching and are found again in the next step.

#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include "broad_phase.h"
#include "contact_events.h"
#include "collision_info.h"
#include "contact_manifold.h"
#include "islands.h"
#include "joints.h"
#include "narrow_phase.h"
#include "rigid_shape.h"
#include "world_settings.h"

namespace engine {

// A velocity, straight and turning: the real one of a shape, or its pseudo velocity
// (split impulses, below).
struct Motion {
    Vec2 linear;
    double angular = 0.0;
};

// The arms r of a contact point crossed with a direction d, r x d, for each shape:
// how hard an impulse along d at the point turns the shape, and, the other way round,
// how fast the shape's turning w moves the point along d ((w x r) . d = w (r x d)).
struct Turns {
    double a = 0.0;
    double b = 0.0;
};

// A shape as the solver sees it over a step: its velocities, worked on in place and
// written back at the end, and how it answers an impulse.
class MouseJoint;  // mouse_joint.h

struct SolverBody {
    Motion velocity;
    Motion pseudo;  // split impulses' pseudo velocity: moves the shape once, then dropped
    double inv_mass;
    double inv_inertia;  // 0 when the world turns rotation off
};

class ContactSolver {
public:
    // One step: finds every pair that overlaps (the broad phase, then the book's narrow
    // phase), recognises the contact points of the last step, and changes the shapes'
    // velocities (and, with split impulses, their positions) so that no contact point
    // approaches, none pulls, and friction stays within its cone. Each colliding pair's
    // narrow-phase answer goes to `found`, in the order met.
    // Every touching pair is reported to `islands`, which wakes a sleeping shape that an
    // awake one reaches, and to `events` (5.7's contact_events.h); a pair of two
    // sleeping or static shapes is not tested. 5.9's joints (joints.h) are solved in
    // the same iterations, each before the contacts, and a pair a joint keeps apart is
    // not tested either; so is the mouse's pull, `mouse` (mouse_joint.h), after them.
    void step(ShapeList shapes, BroadPhase& broad_phase, Islands& islands, ContactEvents& events, Joints& joints,
              const WorldSettings& world, std::vector<Collision>& found, MouseJoint* mouse = nullptr);

    // How many contact points the last step solved, and how many of them were found
    // again from the step before (and so warm started, when that is on).
    std::size_t pointCount() const;
    std::size_t persistedPointCount() const { return persisted_; }

    // What the solver keeps about one contact point over a step.
    struct Point {
        ContactPoint contact;
        Turns normal_turns;        // the arms (from each centre to the point) x normal
        Turns tangent_turns;       // ... x tangent
        double normal_mass = 0.0;  // 1 / (the normal speed one unit of impulse makes)
        double tangent_mass = 0.0;
        double bounce_speed = 0.0;    // the normal speed restitution asks for
        double removal_speed = 0.0;   // the normal speed that removes the overlap
        double target_speed = 0.0;    // the normal speed the iterations aim at now
        double normal_impulse = 0.0;  // totals over the step (kept for the next step)
        double tangent_impulse = 0.0;
        double split_impulse = 0.0;
    };
    struct Contact {
        std::size_t a, b;   // places in the shape list, in this step
        BodyId id_a, id_b;  // who they are, to find the pair again next step
        Vec2 normal;        // from a towards b
        Vec2 tangent;
        double friction, restitution;
        UpToTwo<Point> points;
        // Two points are solved together (solvePair) when the coupling of their normal
        // impulses, k12 below, leaves the 2 x 2 system well conditioned.
        bool solve_as_pair = false;
        double k11 = 0.0, k12 = 0.0, k22 = 0.0;                    // the speeds unit impulses at 1, 2 make at 1, 2
        double inverse11 = 0.0, inverse12 = 0.0, inverse22 = 0.0;  // K^-1, when solved as a pair
    };
    // The contacts the last step solved, with the totals it ended with (the overlay
    // draws them).
    const std::vector<Contact>& contacts() const { return contacts_; }

private:
    void findContacts(ShapeList shapes, BroadPhase& broad_phase, Islands& islands, ContactEvents& events,
                      const Joints& joints, const WorldSettings& world, std::vector<Collision>& found);
    // The pass over the pairs; returns whether it woke an island.
    bool meetPairs(ShapeList shapes, BroadPhase& broad_phase, Islands& islands, ContactEvents& events,
                   const Joints& joints, const WorldSettings& world, std::vector<Collision>& found);
    // Sorts the last step's contacts, and the sleeping ones, into those the pass may meet
    // again (last_, indexed) and those of shapes that both rest (asleep_). `wakes`: the
    // islands' count of wakes, which says whether a sleeping contact can have woken.
    void indexLastContacts(ShapeList shapes, std::uint64_t wakes);
    void prepare(ShapeList shapes, const WorldSettings& world);
    void warmStart();
    void solveVelocities(int iterations, bool with_removal, Joints& joints);
    void relaxAndMove(ShapeList shapes, const WorldSettings& world, Joints& joints);
    void solvePair(Contact& contact);
    void solvePositions(ShapeList shapes, const WorldSettings& world);

    std::vector<SolverBody> bodies_;
    MouseJoint* mouse_ = nullptr;  // the step's mouse joint (5.9), or none
    std::vector<Contact> contacts_;
    // The last step's contacts, and an index of them by their pair of shapes, sorted so
    // that a pair is found by bisection. Shapes are named by their ids (rigid_shape.h):
    // not by their places, which shift when a shape leaves the list, nor by their
    // addresses, which a shape made after a removed one may take over. Either would hand
    // the new shape the impulses of a contact it never had.
    using PairKey = std::pair<BodyId, BodyId>;
    std::vector<Contact> last_;
    std::vector<std::pair<PairKey, std::size_t>> last_index_;
    // The contacts of sleeping islands, as they fell asleep. The pass no longer meets
    // their pairs, but Box2D's contacts sleep with their bodies, and so do these: when
    // the island wakes, its contacts start from the totals that held it at rest, not
    // from 0. A pile of ten woken with no totals would sag for a step under its own
    // weight, as the iterations built them up again from the top, and creep for a
    // second before it rested again.
    std::vector<Contact> asleep_;
    std::uint64_t asleep_checked_at_ = 0;  // the islands' wake count when last sorted
    std::size_t persisted_ = 0;
};

}  // namespace engine
