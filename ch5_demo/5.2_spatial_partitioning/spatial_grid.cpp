#include "spatial_grid.h"

#include <algorithm>
#include <bit>
#include <cmath>

namespace engine {

namespace {

// A cell one and a half times as wide as a typical moving shape: three times its bound
// radius. Its box then covers one or two cells per axis, about 2.8 cells in all. With
// smaller cells each shape is filed under more of them, and gathering its candidates
// walks more chains; with larger ones each cell holds more shapes that are not near
// each other. (Measured on spread shapes, 2 and 4 radii were both slower.)
constexpr double kCellPerMedianRadius = 3.0;
// A box wider than this many cells is not filed under its cells at all: it would be
// filed under more than 80 of them, and a row of it would walk as many chains.
constexpr double kOversizeCells = 8.0;
// How far each box is widened beyond the bounding circle, relative to the sizes of the
// numbers involved: rounding errors are near 1e-16 of them, so this margin covers them
// millions of times over (fact 1 in spatial_grid.h) and adds next to no candidates.
constexpr double kRoundingMargin = 1e-9;
// Cell coordinates are clamped to +-2^30: beyond any world worth simulating, but far
// from overflowing, so a huge coordinate (or an infinite one) still gives a cell.
constexpr double kFarthestCell = 1073741824.0;
// At least 2^4 slots in the table, and between two and four for every entry.
constexpr int kFewestChainBits = 4;
constexpr std::size_t kSlotsPerEntry = 2;
constexpr std::uint32_t kNoEntry = UINT32_MAX;
// Multiplicative hashing: a cell's coordinates times two large odd constants (from the
// golden ratio and from MurmurHash), of which the top bits choose the slot.
constexpr std::uint64_t kMixX = 0x9E3779B97F4A7C15ull;
constexpr std::uint64_t kMixY = 0xC2B2AE3D27D4EB4Full;

// Half the width of the shape's box: its bound radius and the margin.
double reachOf(const RigidShape& shape) {
    const double radius = shape.boundRadius();
    const Vec2 c = shape.center();
    return radius + kRoundingMargin * (radius + std::abs(c.x) + std::abs(c.y));
}

}  // namespace

void SpatialGrid::prepare(ShapeList shapes) {
    shapes_ = shapes;
    cell_size_ = chooseCellSize(shapes);

    const std::size_t count = shapes.size();
    cells_.resize(count);
    oversize_.assign(count, false);
    oversize_list_.clear();
    // Marks left from earlier rounds are all below the rounds to come.
    seen_in_round_.resize(count, 0);

    std::size_t filed = 0;
    for (std::size_t i = 0; i < count; ++i) {
        // (The margin grows with the coordinates, so a shape very far out counts as
        // oversize too, rather than being filed under millions of cells.)
        if (2 * reachOf(*shapes[i]) > kOversizeCells * cell_size_) {
            oversize_[i] = true;
            oversize_list_.push_back(i);
            continue;
        }
        const CellRange& range = cells_[i] = cellsOf(*shapes[i]);
        filed += static_cast<std::size_t>(range.x1 - range.x0 + 1) * static_cast<std::size_t>(range.y1 - range.y0 + 1);
    }

    chain_bits_ = std::max(kFewestChainBits, static_cast<int>(std::bit_width(kSlotsPerEntry * filed)));
    chains_.assign(std::size_t{1} << chain_bits_, kNoEntry);
    entries_.clear();
    free_entries_ = kNoEntry;
    for (std::size_t i = 0; i < count; ++i) {
        if (!oversize_[i]) insert(i, cells_[i]);
    }
}

// The median rather than the mean, so that one huge platform does not make every cell
// huge. Static shapes are left out when there are moving ones: a pair of static shapes
// is never resolved, so it is the moving shapes' neighbourhoods that matter.
double SpatialGrid::chooseCellSize(ShapeList shapes) {
    radii_.clear();
    for (const auto& shape : shapes) {
        if (!shape->isStatic()) radii_.push_back(shape->boundRadius());
    }
    if (radii_.empty()) {
        for (const auto& shape : shapes) radii_.push_back(shape->boundRadius());
    }
    if (radii_.empty()) return 1.0;
    const auto middle = radii_.begin() + static_cast<std::ptrdiff_t>(radii_.size() / 2);
    std::nth_element(radii_.begin(), middle, radii_.end());
    return kCellPerMedianRadius * *middle;
}

std::size_t SpatialGrid::firstCandidate(std::size_t i) {
    gatherCandidates(i, i);
    return nextCandidate(i, i);
}

std::size_t SpatialGrid::nextCandidate(std::size_t, std::size_t) {
    return next_in_row_ < row_.size() ? row_[next_in_row_++] : shapes_.size();
}

void SpatialGrid::moved(std::size_t i, std::size_t j) {
    update(j);
    if (update(i)) gatherCandidates(i, j);
}

void SpatialGrid::gatherCandidates(std::size_t index, std::size_t after) {
    row_.clear();
    next_in_row_ = 0;
    if (oversize_[index]) {
        for (std::size_t j = after + 1; j < shapes_.size(); ++j) row_.push_back(j);
        return;
    }
    // A shape covering several cells, or met again in a chain that two cells share, is
    // taken once.
    ++round_;
    const CellRange& range = cells_[index];
    for (std::int32_t x = range.x0; x <= range.x1; ++x) {
        for (std::int32_t y = range.y0; y <= range.y1; ++y) {
            for (std::uint32_t e = chainOf(x, y); e != kNoEntry; e = entries_[e].next) {
                const std::size_t j = entries_[e].shape;
                if (j <= after || seen_in_round_[j] == round_) continue;
                seen_in_round_[j] = round_;
                row_.push_back(j);
            }
        }
    }
    const auto first_oversize = std::upper_bound(oversize_list_.begin(), oversize_list_.end(), after);
    row_.insert(row_.end(), first_oversize, oversize_list_.end());
    // The pass must meet the pairs in the order testing every pair would.
    std::sort(row_.begin(), row_.end());
}

bool SpatialGrid::update(std::size_t index) {
    // Oversize shapes are everybody's candidates, wherever they are.
    if (oversize_[index]) return false;
    const CellRange now = cellsOf(*shapes_[index]);
    if (now == cells_[index]) return false;
    erase(index, cells_[index]);
    insert(index, now);
    cells_[index] = now;
    return true;
}

SpatialGrid::CellRange SpatialGrid::cellsOf(const RigidShape& shape) const {
    const Vec2 c = shape.center();
    const double reach = reachOf(shape);
    return {cellCoordinate(c.x - reach), cellCoordinate(c.y - reach), cellCoordinate(c.x + reach),
            cellCoordinate(c.y + reach)};
}

std::int32_t SpatialGrid::cellCoordinate(double position) const {
    const double cell = std::floor(position / cell_size_);
    if (std::isnan(cell)) return 0;
    return static_cast<std::int32_t>(std::clamp(cell, -kFarthestCell, kFarthestCell));
}

std::uint32_t& SpatialGrid::chainOf(std::int32_t x, std::int32_t y) {
    // Unsigned arithmetic wraps around instead of overflowing.
    const std::uint64_t hash = static_cast<std::uint64_t>(x) * kMixX + static_cast<std::uint64_t>(y) * kMixY;
    return chains_[hash >> (64 - chain_bits_)];
}

// A new entry goes first in its cell's chain; it reuses one taken out before, if any.
void SpatialGrid::insert(std::size_t index, const CellRange& cells) {
    for (std::int32_t x = cells.x0; x <= cells.x1; ++x) {
        for (std::int32_t y = cells.y0; y <= cells.y1; ++y) {
            std::uint32_t entry = free_entries_;
            if (entry != kNoEntry) {
                free_entries_ = entries_[entry].next;
            } else {
                entry = static_cast<std::uint32_t>(entries_.size());
                entries_.emplace_back();
            }
            std::uint32_t& first = chainOf(x, y);
            entries_[entry] = {static_cast<std::uint32_t>(index), first};
            first = entry;
        }
    }
}

// One entry per cell was made, so one entry per cell is unlinked from its chain (order
// in a chain does not matter) and kept for reuse.
void SpatialGrid::erase(std::size_t index, const CellRange& cells) {
    for (std::int32_t x = cells.x0; x <= cells.x1; ++x) {
        for (std::int32_t y = cells.y0; y <= cells.y1; ++y) {
            std::uint32_t* link = &chainOf(x, y);
            while (entries_[*link].shape != index) link = &entries_[*link].next;
            const std::uint32_t gone = *link;
            *link = entries_[gone].next;
            entries_[gone].next = free_entries_;
            free_entries_ = gone;
        }
    }
}

}  // namespace engine
