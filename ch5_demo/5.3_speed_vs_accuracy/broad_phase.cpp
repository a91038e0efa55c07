#include "broad_phase.h"

#include "spatial_grid.h"

namespace engine {

namespace {

// The book's broad phase: every later shape is a candidate, and two shapes may touch
// when their bounding circles overlap.
class BoundingCircles : public BroadPhase {
public:
    void moved(std::size_t, std::size_t) override {}

private:
    void prepare(ShapeList) override {}
    std::size_t firstCandidate(std::size_t i) override { return i + 1; }
    std::size_t nextCandidate(std::size_t, std::size_t j) override { return j + 1; }
    bool boundsOverlap(const RigidShape& a, const RigidShape& b) const override { return a.boundTest(b); }
};

// No broad phase at all: every pair goes to the narrow phase, which is exact anyway.
// What the bounding circles save is what this costs.
class AllPairs final : public BoundingCircles {
    bool boundsOverlap(const RigidShape&, const RigidShape&) const override { return true; }
};

}  // namespace

std::unique_ptr<BroadPhase> makeBroadPhase(BroadPhaseKind kind) {
    switch (kind) {
        case BroadPhaseKind::all_pairs: return std::make_unique<AllPairs>();
        case BroadPhaseKind::grid: return std::make_unique<SpatialGrid>();
        case BroadPhaseKind::bounding_circle: break;
    }
    return std::make_unique<BoundingCircles>();
}

}  // namespace engine
