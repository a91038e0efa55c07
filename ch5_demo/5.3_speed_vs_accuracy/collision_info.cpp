#include "collision_info.h"

namespace engine {

CollisionInfo::CollisionInfo(double depth, Vec2 normal, Vec2 start) : depth_(depth), normal_(normal), start_(start) {}

Vec2 CollisionInfo::end() const { return start_ + normal_ * depth_; }

void CollisionInfo::changeDir() {
    start_ = end();
    normal_ = -normal_;
}

}  // namespace engine
