#pragma once
// The grid broad phase (world.broad_phase "grid"): the spatial partitioning of the
// book's "Further Exploration", for worlds with many shapes.
//
// The book's broad phase tests the bounding circles of every pair, n (n - 1) / 2 tests
// a pass, although most pairs lie far apart. The grid lays square cells over the plane
// and notes in each cell the shapes whose box (centre +- bound radius) reaches into it.
// Only shapes that share a cell can touch, so each shape has a handful of candidates
// instead of n.
//
// Once per step, not once per pass. The relaxation makes 15 passes a step, and the
// shapes hardly move between them: a positional correction moves a shape by a part of
// an overlap. So the grid makes a list of candidate pairs (a "Verlet list", from
// molecular dynamics) with every box widened by a skin, and the passes walk that list.
// A pair left off the list had boxes more than two skins apart; while no shape has
// moved a skin from where it stood when the list was made, such a pair still cannot
// touch. The list outlives the step, too: the next step makes it again only when a
// shape has moved that far (or the shapes have changed).
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
//  3. The list is made again, before the pass tests one more pair, as soon as a shape
//     has moved a skin (outgrown), and a row's partners are in ascending order, so the
//     pass meets the pairs in the order testing every pair would.
//
// The cells are hashed into a table of chains (the "linked-cell" lists of molecular
// dynamics): each slot of the table holds the first entry of a chain, each entry a
// shape and the next entry. The table has a few slots for every entry, so that two
// cells seldom share one (when they do, they only add candidates), and it needs
// memory in proportion to the shapes however far apart they are. A shape whose box
// would cover more than a few cells per axis (a floor as wide as the canvas) is kept
// out of the cells: it is a candidate in every row, and its own row takes every later
// shape, each box-tested.

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "bounding_circles.h"

namespace engine {

class SpatialGrid {
public:
    // Lists, for every shape i, the shapes j > i whose widened boxes overlap its own,
    // and notes where every shape stands: at the start of a step, with a skin of a
    // fifth of a typical radius.
    void listPairs(const BoundingCircles& circles);
    // The list again in the middle of a step, because a shape has outgrown it: with
    // twice the skin it had, so that a step in which shapes move far (a thousand shapes
    // made at one point burst apart) makes its list a few times, not once per pair.
    void listPairsAgain(const BoundingCircles& circles);
    // Whether the list still holds every pair that may touch: the same number of
    // shapes, the same radii, none moved a skin.
    bool fits(const BoundingCircles& circles) const;
    // Shape `index` has moved a skin since the list was made, on one axis or the other.
    bool outgrown(std::size_t index, const BoundingCircles& circles) const {
        const Vec2 now = circles.center(index);
        const Vec2 then = listed_at_[index];
        return !(std::abs(now.x - then.x) < skin_ && std::abs(now.y - then.y) < skin_);
    }

    // Row i's partners are partner(k) for k from rowBegin(i) to rowEnd(i), ascending.
    std::size_t rowBegin(std::size_t i) const { return row_begin_[i]; }
    std::size_t rowEnd(std::size_t i) const { return row_begin_[i + 1]; }
    std::size_t partner(std::size_t k) const { return partners_[k]; }
    // The place in row i of its first partner after j.
    std::size_t positionAfter(std::size_t i, std::size_t j) const;

    // What the list was made from, for the overlay to draw: how many shapes, the side
    // of a cell, and per shape where it stood, half the width of its widened box, and
    // whether it was too large for the cells (then it is in none, and every shape's
    // candidate).
    std::size_t listedCount() const { return row_begin_.size() - 1; }
    double cellSize() const { return cell_size_; }
    Vec2 listedAt(std::size_t i) const { return listed_at_[i]; }
    double reach(std::size_t i) const { return reach_[i]; }
    bool isOversize(std::size_t i) const { return oversize_[i]; }

private:
    // The cells a box covers: columns x0..x1 and rows y0..y1.
    struct CellRange {
        std::int32_t x0, y0, x1, y1;
    };
    // One link of a chain: 4-byte numbers keep the table small enough for the cache.
    struct Entry {
        std::uint32_t shape;
        std::uint32_t next;
    };

    void makeList(const BoundingCircles& circles);
    double medianRadius(const BoundingCircles& circles);
    bool boxesOverlap(std::size_t i, std::size_t j, const BoundingCircles& circles) const;
    void fileInCells(const BoundingCircles& circles);
    void gatherRow(std::size_t i, const BoundingCircles& circles);
    CellRange cellsOf(std::size_t index, const BoundingCircles& circles) const;
    std::int32_t cellCoordinate(double position) const;
    std::uint32_t& chainOf(std::int32_t x, std::int32_t y);

    double median_radius_ = 1.0;
    double skin_ = 0.0;
    double cell_size_ = 1.0;
    std::vector<double> radii_;  // scratch for the median

    // Per shape, as the list was made: half the width of its widened box, whether it is
    // too large for the cells, where it stood, and its radius.
    std::vector<double> reach_;
    std::vector<bool> oversize_;
    std::vector<std::size_t> oversize_list_;  // ascending
    std::vector<Vec2> listed_at_;
    std::vector<double> listed_radius_;

    std::vector<std::uint32_t> chains_;  // 2^chain_bits_ slots: the first entry, or none
    int chain_bits_ = 0;
    std::vector<Entry> entries_;

    // The list itself, row after row ("compressed rows"): row i is
    // partners_[row_begin_[i] .. row_begin_[i + 1]).
    std::vector<std::size_t> row_begin_{0};
    std::vector<std::uint32_t> partners_;

    // While a row is gathered: a mark per shape, "already in the row" when it equals
    // the current round.
    std::vector<std::uint64_t> seen_in_round_;
    std::uint64_t round_ = 0;
};

}  // namespace engine
