#pragma once
// Islands and sleeping (not in the book: its "Further Exploration" names the engines
// that do it, Box2D first). A pile that came to rest would cost, step after step, as
// much as the storm that built it: every shape integrated, every pair tested, every
// contact solved, only to leave everything where it was. So shapes at rest are put to
// sleep, and a sleeping shape costs nothing until something wakes it.
//
// An island is a group of shapes joined by touching contacts. A static shape joins
// nothing: the floor under two separate piles does not make them one island, or one
// box falling on the far end of the floor would wake every pile on it. Islands sleep
// and wake whole, because a shape at rest is only at rest as long as what holds it up
// does not move: a box cannot sleep while the box under it still slides.
//
// The sleep rule (README.md derives the numbers, in px and s). A shape's sleep speed
//     s = (|dc| + |da| r) / dt + (correction off: max(0, d - slop) / dt)
// is what the shape really did in the step, correction and all: how far its centre
// went (dc) and its farthest point turned (da, at the extent r, the bounding radius).
// Its velocity would not do: under a pile's weight the book's passes leave a resting
// shape with a velocity into the pile, which every step's correction takes back out
// of its position, so that it stands still at 10 px/s. An overlap that the correction
// works on moves the shape, and so counts; with the correction off nothing would ever
// move it out, and the overlap past the slop (d, the deepest its contacts found) counts
// as the speed it would take to leave it within a step. A shape rests while s stays
// under the world's sleep_speed, it is held by a contact in this step or the last
// (under gravity, a shape that touches nothing is falling, however slowly it moves at
// the top of its arc), it has not drifted farther than sleep_speed * time_to_sleep / 10
// within the last time_to_sleep of its rest (a box that starts to slide or tip from
// rest is slow for a long while, but does not stay put), and the world moves at all.
// An island falls asleep when every shape in it has rested for time_to_sleep; its
// velocities are then set to 0, so that it wakes from rest.
//
// The wake rules: an awake shape that touches a sleeping one wakes its island (physics);
// a removed shape wakes its island, which holds every shape it touched; a key that changes a
// shape wakes it and its island; anything done to a static shape, and any change of the
// world's settings, wakes everything (core.h): which islands lean on a platform is
// exactly what the step no longer looks at.
//
// 5.9's kinematic bodies join no island, as static ones, and never sleep; a shape that
// touches one while it moves does not rest (a box on a moving platform never sleeps),
// and a kinematic body that stands still rests as a static one does.

#include <cstddef>
#include <cstdint>
#include <vector>

#include "rigid_shape.h"
#include "world_settings.h"

namespace engine {

class Islands {
public:
    // The physics reports, for each pair its step finds touching (every relaxation
    // pass, or the solver's one look), the pair and its depth. A sleeping shape touched
    // by an awake one wakes its island here, before anything resolves the pair.
    void startStep(ShapeList shapes);
    // Returns whether it woke an island.
    bool touching(ShapeList shapes, std::size_t i, std::size_t j, double depth);
    // 5.9: a joint holds the two (joints.h). Like a touch, it holds each of them and
    // makes them one island, and an awake body wakes a sleeping one it is joined to;
    // unlike a touch, it is there whether they move or not, so two sleeping bodies (or a
    // sleeping one and a static one) stay asleep. Returns whether it woke an island.
    bool joined(ShapeList shapes, std::size_t i, std::size_t j);

    // After the shapes' motion: the islands of the step's contacts, each awake shape's
    // rest timer, and the islands that have rested long enough fall asleep.
    void endStep(ShapeList shapes, const WorldSettings& world);

    // The shape at `index` and its island; a static shape wakes everything. Called for
    // a shape about to be removed too: what it held up, or lay on, wakes. Their rest
    // starts again, unless `timer` says it goes on (RigidShape::wake).
    void wakeIslandOf(ShapeList shapes, std::size_t index, RestTimer timer = RestTimer::starts_again);
    void wakeAll(ShapeList shapes);

    // The shapes that can move and are awake.
    static std::size_t awakeCount(ShapeList shapes);
    // How many times anything was woken so far: what was asleep and is no longer can
    // only have changed when this has (the solver's sleeping contacts, contact_solver.h).
    std::uint64_t wakeCount() const { return wake_count_; }

private:
    std::size_t root(std::size_t i);
    void wakeLabel(ShapeList shapes, std::uint64_t island, RestTimer timer);

    std::vector<Vec2> step_start_center_;  // each shape as the step found it
    std::vector<double> step_start_angle_;
    std::vector<std::size_t> parent_;          // union-find over the step's contacts
    std::vector<double> deepest_;              // px, each shape's deepest overlap this step
    std::vector<std::uint8_t> held_;           // 1: the shape touches something
    std::vector<std::uint8_t> carried_;        // 1: it touches a moving kinematic body (5.9)
    std::vector<double> island_rested_;        // s, per root: the shortest rest in the island
    std::vector<std::uint64_t> island_label_;  // per root: the island's name this step
    std::uint64_t next_label_ = 1;             // 0 is a new shape's, before its first step
    std::uint64_t wake_count_ = 0;
};

}  // namespace engine
