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
//  - nothing is allocated during a step once the arrays have grown to the world's size.

#include <cstddef>

#include "bounding_circles.h"
#include "rigid_shape.h"
#include "spatial_grid.h"
#include "world_settings.h"

namespace engine {

// What a broad phase did over one step, every relaxation pass counted: the pairs it
// handed to the pass (candidates) and those of them that went on to the narrow phase.
// The bench reads it; the physics never does.
struct PairStatistics {
    long candidates = 0;
    long narrow_tests = 0;
};

class BroadPhase {
public:
    explicit BroadPhase(BroadPhaseKind kind = BroadPhaseKind::bounding_circle) : kind_(kind) {}
    BroadPhaseKind kind() const { return kind_; }

    // Before a step's passes: the shapes its rows walk. They stay in the list, unchanged
    // in number and order, until the step ends.
    void startStep(ShapeList shapes);

    // One relaxation pass. resolvePair(i, j), for i < j, does the exact test and the
    // resolution, and says whether the pair collided (and so may have moved).
    template <class ResolvePair>
    void pass(ResolvePair&& resolvePair) {
        switch (kind_) {
            case BroadPhaseKind::bounding_circle: return everyPair<true>(resolvePair);
            case BroadPhaseKind::all_pairs: return everyPair<false>(resolvePair);
            case BroadPhaseKind::grid: return listedPairs(resolvePair);
        }
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
                    if (!circles_.overlap(i, j)) continue;
                }
                ++statistics_.narrow_tests;
                if (resolvePair(i, j)) movedPair(i, j);
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
                if (!circles_.overlap(i, j)) continue;
                ++statistics_.narrow_tests;
                if (!resolvePair(i, j)) continue;
                movedPair(i, j);
                if (grid_.outgrown(i, circles_) || grid_.outgrown(j, circles_)) {
                    grid_.listPairsAgain(circles_);
                    k = grid_.positionAfter(i, j);
                }
            }
        }
    }

    void movedPair(std::size_t i, std::size_t j) {
        circles_.refresh(i, *shapes_[i]);
        circles_.refresh(j, *shapes_[j]);
    }

    BroadPhaseKind kind_;
    ShapeList shapes_;
    BoundingCircles circles_;
    SpatialGrid grid_;
    PairStatistics statistics_;
};

}  // namespace engine
