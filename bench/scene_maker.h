#pragma once
// The bench's scenes, made by code so that the big ones need not be typed: every
// random choice comes from a seeded browser::Random, so the same call makes the same
// scene on every machine. `bench --write-scenes DIR` writes the shipped ones as the
// JSON files in bench/scenes/, which the bench then reads like any scene file; the
// scale and pair scenes are only made in memory.
//
// Units are the book's (px, s, rad, +y down). Every world is the book's (stage 5.1's
// kBookWorld, stages.h: book_world) with its own size and gravity and
// remove_out_of_bounds off, so no run loses bodies. Only the book's world keys are set,
// so every chapter 5 stage reads the scenes; each study chooses the stages it runs.

#include <string>
#include <vector>

#include "scene_description.h"

namespace bench::scenes {

// A pyramid of boxes (30 px, restitution 0) on a static floor: `rows` boxes at the
// bottom, one at the top, 1 px apart and 0.25 px above their support. Gravity 20.
SceneDescription pyramid(int rows);

// `shapes` boxes (sides 10 to 16 px) and discs (10 to 18 px across) raining into an
// open box from a jittered lattice just above its floor; mass in proportion to area. Gravity
// 100, so the pile settles within a few seconds.
SceneDescription rain(int shapes);

// 60 discs at 150 px/s in a closed box, restitution 1, friction 0, no gravity: a gas
// whose kinetic energy must stay what it was.
SceneDescription gas();

// One disc thrown at (150, -150) px/s under gravity 100, with nothing to hit.
SceneDescription projectile();
inline constexpr double kProjectileGravity = 100.0;

// A 40 x 20 box sliding at 200 px/s on a static floor, friction 0.5 on both, gravity
// 100: Coulomb's law stops it after v^2 / (2 mu g) = 400 px.
SceneDescription slide();

// A box of mass `heavy` (60 x 60) on a slab of mass 1 (100 x 20) on a static floor,
// 0.25 px apart, gravity 20: the scene library's heavy_on_light.json (100 : 1).
SceneDescription heavy_on_light(double heavy = 100.0);
inline constexpr double kSlideSpeed = 200.0;
inline constexpr double kSlideFriction = 0.5;
inline constexpr double kSlideGravity = 100.0;

// A disc (radius 20, friction 0.8) at rest on a static slope of 0.5 rad, gravity 100:
// rolling without slipping, it runs down at 2/3 g sin(angle).
SceneDescription slope();
inline constexpr double kSlopeAngle = 0.5;
inline constexpr double kSlopeGravity = 100.0;

// A disc (radius 5) 1 px in front of a static wall 4 px thick, flying at it at
// 1500 px/s, no gravity, friction 0.
SceneDescription thin_wall();
inline constexpr double kWallBallRadius = 5.0;
inline constexpr double kWallThickness = 4.0;
inline constexpr double kWallGap = 1.0;

// `shapes` boxes and discs (8 to 14 px) on a jittered lattice of 20 px, drifting at up
// to 20 px/s with no gravity: the same density, and so about the same contacts per
// shape, whatever the count, for as long as the drift is short against the lattice
// (the scale study runs 11 steps: at most 4 px).
SceneDescription scale(int shapes);

// `shapes` discs (radius 4) at rest on a 20 px lattice, no gravity: no two bounding
// circles touch, so every pair a broad phase looks at ends at its bounding-circle test.
SceneDescription spread(int shapes);

// One pair of one kind in resting contact (restitution 0, gravity 20): a box on a
// static box, a disc on a static box, a disc balanced on top of a static disc.
enum class PairKind { rect_rect, rect_circle, circle_circle };
SceneDescription pair(PairKind kind);

struct NamedScene {
    std::string name;  // the file name without ".json"
    SceneDescription scene;
};
// The scenes shipped in bench/scenes/.
std::vector<NamedScene> shipped();

}  // namespace bench::scenes
