// box2d_world.h in a build without Box2D (Debian: libbox2d-dev).
#include "box2d_world.h"

namespace bench {

bool box2d_available() { return false; }
std::string box2d_version() { return "no Box2D"; }
std::unique_ptr<BenchWorld> box2d_world(const SceneDescription&, bool) { return nullptr; }

}  // namespace bench
