#pragma once
// Where two overlapping shapes touch, as points (not in the book; 5.4's solver,
// contact_solver.h, needs them).
//
// The book's narrow phase answers with one overlap: a depth, a normal and one segment.
// For a box lying flat on a floor that is one point, somewhere under the box, and an
// impulse at one point can hold the box's weight but not its turning: each pass nudges
// one corner, then the other, and a stack jitters. A flat contact is a whole segment of
// touching, and two points (its ends) are enough to carry any force and torque the
// segment can carry, so the manifold of two rectangles has up to two points.
//
// How the two points are found (clipping). The book's separating axis test still
// chooses the axis: its normal is a face normal of one of the rectangles, and that
// face, or the first rectangle's face that looks along it when that one is deeper by
// no more than a tolerance (contact_manifold.cpp says why), is the *reference face*.
// The other rectangle's face that looks most against it is the
// *incident face*. The incident face, a segment, is cut by the two side lines of the
// reference face (the lines through its ends, square to it), so that what is left lies
// over the reference face; of that, the ends that lie behind the reference face are
// the contact points, each as deep as it lies behind.
//
// A pair with a circle touches at one point: the middle of the book's segment.
//
// Each point carries a key naming the features that made it (which faces, and which
// end of the incident face), so that the solver can recognise the same point in the
// next step, although the shapes have moved, and start it from its last impulses.

#include <array>
#include <cstddef>
#include <cstdint>

#include "collision_info.h"
#include "rigid_shape.h"

namespace engine {

struct ContactPoint {
    Vec2 position;          // halfway between the two outlines
    double depth = 0.0;     // > 0: how far the outlines overlap here, along the normal
    std::uint32_t key = 0;  // the features that made the point (same key, same point)
};

// At most two of something, kept in place: a step makes one manifold per touching
// pair, and a list on the heap for each would cost more than the points themselves.
template <class Item>
class UpToTwo {
public:
    void push_back(const Item& item) { items_.at(count_++) = item; }
    std::size_t size() const { return count_; }
    bool empty() const { return count_ == 0; }
    Item& operator[](std::size_t i) { return items_[i]; }
    const Item& operator[](std::size_t i) const { return items_[i]; }
    Item* begin() { return items_.data(); }
    Item* end() { return items_.data() + count_; }
    const Item* begin() const { return items_.data(); }
    const Item* end() const { return items_.data() + count_; }

private:
    std::array<Item, 2> items_{};
    std::size_t count_ = 0;
};

struct ContactManifold {
    Vec2 normal;  // unit, from the first shape towards the second
    UpToTwo<ContactPoint> points;
};

// What a point's key names: the reference face and the incident face (face i of a
// rectangle runs from its corner i to corner i + 1), or that the point stands alone (a
// pair with a circle, or rectangles where the book's one point stood in).
struct ContactFeatures {
    bool single_point = false;
    bool reference_is_b = false;  // the reference face is the second shape's
    std::size_t reference_face = 0;
    std::size_t incident_face = 0;
};
ContactFeatures featuresOf(std::uint32_t key);

// The contact points of two shapes whose overlap the narrow phase found (`info`, its
// normal from a towards b). Two rectangles give one or two points, a pair with a
// circle one. Of two rectangles, a's face is the reference unless b's is shallower by
// more than `tolerance` (px), and the manifold's normal is the reference face's.
ContactManifold contactManifold(const RigidShape& a, const RigidShape& b, const CollisionInfo& info, double tolerance);

}  // namespace engine
