#pragma once
// Tunnelling: a discrete engine only looks at the world once per (sub-)step, so a ball
// fast enough to be in front of a thin wall at one look and past it at the next never
// meets it. The search finds the slowest speed at which the ball gets through.
//
// The scene has one moving body, a ball flying along +x, and one static wall ahead of
// it. At speed v the ball moves v dt / substeps between looks; getting through is
// taken to grow with v (it does when the ball starts closer to the wall than the wall's
// half thickness plus its radius: a slower ball then always has a look at which it is
// caught, and is pushed back out the near side).

#include "scene_description.h"
#include "stages.h"

namespace bench {

// True when the ball, sent at `speed` px/s along +x by the stage's engine, ends up
// wholly past the wall. It is caught when it starts moving back, or when it is still
// not through after twice the steps it needs to cross at that speed.
bool ball_passes(Stage stage, const SceneDescription& scene, double speed);

// The slowest speed at which the ball passes, found by doubling from 100 px/s until it
// passes, then halving the bracket until it is narrower than `tolerance` times its
// top. Returns the top: a speed that passes, at most that much above the true one.
double slowest_passing_speed(Stage stage, const SceneDescription& scene, double tolerance);

}  // namespace bench
