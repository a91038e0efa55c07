#pragma once
// The grid broad phase (world.broad_phase "grid"): the spatial partitioning of the
// book's "Further Exploration", for worlds with many shapes.
//
// The book's broad phase tests the bounding circles of every pair, n (n - 1) / 2 tests
// a pass, although most pairs lie far apart. The grid lays square cells over the plane
// and notes in each cell the shapes whose bounding box (centre +- bound radius) reaches
// into it. A shape's candidates are the shapes that share a cell with it; only those
// are tested, so spread-out shapes have a handful of candidates each instead of n.
//
// It is exact: it finds the very pairs that testing every pair finds, so a world runs
// bit for bit the same with either broad phase. That rests on three facts.
//  1. Two bounding circles that overlap have overlapping boxes, and on each axis the
//     ranges of cells of two overlapping intervals overlap, so the two shapes share a
//     cell. The bounding-circle test works in rounded arithmetic, and may pass pairs
//     that are apart by a few units in the last place; each box is widened by a margin
//     a million times larger than such errors, which only adds candidates. Rounding
//     and clamping the cell coordinates never swap the order of two numbers, so
//     intervals that overlap still overlap as cell ranges.
//  2. Every candidate still goes through the bounding-circle test, so an extra one
//     changes nothing; only a missing one would.
//  3. The relaxation pass resolves each pair as soon as it finds it, so shapes move
//     during the pass. The grid follows: after every resolved pair (moved()) both
//     shapes' cells are brought up to date at once (usually they have not changed). While the pass
//     works on shape i's row, pairs (i, j > i) in order, only shape i and the j just
//     resolved move; the shapes still ahead in the row stay put. So the row's
//     candidates, gathered when it starts, stay right unless shape i's own cells
//     change, and then they are gathered again for the rest of the row.
//
// The cells are hashed into a table of chains (the "linked-cell" lists of molecular
// dynamics): each slot of the table holds the first entry of a chain, each entry a
// shape and the next entry. The table has a few slots for every entry, so that two
// cells seldom share one (when they do, they only add candidates), and it needs
// memory in proportion to the shapes however far apart they are. A shape whose box
// would cover more than a few cells per axis (a floor as wide as the canvas) is kept
// out of the cells: it is a candidate in every row, and its own row takes every later
// shape.

#include <cstddef>
#include <cstdint>
#include <vector>

#include "broad_phase.h"
#include "rigid_shape.h"

namespace engine {

class SpatialGrid final : public BroadPhase {
public:
    // Pair (i, j) was resolved: both shapes are filed anew, and when shape i now covers
    // other cells, the rest of row i (the candidates after j) is gathered again.
    void moved(std::size_t i, std::size_t j) override;

private:
    // Once per step: sorts every shape into the cells its box covers, the cells three
    // times as wide as the median bound radius of the moving shapes.
    void prepare(ShapeList shapes) override;
    // Row i walks the list candidates(i, i) gathers.
    std::size_t firstCandidate(std::size_t i) override;
    std::size_t nextCandidate(std::size_t i, std::size_t j) override;
    bool boundsOverlap(const RigidShape& a, const RigidShape& b) const override { return a.boundTest(b); }

    // The shapes with an index above `after` that may touch shape `index`: those that
    // share a cell with it and the oversize ones (all of them above `after`, when shape
    // `index` is oversize itself), in ascending order, each once.
    void gatherCandidates(std::size_t index, std::size_t after);
    // Moves shape `index` to the cells its box covers now. True when they changed.
    bool update(std::size_t index);

    // The cells a box covers: columns x0..x1 and rows y0..y1.
    struct CellRange {
        std::int32_t x0, y0, x1, y1;
        friend bool operator==(const CellRange&, const CellRange&) = default;
    };
    // One link of a chain: 4-byte numbers keep the table small enough for the cache.
    struct Entry {
        std::uint32_t shape;
        std::uint32_t next;
    };

    double chooseCellSize(ShapeList shapes);
    CellRange cellsOf(const RigidShape& shape) const;
    std::int32_t cellCoordinate(double position) const;
    std::uint32_t& chainOf(std::int32_t x, std::int32_t y);
    void insert(std::size_t index, const CellRange& cells);
    void erase(std::size_t index, const CellRange& cells);

    ShapeList shapes_;
    double cell_size_ = 1.0;
    std::vector<double> radii_;  // scratch for the median

    std::vector<std::uint32_t> chains_;  // 2^chain_bits_ slots: the first entry, or none
    int chain_bits_ = 0;
    std::vector<Entry> entries_;
    std::uint32_t free_entries_ = 0;  // a chain of the entries taken out, for reuse

    std::vector<CellRange> cells_;  // per shape: the cells it is filed under
    std::vector<bool> oversize_;    // per shape
    std::vector<std::size_t> oversize_list_;  // ascending

    // The row being walked: its candidates, the next one to hand out, and a mark per
    // shape, "already on the list" when it equals the current round.
    std::vector<std::size_t> row_;
    std::size_t next_in_row_ = 0;
    std::vector<std::uint64_t> seen_in_round_;
    std::uint64_t round_ = 0;
};

}  // namespace engine
