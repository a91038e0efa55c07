#pragma once
// Every shape's bounding circle (Figure 3-4), kept apart from the shapes, for the
// broad phase's loops.
//
// The book asks each shape object for its bounding-circle test; the objects lie
// wherever the heap put them, and each test is a call. The broad phase makes hundreds
// of thousands of these tests per step and needs only three numbers per shape, so here
// they sit side by side in three arrays (a "structure of arrays"): the loop over row i
// reads memory in order, and the test is a few arithmetic operations, inline.

#include <cmath>
#include <cstddef>
#include <vector>

#include "rigid_shape.h"

namespace engine {

class BoundingCircles {
public:
    // Every shape's centre and bound radius, as the shapes stand now.
    void assign(ShapeList shapes);
    // A shape has moved (its radius never changes: turning does not change it).
    void refresh(std::size_t index, const RigidShape& shape) {
        const Vec2 center = shape.center();
        x_[index] = center.x;
        y_[index] = center.y;
    }

    std::size_t size() const { return x_.size(); }
    Vec2 center(std::size_t index) const { return {x_[index], y_[index]}; }
    double radius(std::size_t index) const { return radius_[index]; }
    bool isStatic(std::size_t index) const { return is_static_[index] != 0; }

    // The book's test, distance <= r1 + r2 (RigidShape::boundTest), with the same answer
    // to the last bit. Both sides are >= 0, so it holds exactly when
    // distance^2 <= (r1 + r2)^2, and the square root can go. But the computer rounds:
    // d2 and reach * reach each carry a relative error of a few parts in 10^16, and the
    // book's square root one more. Where the two squares differ by more than a part in
    // 10^12, no rounding can turn the answer round. Within that band (the circles touch
    // to 12 digits), or for radii so small that their square loses digits (below
    // 10^-140 px), the book's own comparison decides.
    bool overlap(std::size_t i, std::size_t j) const {
        const double dx = x_[i] - x_[j];
        const double dy = y_[i] - y_[j];
        const double d2 = dx * dx + dy * dy;  // the book's distance, before its root
        const double reach = radius_[i] + radius_[j];
        if (clearlyApart(d2, reach)) return false;
        if (clearlyOverlapping(d2, reach)) return true;
        return std::sqrt(d2) <= reach;
    }

    // The first j in [from, end) whose circle may overlap circle i, or `end`: the pairs
    // that overlap() turns down at its first comparison are skipped, a block of eight
    // at a time. A block has no branch inside, so the compiler computes it with vector
    // instructions, several pairs at once; a row is mostly far-apart pairs, and only the
    // blocks that hold a near one are looked at pair by pair.
    std::size_t nextNear(std::size_t i, std::size_t from, std::size_t end) const {
        const double xi = x_[i];
        const double yi = y_[i];
        const double ri = radius_[i];
        const auto near = [&](std::size_t j) {
            const double dx = xi - x_[j];
            const double dy = yi - y_[j];
            return !clearlyApart(dx * dx + dy * dy, ri + radius_[j]);
        };
        std::size_t j = from;
        for (; j + kBlock <= end; j += kBlock) {
            bool any = false;
            for (std::size_t k = 0; k < kBlock; ++k) any |= near(j + k);
            if (any) break;
        }
        for (; j < end; ++j) {
            if (near(j)) return j;
        }
        return end;
    }

private:
    // The two comparisons of squares that settle the book's test when rounding cannot
    // (see overlap()); neither holds for NaN, which goes on to the book's comparison.
    static bool clearlyApart(double d2, double reach) {
        const double reach2 = reach * reach;
        return reach2 >= kSmallestSquare && d2 > reach2 * kAboveRounding;
    }
    static bool clearlyOverlapping(double d2, double reach) {
        const double reach2 = reach * reach;
        return reach2 >= kSmallestSquare && d2 < reach2 * kBelowRounding;
    }

    static constexpr std::size_t kBlock = 8;
    static constexpr double kAboveRounding = 1 + 1e-12;
    static constexpr double kBelowRounding = 1 - 1e-12;
    static constexpr double kSmallestSquare = 1e-280;  // far above where doubles lose digits

    std::vector<double> x_;
    std::vector<double> y_;
    std::vector<double> radius_;
    std::vector<char> is_static_;  // (not vector<bool>: one byte each is quicker to read)
};

}  // namespace engine
