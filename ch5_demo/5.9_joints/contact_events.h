#pragma once
// Collision events (not in the book: its "Further Exploration" names collision callbacks,
// OnCollisionEnter and OnCollisionExit, among the topics left to explore). Game logic
// wants to hear that two shapes began or stopped touching: to score a goal, count what
// lies in a zone, play a sound as hard as the hit. The physics knows it, pair by pair,
// in the middle of its step.
//
// Why buffered, and read after the step. A callback called from inside the step would
// hand the game a world half-way through its work: the book's relaxation passes have
// moved some shapes and not others, and the list of shapes is being walked. A game that
// removed a shape there, or added one, would pull the list from under the loop that
// called it. So the step only writes down what happened, and the game reads the list
// once the step is over, when the world stands still and any change is safe (as Box2D
// v3 does).
//
// Touching, once for both solvers: a pair begins to touch in the first step whose
// collision pass (any of the book's relaxation passes, or the sequential impulse
// solver's one look) finds its shapes overlapping. It goes on touching while one of
// the last kMissedSteps steps found it: the book's passes push a resting shape clear of
// what holds it up, its bounce lifts it a hair, and gravity brings it back a step or two
// later, so a box at rest on the floor is not found in every step (5.5's islands count
// a shape as held by a contact of this step or the last for the same reason). A pair
// that no pass tests, because both of its shapes rest (asleep, or static), goes on
// touching as it did when they fell asleep: sleep is not separation. It stops touching
// when kMissedSteps steps in a row do not find it, or at once when one of its shapes is
// removed, made static, or moved by a key.
//
// A pair is named by its shapes' ids (rigid_shape.h), smaller first: an id never
// changes and is never given twice, so a pair cannot be mistaken for another one when
// shapes leave the list. Its normal points from the first shape to the second.

#include <cstddef>
#include <deque>
#include <string_view>
#include <utility>
#include <vector>

#include "collision_info.h"
#include "rigid_shape.h"

namespace engine {

// A begin is also a hit when the pair's surfaces met faster than this along the normal
// (a pair with a sensor is never hit: nothing strikes a zone):
// a fall of 2.5 px under the book's gravity (v^2 = 2 g h), so that a shape settling on
// another, or a pile's jitter (under 5.5's sleep speed, 3 px/s), is no hit.
inline constexpr double kHitSpeed = 10.0;  // px/s

// How many steps in a row must miss a pair before it ends. A box of the book's woken
// from sleep hovered 0.008 px over the floor (tests/stages/s5_7_test.cpp): gravity from
// rest closes that in two steps (g dt^2 (1 + 2) = 0.017 px), found again in the third.
inline constexpr int kMissedSteps = 3;

// How long the overlay shows an event where it happened: half a second of the book's
// steps, long enough to see, short enough not to pile up.
inline constexpr long kShownSteps = 30;

// 5.9 adds `limit`: a joint's limit (a revolute's angle, a slider's translation, a
// rope's length) began to hold it, told once when it arrives, as a begin is, not in each
// step it stays there (joints.h, Joints::reportLimits).
enum class EventKind { begin, end, hit, limit };

// Who reads the events: each turns them on and off for itself, and they are kept while
// any one of them reads (the overlay going off must not silence the --events file).
enum class EventReader : unsigned { program = 1, game = 2, overlay = 4 };
std::string_view kindName(EventKind kind);

struct ContactEvent {
    long step = 0;  // the steps run when it happened (a key's between two steps: the one before)
    EventKind kind = EventKind::begin;
    BodyId id_a = 0;  // the smaller id
    BodyId id_b = 0;
    Vec2 point;          // the middle of the overlap (an end: where the pair last touched)
    Vec2 normal;         // from a to b
    double speed = 0.0;  // px/s, how fast the pair's surfaces met along the normal (hits only)
    // A limit (5.9): the pair is the joint's two bodies, the point b's anchor (the pin of
    // a revolute), the normal the way the limit pushes the larger id's body ((0, 0) for
    // an angle), the speed how fast the joint was closing on the limit at the step's
    // start: px/s for a slider or a rope, rad/s for an angle.
};

class ContactEvents {
public:
    // Events cost a little bookkeeping in every step; a world nobody listens to keeps
    // none (and touches nothing either way: the shapes move the same, to the bit).
    // `reader` starts or stops reading; when the last one stops, the record is dropped.
    void keep(EventReader reader, bool on);
    bool kept() const { return readers_ != 0; }

    // The step's outline, for the core: the key events since the last step go to the
    // front of the new step's list; the physics reports each pair it finds touching;
    // after the motion (and the removal of shapes that left the canvas), the pairs are
    // compared with the step before. `hit_speed` is the approach speed, px/s, above
    // which a begin is also a hit.
    void startStep(long step);
    void touching(const RigidShape& a, const RigidShape& b, const CollisionInfo& info);
    // The same for a pair with a sensor in it: told like any touch, but two sensors
    // never feel each other (zones do not trigger zones).
    void sensed(const RigidShape& a, const RigidShape& b, const CollisionInfo& info);
    // A fast shape's sweep (continuous.h) passed through a sensor within the step, at
    // `point`, moving along `direction`: the pair touched in this step though no look
    // at the step's end finds it.
    void crossed(const RigidShape& mover, const RigidShape& sensor, Vec2 point, Vec2 direction);
    void endStep(ShapeList shapes, double hit_speed);
    // 5.9: a joint's limit began to hold in this step (joints.h): the joint's bodies,
    // b's anchor, the way the limit pushes b, and the speed it closed at (above).
    void limitReached(BodyId a, BodyId b, Vec2 point, Vec2 normal, double speed);

    // A key took the shape out of its contacts (removed it, made it static, moved it):
    // each pair it touched ends now. If it still touches, the next step begins it anew.
    void shapeLeaves(BodyId id);

    // What happened in the last step, in order (with the keys' before it).
    const std::vector<ContactEvent>& events() const { return events_; }
    // What happened in the last kShownSteps steps, oldest first (the overlay's).
    const std::deque<ContactEvent>& recent() const { return recent_; }
    // The step the events were last told for.
    long step() const { return step_; }
    // How many pairs touch now.
    std::size_t touchingCount() const { return marks_.size(); }

private:
    using PairIds = std::pair<BodyId, BodyId>;
    // Where and how a report found a pair touching.
    struct Sighting {
        Vec2 point;
        Vec2 normal;
        bool sensor = false;  // one of the two is a sensor: it feels, it is not struck
    };
    // The list of pairs touching, sorted by ids, is kept in three arrays side by side
    // (marks_, touches_ and found_, below), entry k of each for the same pair, each
    // read by its own part of the step.
    // What every report looks up (touching() and report(), in the .cpp): the pair, and
    // whether a report of this step has found it. A small entry: the book's passes walk
    // these thousands of times a step.
    struct Mark {
        PairIds pair;
        bool found = false;
    };
    // What the step's end reads: where the pair touched in the last step that found it
    // (its end is told there), and how many steps in a row have not found it.
    struct Touch {
        Sighting seen;
        int missed = 0;
    };
    // A pair that was not touching, found in this step: it begins, if its shapes are
    // still there at the step's end.
    struct Begin {
        PairIds pair;
        Sighting seen;
        double speed = 0.0;  // px/s, how fast its surfaces met (worked out for a begin only)
    };
    ContactEvent eventOf(EventKind kind, PairIds pair, const Sighting& seen, double speed = 0.0) const;
    // A pair found touching: written down if this is the step's first report of it.
    void report(const RigidShape& a, const RigidShape& b, Vec2 point, Vec2 normal, bool sensor);
    void closeRun();

    unsigned readers_ = 0;  // EventReader bits
    // A reader who starts listening after steps have run hears of what changes from
    // then on: the pairs touching already are taken in, in the next step, without a
    // begin (the overlay turned on with t would otherwise see every resting pair begin).
    bool taking_in_ = false;
    long step_ = 0;
    // The pairs touching (above). Kept from step to step: the step's end writes the new
    // list into next_marks_ and next_touches_ and swaps them in, so the same memory
    // serves step after step.
    std::vector<Mark> marks_;
    std::vector<Touch> touches_;
    // The third: where this step's first report found each pair (where its Mark says
    // found). It becomes the pair's Touch only at the step's end, once the pair's shapes
    // are known to be still there: a pair whose shape leaves at the step's end (out of
    // bounds) ends where it touched in the step before.
    std::vector<Sighting> found_;
    // The step's new pairs, sorted by ids: begun_ from the runs of reports before, run_
    // from the current one.
    std::vector<Begin> begun_;
    std::vector<Begin> run_;
    // Where the current run of reports stands: the last pair report() took, and how far
    // the run has walked marks_ (to the first pair after its last report: a pass that
    // finds the pairs the pass before found finds each one next in line) and begun_.
    PairIds last_report_;
    std::size_t marks_walked_ = 0;
    std::size_t begun_walked_ = 0;
    std::vector<BodyId> ids_;  // the shapes' ids, in the list's order (shapeWithId's)
    std::vector<Mark> next_marks_;
    std::vector<Touch> next_touches_;
    std::vector<Begin> next_begun_;
    std::vector<ContactEvent> events_;
    std::vector<ContactEvent> pending_;  // the keys' since the last step
    // Oldest first, as they happened: a step drops the oldest from the front and adds
    // its own at the back, and no event in between is moved.
    std::deque<ContactEvent> recent_;
};

}  // namespace engine
