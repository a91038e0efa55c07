#pragma once
// Continuous collision (beyond the book: the first of the collision topics its chapter 5
// leaves to explore). The book's step looks at the world only where each step ends. A
// shape that moves further in one step than it is thick can be on one side of a thin
// wall at one look and on the other side at the next, and no look ever sees the two
// overlap: it tunnels. Or it is caught deep in the wall, past the wall's middle, and
// the correction pushes it out on the far side.
//
// Most shapes never move that far, so only the fast ones are looked at more closely
// (Box2D's choice): a shape whose farthest point moved more in this step than
// kFastShare of its smallest extent. Each fast shape is swept along the step's motion
// against the static shapes (a bullet also against the moving ones, where they ended
// the step), and, if it meets one, moved back to its time of impact: the moment its
// outline is kImpactDepth into the obstacle. There the next step's collision handling,
// either solver, finds an ordinary shallow contact and bounces it. What the method
// gives up: the rest of the step after the impact is lost (README.md measures it).
//
// The time of impact is found by conservative advancement, for every pair of shapes
// alike: the gap between the two outlines is measured (5.8: by GJK when one of them is
// a polygon), and no point of the moving shape travels faster than its centre's speed
// plus its spin times its reach, so the shape may safely move on by gap / that speed
// without touching; that is repeated until the gap is under a quarter of the depth. A
// head-on shot needs one advance, a grazing one a few; kMaxAdvances bounds them, and a
// shape stopped by that bound is stopped short of the obstacle, never inside it.
//
// Every bound comes from the shape's own extent: its reach (a plate's half diagonal)
// bounds how fast its points move as it turns, and its thinness (half its shorter
// side) how deep it may be stopped. A shape the solver has left deep in contact (a
// plate thinner than the sequential impulse solver's slop sinks in by more than half
// its thickness) is swept deeper, up to three quarters of its thinness, and beyond that
// only its centre is kept out: a centre outside the obstacle is what makes the next
// step's collision handling push it back the way it came (README.md, the envelope).

#include <array>
#include <cstddef>
#include <optional>
#include <span>
#include <vector>

#include "convex_polygon.h"
#include "rigid_shape.h"

namespace engine {

// A shape is fast when its farthest point moves more than half its smallest extent (a
// circle's radius, half a rectangle's shorter side) in one step, as in Box2D. Below
// that the step's collision handling catches the shape before its centre is half way
// into anything, however thin, and pushes it back out the side it came from; the other
// half is left for its turning and for what the other contacts do to it.
inline constexpr double kFastShare = 0.5;
// How deep a swept shape is left in what it hits (never more than a quarter of its
// smallest extent): deep enough that the next step's narrow phase finds the contact,
// shallow enough that the correction moves it back less than a pixel.
inline constexpr double kImpactDepth = 0.5;  // px
inline constexpr int kMaxAdvances = 50;

// A shape's outline as the sweep sees it: a core grown by a radius. A circle's core is
// its centre, a rectangle's the quadrilateral of its four corners, a polygon's (5.8) its
// corners, with no radius.
struct Outline {
    Vec2 center;
    bool is_point = true;                             // a circle
    std::array<Vec2, kMaxPolygonVertices> corners{};  // in order round it
    std::size_t count = 0;                            // how many corners
    bool square_corners = false;                      // a rectangle's (shrunk says why)
    double radius = 0.0;

    std::span<const Vec2> cornerList() const { return {corners.data(), count}; }
};

Outline outlineOf(const RigidShape& shape);
// The outline turned by `turn` rad about its centre, then moved by `offset`.
Outline moved(const Outline& outline, Vec2 offset, double turn);
// The outline with every side pulled in by `depth`.
Outline shrunk(const Outline& outline, double depth);
// How far apart the two outlines are; 0 or less when they touch or overlap. By GJK for
// two outlines with corners of which one is a polygon's, by the per-kind functions for
// the rest (continuous.cpp says why).
double gap(const Outline& a, const Outline& b);
// Each of the two for every pair of kinds, to race them (bench/gap_study.cpp): 5.6's
// per-kind functions (a point and a point, a point and corners, corners and corners),
// and GJK (gjk.h; 0 when they touch or overlap).
double perKindGap(const Outline& a, const Outline& b);
double gjkGap(const Outline& a, const Outline& b);
// A circle's radius, half a rectangle's shorter side.
double smallestExtent(const RigidShape& shape);

// A shape's motion in one step: its outline where the step began, and how far it then
// moved and turned.
struct StepMotion {
    Outline start;
    Vec2 offset;
    double turn = 0.0;  // rad
};
// How far the motion carries the outline's farthest point, at most.
double reach(const StepMotion& motion);
// Whether `shape`, having moved by `offset` and turned by `turn` in this step, is fast:
// its farthest point (a rectangle's corner; nothing of a circle's outline moves when it
// turns) moved more than kFastShare of its smallest extent.
bool isFast(const RigidShape& shape, Vec2 offset, double turn);

// The share t of the motion (0 < t <= 1) at which the moving outline is first `depth`
// into `obstacle` (to within a quarter of the depth), the obstacle standing still.
// Nothing when that never happens in this motion; 0 when the two already touch that
// deep where the motion starts.
std::optional<double> timeOfImpact(const StepMotion& motion, const Outline& obstacle, double depth);
// Where the sweep stops a shape whose smallest extent is `extent` and which may already
// touch `obstacle` where its motion starts: the share of the motion, or nothing when it
// need not be stopped (continuous.cpp says how it goes deeper for a shape in contact).
std::optional<double> impactAgainst(const StepMotion& motion, const Outline& obstacle, double extent);

// A fast shape whose sweep went through a sensor in the last step (5.7): the sensor
// feels it even when no look at a step's end finds the two overlapping. `t` is the
// place of the mover's centre when its outline was first kImpactDepth inside the sensor.
struct Crossing {
    std::size_t mover;
    std::size_t sensor;
    Vec2 point;      // the mover's centre as it entered
    Vec2 direction;  // of its motion, a unit vector
};

// What the sweep did to one fast shape in the last step (the overlay draws it).
struct Sweep {
    std::size_t index;
    Vec2 from;                     // its centre where the step began
    Vec2 to;                       // and where its motion would have taken it
    std::optional<double> impact;  // the share of the motion it was moved back to
};

class ContinuousCollision {
public:
    // Before the shapes move: where each one is.
    void startStep(ShapeList shapes);
    // After they moved: sweeps every fast shape and moves the ones that hit something
    // back to their time of impact.
    void sweep(ShapeList shapes);
    const std::vector<Sweep>& sweeps() const { return sweeps_; }
    const std::vector<Crossing>& crossings() const { return crossings_; }
    // For the core, when it takes shapes out of the list.
    void forgetSweeps() {
        sweeps_.clear();
        crossings_.clear();
    }

private:
    struct Pose {
        Vec2 center;
        double angle = 0.0;
    };
    std::vector<Pose> start_;
    std::vector<std::size_t> static_;  // the places of the static shapes, this step
    std::vector<Sweep> sweeps_;
    std::vector<Crossing> crossings_;
    std::vector<std::size_t> sensors_met_;  // one shape's sensors on its way, while it is swept
};

}  // namespace engine
