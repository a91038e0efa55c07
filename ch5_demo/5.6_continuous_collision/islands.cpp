#include "islands.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace engine {

namespace {
// How fast a shape still moves, all told (islands.h): straight, turning at its farthest
// point, and the overlap past the slop it would still have to be moved out of in a step.
double sleepSpeed(const RigidShape& shape, double deepest, const WorldSettings& world) {
    const double correction = std::max(0.0, deepest - world.slop) / world.dt;
    return shape.velocity().length() + std::abs(shape.angularVelocity()) * shape.boundRadius() + correction;
}

// How far the shape has gone since its rest began: its centre, and its farthest point
// turning about it. A shape that starts to slide or tip from rest is slow for a long
// while, but it goes on in one direction, where a resting one only trembles in place.
double driftSinceRest(const RigidShape& shape) {
    const SleepState& state = shape.sleep();
    if (state.rested_s == 0.0) return 0.0;
    return shape.center().distance(state.rest_center) + std::abs(shape.angle() - state.rest_angle) * shape.boundRadius();
}
}  // namespace

void Islands::touching(ShapeList shapes, std::size_t i, std::size_t j, double depth) {
    touches_.push_back({i, j, depth});
    // An awake shape has reached a sleeping one: the sleeper's island must take part in
    // this very step, or the awake shape would sink into it as into a static wall.
    if (shapes[i]->sleep().asleep) wakeIslandOf(shapes, i);
    if (shapes[j]->sleep().asleep) wakeIslandOf(shapes, j);
}

std::size_t Islands::root(std::size_t i) {
    while (parent_[i] != i) i = parent_[i] = parent_[parent_[i]];  // halving the path as it goes
    return i;
}

void Islands::endStep(ShapeList shapes, const WorldSettings& world) {
    if (!world.sleep) return;
    const std::size_t count = shapes.size();
    parent_.resize(count);
    std::iota(parent_.begin(), parent_.end(), std::size_t{0});
    deepest_.assign(count, 0.0);
    held_.assign(count, 0);
    for (const Touch& touch : touches_) {
        deepest_[touch.a] = std::max(deepest_[touch.a], touch.depth);
        deepest_[touch.b] = std::max(deepest_[touch.b], touch.depth);
        held_[touch.a] = held_[touch.b] = 1;
        // Never through a static shape: it holds what lies on it, but carries no motion
        // from one of them to another.
        if (shapes[touch.a]->isStatic() || shapes[touch.b]->isStatic()) continue;
        parent_[root(touch.a)] = root(touch.b);
    }
    // Without gravity nothing falls, and a shape floating still is at rest.
    const bool falling_without_support = world.gravity != Vec2{};
    island_rested_.assign(count, std::numeric_limits<double>::infinity());
    for (std::size_t i = 0; i < count; ++i) {
        RigidShape& shape = *shapes[i];
        if (shape.isResting()) continue;
        // The book's passes leave a resting box rocking on its corners, off the floor
        // every other step: a contact in this step or the last one holds it.
        const bool held = held_[i] || shape.sleep().held;
        const bool resting = world.movement && (held || !falling_without_support) &&
                             sleepSpeed(shape, deepest_[i], world) < world.sleep_speed &&
                             driftSinceRest(shape) <= world.slop;
        shape.rest(resting, held_[i], world.dt);
        double& rested = island_rested_[root(i)];
        rested = std::min(rested, shape.sleep().rested_s);
    }
    island_label_.assign(count, 0);
    for (std::size_t i = 0; i < count; ++i) {
        RigidShape& shape = *shapes[i];
        if (shape.isResting()) continue;
        const std::size_t island = root(i);
        if (island_label_[island] == 0) island_label_[island] = next_label_++;
        shape.joinIsland(island_label_[island]);
        if (island_rested_[island] >= world.time_to_sleep) shape.fallAsleep(island_label_[island]);
    }
}

void Islands::wakeLabel(ShapeList shapes, std::uint64_t island) {
    for (const auto& shape : shapes) {
        if (shape->sleep().island == island && !shape->isStatic()) shape->wake();
    }
}

void Islands::wakeIslandOf(ShapeList shapes, std::size_t index) {
    if (index >= shapes.size()) return;
    RigidShape& shape = *shapes[index];
    if (shape.isStatic()) return wakeAll(shapes);
    wakeLabel(shapes, shape.sleep().island);
    shape.wake();
}

void Islands::wakeAll(ShapeList shapes) {
    for (const auto& shape : shapes) shape->wake();
}

std::size_t Islands::awakeCount(ShapeList shapes) {
    return static_cast<std::size_t>(
        std::count_if(shapes.begin(), shapes.end(), [](const auto& shape) { return !shape->isResting(); }));
}

}  // namespace engine
