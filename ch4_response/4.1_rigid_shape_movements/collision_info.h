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
// correction, and that is how it is drawn (an orange line).

#include "vec2.h"

namespace engine {

using lib::Vec2;

class CollisionInfo {
public:
    CollisionInfo() = default;
    CollisionInfo(double depth, Vec2 normal, Vec2 start);

    double depth() const { return depth_; }
    Vec2 normal() const { return normal_; }
    Vec2 start() const { return start_; }
    Vec2 end() const;

    // The same overlap seen from the other shape: the normal turns round, and start
    // and end swap, so the segment stays where it is.
    void changeDir();

private:
    double depth_ = 0.0;
    Vec2 normal_;
    Vec2 start_;
};

}  // namespace engine
