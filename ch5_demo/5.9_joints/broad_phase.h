#pragma once
// The broad phase as a choice (the book's "Further Exploration": spatial partitioning),
// and the book's relaxation pass made fast.
//
// The book's relaxation pass walks every pair (i, j > i) and asks the bounding circles
// first; n shapes make n (n - 1) / 2 pairs a pass, although most lie far apart. Here the
// broad phase runs the pass: it walks, row i by row i, the partners j worth a look in
// ascending order, tests their bounding circles, and hands each pair that may touch to
// the physics (resolvePair), which does the exact test and the resolution.
//   bounding_circle  the book: every j > i, then the bounding-circle test
//   all_pairs        every j > i, no bounding-circle test: every pair to the narrow phase
//   grid             only the pairs on a list the grid makes (spatial_grid.h), then the
//                    bounding-circle test
// All three meet the colliding pairs in the same order, so the world moves bit for bit
// the same; only the time differs (all_pairs may part from the others on a pair that
// the narrow test finds touching, to the last digit, where the bounding circles are a
// last digit apart: corners meeting a circle or another corner exactly on a diagonal).
//
// Why it is fast. A pass of 1000 shapes makes half a million bound tests: the book's
// RigidShape::boundTest is a call through a pointer into a shape somewhere on the heap,
// and a square root. Here:
//  - the centres and radii sit side by side in three arrays (BoundingCircles), so row i
//    walks memory in order and the processor can load ahead;
//  - the test is inline, and compares squares: no square root unless the two answers
//    could disagree (BoundingCircles::overlap);
//  - the pass is a template on the function that resolves a pair, so the compiler
//    writes one loop per broad phase with no call per pair;
//  - nothing is allocated during a step once the arrays have grown to the world's size;
//  - the exact test is skipped where its answer is already known (knownApart below).
//
// Exact skipping: what the book's loop computes again although nothing has changed.
// Within a step the passes walk the same pairs in the same order, and only the
// resolutions of the pass move shapes or change their velocities. So the broad phase
// notes, per shape, the moment of the step's loop at which a resolution last touched it:
// the "tick" of the pair (i, j) in pass p counts the pairs before it in the book's
// double loop, (p + 1) n^2 + i n + j, and every shape counts as touched at the tick of
// pass 0's start, n^2 (the motion of the last step moved it). The rule, for pass p >= 1:
//   if neither shape of (i, j) has been touched since the pair's tick in pass p - 1,
//   the pair is apart now.
// Proof. At its tick in pass p - 1 the book's loop met the pair (the broad phase is
// exact: it hands on every pair that can touch, spatial_grid.h). Had it collided then,
// it would have been resolved then, and the resolution touches both shapes at that very
// tick; so it was apart. The exact test reads nothing but the two shapes' positions,
// angles and sizes, and only a resolution that touches a shape changes them within a
// step; none has since. So the test would give the same answer: apart, nothing to do.
// (A pair of two static shapes is the exception that proves it: its resolution changes
// nothing, so it does not count as a touch, and the pair, colliding or not, is skipped:
// skipping it leaves the world as resolving it does.)
// The rule is asked of the pairs whose bound test passed. Asked first, it would save
// their bound tests too, but measured on rains of 400 and 1000 and on the gas, the two
// orders cost the same to within the noise, and this way the bench can count the exact
// tests it saves. all_pairs asks no rule: it is there to show what leaving nothing out
// costs. Ticks grow to (passes + 2) n^2, which 64 bits hold for the scene files' 1000
// passes of up to 2500 bodies many times over; a world too large for them skips nothing.

#include <cstddef>
#include <cstdint>
#include <vector>

#include "bounding_circles.h"
#include "rigid_shape.h"
#include "spatial_grid.h"
#include "world_settings.h"

namespace engine {

// What a broad phase did over one step, every relaxation pass counted: the pairs it
// looked at (candidates, each bound-tested but with all_pairs), the exact tests it had
// computed and those the skip rule saved, and the passes it ran. The bench reads it;
// the physics never does.
struct PairStatistics {
    long candidates = 0;
    long narrow_tests = 0;
    long skipped_tests = 0;
    long passes = 0;
    long slept_pairs = 0;  // passed over: a sleeping shape and a sleeping or static one
};

class BroadPhase {
public:
    explicit BroadPhase(BroadPhaseKind kind = BroadPhaseKind::bounding_circle) : kind_(kind) {}
    BroadPhaseKind kind() const { return kind_; }

    // Before a step's passes (at most `passes` of them): the shapes its rows walk. They
    // stay in the list, unchanged in number and order, until the step ends.
    void startStep(ShapeList shapes, int passes);
    // Notes which shapes sleep: a pair of a sleeping shape and another sleeping or
    // static one is passed over before its bound test, so that a pile asleep costs no
    // pair work (the pair's count is kept in statistics().slept_pairs). Done by
    // startStep, and again whenever a step wakes an island in the middle of a pass. A
    // pair of two static shapes takes 5.4's path: the physics refuses it.
    void noteResting();

    // One relaxation pass. resolvePair(i, j), for i < j, does the exact test and the
    // resolution, and says whether the resolution changed the pair (it collided, and
    // the two are not both static). Returns whether any pair changed.
    template <class ResolvePair>
    bool pass(ResolvePair&& resolvePair) {
        changed_ = false;
        switch (kind_) {
            case BroadPhaseKind::bounding_circle: everyPair<true>(resolvePair); break;
            case BroadPhaseKind::all_pairs: everyPair<false>(resolvePair); break;
            case BroadPhaseKind::grid: listedPairs(resolvePair); break;
        }
        ++statistics_.passes;
        pass_tick_ += square_;
        return changed_;
    }

    const PairStatistics& statistics() const { return statistics_; }
    // The grid's list, as the last step walked it (the overlay draws it).
    const SpatialGrid& grid() const { return grid_; }

private:
    // The book's double loop: every pair (i, j > i), in order.
    template <bool kTestBounds, class ResolvePair>
    void everyPair(ResolvePair& resolvePair) {
        const std::size_t count = circles_.size();
        for (std::size_t i = 0; i < count; ++i) {
            statistics_.candidates += static_cast<long>(count - i - 1);
            for (std::size_t j = i + 1; j < count; ++j) {
                if constexpr (kTestBounds) {
                    j = circles_.nextNear(i, j, count);
                    if (j == count) break;
                    if (sleepingPair(i, j)) continue;
                    if (!circles_.overlap(i, j)) continue;
                    if (knownApart(i, j)) {
                        ++statistics_.skipped_tests;
                        continue;
                    }
                }
                ++statistics_.narrow_tests;
                if (resolvePair(i, j)) touched(i, j);
            }
        }
    }

    // The grid's pairs: row i walks its partners on the list, in ascending order. When
    // a resolution moves a shape too far for the list (SpatialGrid::outgrown), the list
    // is made again from where the shapes are now, and row i goes on after j.
    template <class ResolvePair>
    void listedPairs(ResolvePair& resolvePair) {
        const std::size_t count = circles_.size();
        for (std::size_t i = 0; i < count; ++i) {
            for (std::size_t k = grid_.rowBegin(i); k < grid_.rowEnd(i);) {
                const std::size_t j = grid_.partner(k++);
                ++statistics_.candidates;
                if (sleepingPair(i, j)) continue;
                if (!circles_.overlap(i, j)) continue;
                if (knownApart(i, j)) {
                    ++statistics_.skipped_tests;
                    continue;
                }
                ++statistics_.narrow_tests;
                if (!resolvePair(i, j)) continue;
                touched(i, j);
                if (grid_.outgrown(i, circles_) || grid_.outgrown(j, circles_)) {
                    grid_.listPairsAgain(circles_);
                    k = grid_.positionAfter(i, j);
                }
            }
        }
    }

    enum Rest : std::uint8_t { kAwake = 0, kStatic = 1, kAsleep = 2 };
    bool sleepingPair(std::size_t i, std::size_t j) {
        const bool both_rest = resting_[i] != kAwake && resting_[j] != kAwake;
        const bool one_asleep = resting_[i] == kAsleep || resting_[j] == kAsleep;
        if (!both_rest || !one_asleep) return false;
        ++statistics_.slept_pairs;
        return true;
    }

    // The pair's tick in this pass (see the top of this file).
    std::uint64_t tick(std::size_t i, std::size_t j) const { return pass_tick_ + i * circles_.size() + j; }
    // The skip rule: neither shape touched since the pair's tick in the pass before. In
    // pass 0 that tick lies before the step's start, where every shape was touched.
    bool knownApart(std::size_t i, std::size_t j) const {
        const std::uint64_t then = tick(i, j) - square_;
        return skipping_ && touched_at_[i] < then && touched_at_[j] < then;
    }
    void touched(std::size_t i, std::size_t j) {
        circles_.refresh(i, *shapes_[i]);
        circles_.refresh(j, *shapes_[j]);
        touched_at_[i] = touched_at_[j] = tick(i, j);
        changed_ = true;
    }

    BroadPhaseKind kind_;
    ShapeList shapes_;
    std::vector<std::uint8_t> resting_;  // per shape, a Rest
    BoundingCircles circles_;
    SpatialGrid grid_;
    PairStatistics statistics_;

    // The skip rule's clock: square_ is n^2, the ticks of one pass.
    bool skipping_ = false;  // the step's ticks fit in 64 bits
    std::uint64_t square_ = 0;
    std::uint64_t pass_tick_ = 0;
    std::vector<std::uint64_t> touched_at_;
    bool changed_ = false;
};

}  // namespace engine
