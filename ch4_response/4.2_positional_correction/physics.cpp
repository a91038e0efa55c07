#include "physics.h"

namespace engine {

namespace {

// Moves the two shapes apart along the normal by `rate` of their overlap, shared in
// proportion to their inverse masses: a shape twice as heavy moves half as far, a
// static one not at all, and the pair's centre of mass stays where it was. The moves
// are added to `response` when the overlay keeps one.
void positionalCorrection(RigidShape& a, RigidShape& b, const CollisionInfo& info, double rate,
                          PairResponse* response) {
    const double amount = info.depth() / (a.invMass() + b.invMass()) * rate;
    const Vec2 correction = info.normal() * amount;  // the normal points from a to b
    a.move(correction * -a.invMass());
    b.move(correction * b.invMass());
    if (!response) return;
    response->moved_first += correction * -a.invMass();
    response->moved_second += correction * b.invMass();
}

// What a collision does to the pair. In this project: push them apart.
// What it did goes into `response`, the overlay's record of the pair (nullptr while
// the overlay keeps none).
void resolveCollision(RigidShape& a, RigidShape& b, const CollisionInfo& info, const WorldSettings& world,
                      PairResponse* response) {
    // Nothing moves two static shapes: 1/mA + 1/mB = 0, and every share below is 0 / 0.
    if (a.isStatic() && b.isStatic()) return;
    if (world.positional_correction) positionalCorrection(a, b, info, world.correction_rate, response);
}

}  // namespace

std::optional<CollisionInfo> findCollision(const RigidShape& a, const RigidShape& b) {
    if (!a.boundTest(b)) return std::nullopt;
    std::optional<CollisionInfo> info = a.collisionTest(b);
    // A normal with a negative component along the line between the centres points
    // from b towards a.
    if (info && info->normal().dot(b.center() - a.center()) < 0) info->changeDir();
    return info;
}

void Physics::keepResponses(bool keep) {
    keep_responses_ = keep;
    if (!keep) responses_.clear();
}

PairResponse* Physics::responseOf(PairKey pair) { return keep_responses_ ? &responses_[pair] : nullptr; }

void Physics::collision(ShapeList shapes, const WorldSettings& world) {
    collisions_.clear();
    responses_.clear();
    for (int pass = 0; pass < world.relaxation_iterations; ++pass) relaxationPass(shapes, world);
}

// Every pair is resolved as soon as it is found, so the pairs after it already see the
// shapes where that correction left them.
void Physics::relaxationPass(ShapeList shapes, const WorldSettings& world) {
    collisions_.clear();
    for (std::size_t i = 0; i < shapes.size(); ++i) {
        for (std::size_t j = i + 1; j < shapes.size(); ++j) {
            RigidShape& a = *shapes[i];
            RigidShape& b = *shapes[j];
            const std::optional<CollisionInfo> info = findCollision(a, b);
            if (!info) continue;
            collisions_.push_back({i, j, *info});  // two static shapes too: the borders' corners
            resolveCollision(a, b, *info, world, responseOf({i, j}));
        }
    }
}

void Physics::drawCollisions(browser::Canvas& context) const {
    context.setStrokeStyle(browser::colors::kOrange);
    for (const Collision& pair : collisions_) {
        context.beginPath();
        context.moveTo(pair.info.start().x, pair.info.start().y);
        context.lineTo(pair.info.end().x, pair.info.end().y);
        context.stroke();
    }
}

}  // namespace engine
