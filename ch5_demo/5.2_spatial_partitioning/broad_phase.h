#pragma once
// The broad phase as a choice (the book's "Further Exploration": spatial partitioning).
//
// The book's relaxation pass walks every pair (i, j > i) and asks the bounding circles
// first; n shapes make n (n - 1) / 2 pairs a pass, although most lie far apart. A broad
// phase hands the pass, for each row i, the partners j worth a look, in ascending order,
// and says which of them may touch: the pass stays the book's double loop, only the
// inner loop's "next j" and its first test come from here.
//   bounding_circle  the book: every j > i, then the bounding-circle test
//   all_pairs        every j > i, no bounding-circle test: every pair to the narrow phase
//   grid             only the j that share a cell of a grid with shape i
//                    (spatial_grid.h), then the bounding-circle test
// All three meet the colliding pairs in the same order, so the world moves bit for bit
// the same; only the time differs (all_pairs may part from the others on a pair that
// the narrow test finds touching, to the last digit, where the bounding circles are a
// last digit apart: corners meeting a circle or another corner exactly on a diagonal).

#include <cstddef>
#include <memory>
#include <span>

#include "rigid_shape.h"
#include "world_settings.h"

namespace engine {

// The world's shapes, as the core keeps them.
using ShapeList = std::span<const std::unique_ptr<RigidShape>>;

// What a broad phase did over one step, every relaxation pass counted: the pairs it
// handed to the pass (candidates) and those of them that went on to the narrow phase.
// The bench reads it; the physics never does.
struct PairStatistics {
    long candidates = 0;
    long narrow_tests = 0;
};

class BroadPhase {
public:
    virtual ~BroadPhase() = default;

    // Before a step's passes: the shapes its rows walk. They stay in the list, unchanged
    // in number and order, until the step ends.
    void startStep(ShapeList shapes) {
        statistics_ = {};
        end_of_row_ = shapes.size();
        prepare(shapes);
    }
    // Row i: its first candidate j > i, then the one after j; shapes.size() ends the row.
    std::size_t first(std::size_t i) { return counted(firstCandidate(i)); }
    std::size_t next(std::size_t i, std::size_t j) { return counted(nextCandidate(i, j)); }
    // Whether the pair goes on to the narrow phase.
    bool mayTouch(const RigidShape& a, const RigidShape& b) {
        const bool may = boundsOverlap(a, b);
        if (may) ++statistics_.narrow_tests;
        return may;
    }
    // The pass resolved pair (i, j) of row i: both shapes may have moved.
    virtual void moved(std::size_t i, std::size_t j) = 0;

    const PairStatistics& statistics() const { return statistics_; }

private:
    virtual void prepare(ShapeList shapes) = 0;
    virtual std::size_t firstCandidate(std::size_t i) = 0;
    virtual std::size_t nextCandidate(std::size_t i, std::size_t j) = 0;
    virtual bool boundsOverlap(const RigidShape& a, const RigidShape& b) const = 0;

    std::size_t counted(std::size_t j) {
        if (j < end_of_row_) ++statistics_.candidates;
        return j;
    }

    std::size_t end_of_row_ = 0;
    PairStatistics statistics_;
};

// The broad phase the settings choose.
std::unique_ptr<BroadPhase> makeBroadPhase(BroadPhaseKind kind);

}  // namespace engine
