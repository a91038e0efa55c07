#include "spatial_grid.h"

#include <algorithm>
#include <bit>

namespace engine {

namespace {

// A cell one and a half times as wide as a typical moving shape: three times its bound
// radius. Its box then covers one or two cells per axis, about 2.8 cells in all. With
// smaller cells each shape is filed under more of them, and gathering its candidates
// walks more chains; with larger ones each cell holds more shapes that are not near
// each other. (Measured on spread shapes, 2 and 4 radii were both slower.)
constexpr double kCellPerMedianRadius = 3.0;
// ... and the cells grow with the skin, which widens every box on both sides.
constexpr double kCellPerSkin = 2.0;
// The skin, a fifth of a typical radius. A thicker one lists more pairs that the
// passes test in vain; a thinner one makes the list again more often. A shape falling
// at 300 px/s moves 5 px a step, more than any skin worth having, so a rain makes its
// list about once a step; a pile at rest keeps it for many. (Measured on the bench's
// rains: a tenth and a half of a radius were both slower.)
constexpr double kSkinPerMedianRadius = 0.2;
// A box wider than this many cells is not filed under its cells at all: it would be
// filed under more than 80 of them, and a row of it would walk as many chains.
constexpr double kOversizeCells = 8.0;
// How far each box is widened beyond the bounding circle and the skin, relative to the
// sizes of the numbers involved: rounding errors are near 1e-16 of them, so this margin
// covers them millions of times over (fact 1 in spatial_grid.h) and adds next to no
// candidates.
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

}  // namespace

void SpatialGrid::listPairs(const BoundingCircles& circles) {
    median_radius_ = medianRadius(circles);
    skin_ = kSkinPerMedianRadius * median_radius_;
    makeList(circles);
}

void SpatialGrid::listPairsAgain(const BoundingCircles& circles) {
    skin_ *= 2;
    makeList(circles);
}

void SpatialGrid::makeList(const BoundingCircles& circles) {
    const std::size_t count = circles.size();
    cell_size_ = kCellPerMedianRadius * median_radius_ + kCellPerSkin * skin_;

    reach_.resize(count);
    listed_at_.resize(count);
    listed_radius_.resize(count);
    oversize_.assign(count, false);
    oversize_list_.clear();
    for (std::size_t i = 0; i < count; ++i) {
        const Vec2 c = circles.center(i);
        const double radius = circles.radius(i);
        listed_at_[i] = c;
        listed_radius_[i] = radius;
        // (The margin grows with the coordinates, so a shape very far out counts as
        // oversize too, rather than being filed under millions of cells.)
        reach_[i] = radius + skin_ + kRoundingMargin * (radius + skin_ + std::abs(c.x) + std::abs(c.y));
        if (2 * reach_[i] > kOversizeCells * cell_size_) {
            oversize_[i] = true;
            oversize_list_.push_back(i);
        }
    }
    fileInCells(circles);

    // Marks left from earlier rounds are all below the rounds to come.
    seen_in_round_.resize(count, 0);
    row_begin_.assign(1, 0);
    partners_.clear();
    for (std::size_t i = 0; i < count; ++i) {
        gatherRow(i, circles);
        row_begin_.push_back(partners_.size());
    }
}

bool SpatialGrid::fits(const BoundingCircles& circles) const {
    const std::size_t count = circles.size();
    if (count != listed_at_.size()) return false;
    for (std::size_t i = 0; i < count; ++i) {
        if (circles.radius(i) != listed_radius_[i] || outgrown(i, circles)) return false;
    }
    return true;
}

std::size_t SpatialGrid::positionAfter(std::size_t i, std::size_t j) const {
    const auto row = partners_.begin();
    return static_cast<std::size_t>(std::upper_bound(row + static_cast<std::ptrdiff_t>(rowBegin(i)),
                                                     row + static_cast<std::ptrdiff_t>(rowEnd(i)), j) -
                                    row);
}

// The cell size and the skin follow the median bound radius of the moving shapes. The
// median rather than the mean, so that one huge platform does not make every cell
// huge. Static shapes are left out when there are moving ones: a pair of static shapes
// is never resolved, so it is the moving shapes' neighbourhoods that matter.
double SpatialGrid::medianRadius(const BoundingCircles& circles) {
    radii_.clear();
    for (std::size_t i = 0; i < circles.size(); ++i) {
        if (!circles.isStatic(i)) radii_.push_back(circles.radius(i));
    }
    if (radii_.empty()) {
        for (std::size_t i = 0; i < circles.size(); ++i) radii_.push_back(circles.radius(i));
    }
    if (radii_.empty()) return 1.0;  // no shapes: any size will do
    const auto middle = radii_.begin() + static_cast<std::ptrdiff_t>(radii_.size() / 2);
    std::nth_element(radii_.begin(), middle, radii_.end());
    return *middle;
}

bool SpatialGrid::boxesOverlap(std::size_t i, std::size_t j, const BoundingCircles& circles) const {
    const Vec2 a = circles.center(i);
    const Vec2 b = circles.center(j);
    const double reach = reach_[i] + reach_[j];
    return std::abs(a.x - b.x) <= reach && std::abs(a.y - b.y) <= reach;
}

void SpatialGrid::fileInCells(const BoundingCircles& circles) {
    const std::size_t count = circles.size();
    std::size_t filed = 0;
    for (std::size_t i = 0; i < count; ++i) {
        if (oversize_[i]) continue;
        const CellRange range = cellsOf(i, circles);
        filed += static_cast<std::size_t>(range.x1 - range.x0 + 1) * static_cast<std::size_t>(range.y1 - range.y0 + 1);
    }
    chain_bits_ = std::max(kFewestChainBits, static_cast<int>(std::bit_width(kSlotsPerEntry * filed)));
    chains_.assign(std::size_t{1} << chain_bits_, kNoEntry);
    entries_.clear();
    for (std::size_t i = 0; i < count; ++i) {
        if (oversize_[i]) continue;
        const CellRange range = cellsOf(i, circles);
        for (std::int32_t x = range.x0; x <= range.x1; ++x) {
            for (std::int32_t y = range.y0; y <= range.y1; ++y) {
                std::uint32_t& first = chainOf(x, y);
                entries_.push_back({static_cast<std::uint32_t>(i), first});
                first = static_cast<std::uint32_t>(entries_.size() - 1);
            }
        }
    }
}

// Row i: the later shapes that share a cell with shape i, and the later oversize ones
// (every later shape, when shape i is oversize itself), each once, those whose widened
// boxes overlap, in ascending order.
void SpatialGrid::gatherRow(std::size_t i, const BoundingCircles& circles) {
    const std::size_t row_start = partners_.size();
    const std::size_t count = circles.size();
    if (oversize_[i]) {
        for (std::size_t j = i + 1; j < count; ++j) {
            if (boxesOverlap(i, j, circles)) partners_.push_back(static_cast<std::uint32_t>(j));
        }
        return;
    }
    // A shape covering several cells, or met again in a chain that two cells share, is
    // taken once.
    ++round_;
    const CellRange range = cellsOf(i, circles);
    for (std::int32_t x = range.x0; x <= range.x1; ++x) {
        for (std::int32_t y = range.y0; y <= range.y1; ++y) {
            for (std::uint32_t e = chainOf(x, y); e != kNoEntry; e = entries_[e].next) {
                const std::size_t j = entries_[e].shape;
                if (j <= i || seen_in_round_[j] == round_) continue;
                seen_in_round_[j] = round_;
                if (boxesOverlap(i, j, circles)) partners_.push_back(static_cast<std::uint32_t>(j));
            }
        }
    }
    for (auto later = std::upper_bound(oversize_list_.begin(), oversize_list_.end(), i); later != oversize_list_.end();
         ++later) {
        if (boxesOverlap(i, *later, circles)) partners_.push_back(static_cast<std::uint32_t>(*later));
    }
    // The pass must meet the pairs in the order testing every pair would.
    std::sort(partners_.begin() + static_cast<std::ptrdiff_t>(row_start), partners_.end());
}

SpatialGrid::CellRange SpatialGrid::cellsOf(std::size_t index, const BoundingCircles& circles) const {
    const Vec2 c = circles.center(index);
    const double reach = reach_[index];
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

}  // namespace engine
