#pragma once
// Box2D 2.4 as the reference engine, for the scenes where a comparison means something
// (piles and the gas). The scene is scaled to metres, kPixelsPerMetre px to the metre,
// as Box2D is tuned for bodies of 0.1 to 10 m; the snapshot is scaled back to px.
// Box2D's boxes are rounded by a skin of b2_polygonRadius (0.3 px here) around a
// smaller core, so that they are the scene's size where they touch; the measures see
// them as plain boxes of the scene's size. Box2D runs as the bench's targets ask:
// continuous collision off (our engines have none), 8 velocity and 3 position
// iterations per step; and with sleeping off, as a body that sleeps costs nothing and
// ours never do. Friction and restitution are each
// body's own; our scenes give every body of a pile the same ones, so Box2D's mixing
// rules (sqrt(f1 f2), max(e1, e2)) and ours (min, min) agree.
//
// Box2D is optional (Debian: libbox2d-dev); without it box2d_world() gives nothing
// and the bench says so once (kNoBox2d).

#include <memory>
#include <string_view>

#include "bench_world.h"
#include "scene_description.h"

namespace bench {

inline constexpr double kPixelsPerMetre = 30.0;
inline constexpr int kBox2dVelocityIterations = 8;
inline constexpr int kBox2dPositionIterations = 3;
inline constexpr std::string_view kNoBox2d = "Box2D 2.4 not found (Debian: libbox2d-dev): no reference row";

bool box2d_available();
// "Box2D 2.4", from the library itself.
std::string box2d_version();

// Nothing in a build without Box2D. `sleeping` lets Box2D put resting bodies to sleep
// (its own rule: under 0.01 m/s and 2 degrees/s for 0.5 s), for the study of 5.5's
// sleeping (sleep_study.cpp); every other measure runs with sleeping off.
std::unique_ptr<BenchWorld> box2d_world(const SceneDescription& scene, bool sleeping = false);

}  // namespace bench
