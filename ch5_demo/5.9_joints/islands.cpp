#include "islands.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <utility>

namespace engine {

namespace {
// How fast a shape moved in the step, all told (islands.h): straight and turning at its
// farthest point, from where the step found it; and, with no correction to push it
// out, the overlap past the slop it would have to leave within a step.
double sleepSpeed(const RigidShape& shape, Vec2 start_center, double start_angle, double deepest,
                  const WorldSettings& world) {
    const double correction = world.positional_correction ? 0.0 : std::max(0.0, deepest - world.slop) / world.dt;
    const double moved = shape.center().distance(start_center) / world.dt;
    const double turned = std::abs(shape.angle() - start_angle) * shape.boundRadius() / world.dt;
    return moved + turned + correction;
}

// How far the shape has gone since its rest began, or since the last time_to_sleep of
// it began (RigidShape::rest): its centre, and its farthest point turning about it. A
// shape that starts to slide or tip from rest is slow for a long while, but it goes on
// in one direction, where a resting one only trembles in place. Over the last window
// only: a shape that creeps by a hair a second while its island is kept awake by
// another would otherwise run out of allowance, and keep the island awake in turn.
double driftSinceRest(const RigidShape& shape) {
    const SleepState& state = shape.sleep();
    if (state.rested_s == 0.0) return 0.0;
    return shape.center().distance(state.rest_center) +
           std::abs(shape.angle() - state.rest_angle) * shape.boundRadius();
}

// A steady creep at 0.3 px/s over the time to sleep: 0.15 px with the defaults, where a
// box sliding from rest at 1.2 px/s^2 gets in half a second. In pixels, not in
// proportion to the sleep speed: a pile that jitters more under a stronger gravity
// may still not creep farther (the README's figures: at 1000 px/s^2, a drift allowed
// in proportion let a pile fall asleep while it still slumped 5 px).
double driftAllowed(const WorldSettings& world) { return kCreepSpeed * world.time_to_sleep; }
}  // namespace

void Islands::startStep(ShapeList shapes) {
    const std::size_t count = shapes.size();
    parent_.resize(count);
    std::iota(parent_.begin(), parent_.end(), std::size_t{0});
    deepest_.assign(count, 0.0);
    held_.assign(count, 0);
    carried_.assign(count, 0);
    step_start_center_.resize(shapes.size());
    step_start_angle_.resize(shapes.size());
    for (std::size_t i = 0; i < shapes.size(); ++i) {
        step_start_center_[i] = shapes[i]->center();
        step_start_angle_[i] = shapes[i]->angle();
    }
}

bool Islands::touching(ShapeList shapes, std::size_t i, std::size_t j, double depth) {
    // Each pass of the book's relaxation reports its pairs again: the islands are joined
    // as they come, with no list to keep.
    deepest_[i] = std::max(deepest_[i], depth);
    deepest_[j] = std::max(deepest_[j], depth);
    held_[i] = held_[j] = 1;
    // Never through a static shape: it holds what lies on it, but carries no motion from
    // one of them to another. Nor through a kinematic one (5.9), which nothing they do
    // moves; but while it moves it keeps what it touches from resting.
    if (shapes[i]->isDynamic() && shapes[j]->isDynamic()) parent_[root(i)] = root(j);
    if (shapes[i]->isKinematic() && !shapes[i]->isResting()) carried_[j] = 1;
    if (shapes[j]->isKinematic() && !shapes[j]->isResting()) carried_[i] = 1;
    // An awake shape has reached a sleeping one: the sleeper's island must take part in
    // this very step, or the awake shape would sink into it as into a static wall. Its
    // rest goes on: nothing has moved it yet. Were it to start again, a shape at the edge
    // of a pile whose touch comes and goes (apart for a step, so that it fell asleep on
    // its own, then touching again) would make the whole pile wait another
    // time_to_sleep, again and again (the README's figures). If the touch does move the
    // island, its sleep speed starts its rest again; if not, it was at rest all along.
    bool woke = false;
    for (const std::size_t shape : {i, j}) {
        if (!shapes[shape]->sleep().asleep) continue;
        wakeIslandOf(shapes, shape, RestTimer::goes_on);
        woke = true;
    }
    return woke;
}

bool Islands::joined(ShapeList shapes, std::size_t i, std::size_t j) {
    held_[i] = held_[j] = 1;
    if (!shapes[i]->isStatic() && !shapes[j]->isStatic()) parent_[root(i)] = root(j);
    bool woke = false;
    for (const auto& [sleeper, other] : {std::pair{i, j}, std::pair{j, i}}) {
        if (!shapes[sleeper]->sleep().asleep || shapes[other]->isResting()) continue;
        wakeIslandOf(shapes, sleeper, RestTimer::goes_on);
        woke = true;
    }
    return woke;
}

std::size_t Islands::root(std::size_t i) {
    while (parent_[i] != i) i = parent_[i] = parent_[parent_[i]];  // halving the path as it goes
    return i;
}

void Islands::endStep(ShapeList shapes, const WorldSettings& world) {
    if (!world.sleep) return;
    const std::size_t count = shapes.size();
    // Without gravity nothing falls, and a shape floating still is at rest.
    const bool falling_without_support = world.gravity != Vec2{};
    island_rested_.assign(count, std::numeric_limits<double>::infinity());
    for (std::size_t i = 0; i < count; ++i) {
        RigidShape& shape = *shapes[i];
        if (shape.isResting() || shape.isKinematic()) continue;
        // The book's passes leave a resting box rocking on its corners, off the floor
        // every other step: a contact in this step or the last one holds it.
        const bool held = held_[i] || shape.sleep().held;
        const double speed = sleepSpeed(shape, step_start_center_[i], step_start_angle_[i], deepest_[i], world);
        const bool resting = world.movement && (held || !falling_without_support) && speed < sleepSpeed(world) &&
                             driftSinceRest(shape) <= driftAllowed(world) && !carried_[i];
        shape.rest(resting, held_[i], speed, world.dt, world.time_to_sleep);
        double& rested = island_rested_[root(i)];
        rested = std::min(rested, shape.sleep().rested_s);
    }
    island_label_.assign(count, 0);
    for (std::size_t i = 0; i < count; ++i) {
        RigidShape& shape = *shapes[i];
        if (shape.isResting() || shape.isKinematic()) continue;
        const std::size_t island = root(i);
        if (island_label_[island] == 0) island_label_[island] = next_label_++;
        shape.joinIsland(island_label_[island]);
        // Every shape of the island must rest in this very step: with time_to_sleep 0,
        // "rested at least 0 s" would also hold for a shape that did not rest at all.
        const double rested = island_rested_[island];
        if (rested > 0.0 && rested >= world.time_to_sleep) shape.fallAsleep(island_label_[island]);
    }
}

void Islands::wakeLabel(ShapeList shapes, std::uint64_t island, RestTimer timer) {
    for (const auto& shape : shapes) {
        if (shape->sleep().island == island && !shape->isStatic()) shape->wake(timer);
    }
}

void Islands::wakeIslandOf(ShapeList shapes, std::size_t index, RestTimer timer) {
    if (index >= shapes.size()) return;
    ++wake_count_;
    RigidShape& shape = *shapes[index];
    if (!shape.isDynamic()) return wakeAll(shapes);  // static or kinematic
    wakeLabel(shapes, shape.sleep().island, timer);
    shape.wake(timer);
}

void Islands::wakeAll(ShapeList shapes) {
    ++wake_count_;
    for (const auto& shape : shapes) shape->wake();
}

std::size_t Islands::awakeCount(ShapeList shapes) {
    return static_cast<std::size_t>(
        std::count_if(shapes.begin(), shapes.end(), [](const auto& shape) { return !shape->isResting(); }));
}

}  // namespace engine
