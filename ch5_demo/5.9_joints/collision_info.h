#pragma once
// What a narrow-phase test finds out about two shapes that overlap (the book's
// Lib/CollisionInfo.js, Figure 3-6):
//
//   depth   how far they overlap, measured along the normal: the least distance
//           that one of them must move to end the overlap
//   normal  the unit direction of that move
//   start   where the overlap begins, on one shape's outline,
//   end     = start + normal * depth, where it ends, on the other shape's outline
//
// So the segment from start to end shows both the direction and the size of the
// correction, and that is how 3.2 to 4.2 draw it (an orange line).

#include <optional>

#include "vec2.h"

namespace engine {

using lib::Vec2;

// Written inline, here: the narrow phase makes one for every pair that collides, and
// an out-of-line constructor would pass its numbers through memory on every one.
class CollisionInfo {
public:
    CollisionInfo() = default;
    CollisionInfo(double depth, Vec2 normal, Vec2 start) : depth_(depth), normal_(normal), start_(start) {}

    double depth() const { return depth_; }
    Vec2 normal() const { return normal_; }
    Vec2 start() const { return start_; }
    Vec2 end() const { return start_ + normal_ * depth_; }

    // The same overlap seen from the other shape: the normal turns round, and start
    // and end swap, so the segment stays where it is.
    void changeDir() {
        start_ = end();
        normal_ = -normal_;
    }

private:
    double depth_ = 0.0;
    Vec2 normal_;
    Vec2 start_;
};

// An overlap another shape's test found, seen from this shape's side (5.8: a polygon's
// test answers for the rectangle or circle it meets).
inline std::optional<CollisionInfo> turnedRound(std::optional<CollisionInfo> info) {
    if (info) info->changeDir();
    return info;
}

}  // namespace engine
