#include "box2d_world.h"

#include <box2d/box2d.h>

#include <cmath>
#include <numbers>
#include <vector>

namespace bench {
namespace {

b2Vec2 metres(Vec2 px) {
    return {static_cast<float>(px.x / kPixelsPerMetre), static_cast<float>(px.y / kPixelsPerMetre)};
}
Vec2 pixels(b2Vec2 m) { return Vec2{m.x, m.y} * kPixelsPerMetre; }

// Box2D rounds every polygon's corners by b2_polygonRadius (a skin that keeps resting
// polygons from touching core to core), so a box whose core is that much smaller on
// every side has the scene's size where it meets others.
b2Vec2 core_half_size(const bench::BodyDescription& box) {
    return {static_cast<float>(box.width / 2 / kPixelsPerMetre) - b2_polygonRadius,
            static_cast<float>(box.height / 2 / kPixelsPerMetre) - b2_polygonRadius};
}

// The area Box2D weighs: the core of a box, the whole of a disc.
double area_m2(const bench::BodyDescription& body) {
    if (body.shape == bench::Shape::circle) {
        const double r = body.radius / kPixelsPerMetre;
        return std::numbers::pi * r * r;
    }
    const b2Vec2 half = core_half_size(body);
    return 4.0 * half.x * half.y;
}

class Box2dWorld final : public BenchWorld {
public:
    Box2dWorld(const SceneDescription& scene, bool sleeping)
        : world_(metres(scene.world.gravity)), dt_(static_cast<float>(scene.world.dt)), descriptions_(scene.bodies) {
        world_.SetContinuousPhysics(false);
        world_.SetAllowSleeping(sleeping);
        // Box2D makes contacts slower than this inelastic, so that resting bodies stop
        // bouncing; with no gravity nothing rests, and every collision should bounce.
        const bool resting_possible = scene.world.gravity != Vec2{};
        for (const bench::BodyDescription& body : scene.bodies) add(body, resting_possible);
    }

    Snapshot snapshot() const override {
        Snapshot bodies;
        bodies.reserve(bodies_.size());
        for (std::size_t i = 0; i < bodies_.size(); ++i) {
            const b2Body& body = *bodies_[i];
            const bench::BodyDescription& description = descriptions_[i];
            const Vec2 center = pixels(body.GetPosition());
            oracle::Shape shape = oracle::Disc{center, description.radius};
            if (description.shape == bench::Shape::rectangle) {
                shape = oracle::Box{center, description.width, description.height, body.GetAngle()};
            }
            const bool fixed = body.GetType() == b2_staticBody;
            bodies.push_back({.shape = shape,
                              .is_static = fixed,
                              .mass = body.GetMass(),
                              .inertia = body.GetInertia() * kPixelsPerMetre * kPixelsPerMetre,
                              .velocity = pixels(body.GetLinearVelocity()),
                              .angular_velocity = body.GetAngularVelocity()});
        }
        return bodies;
    }

    std::optional<std::size_t> awake_count() const override {
        std::size_t awake = 0;
        for (const b2Body* body : bodies_) awake += body->GetType() == b2_dynamicBody && body->IsAwake() ? 1 : 0;
        return awake;
    }

protected:
    void advance(long steps) override {
        for (long i = 0; i < steps; ++i) world_.Step(dt_, kBox2dVelocityIterations, kBox2dPositionIterations);
    }

private:
    void add(const bench::BodyDescription& description, bool resting_possible) {
        b2BodyDef definition;
        const bool fixed = description.mass == 0.0;
        definition.type = fixed ? b2_staticBody : b2_dynamicBody;
        definition.position = metres(description.center);
        definition.angle = static_cast<float>(description.angle);
        definition.linearVelocity = metres(description.velocity);
        definition.angularVelocity = static_cast<float>(description.angular_velocity);
        b2Body* body = world_.CreateBody(&definition);

        b2PolygonShape box;
        b2CircleShape disc;
        b2FixtureDef fixture;
        if (description.shape == bench::Shape::circle) {
            disc.m_radius = static_cast<float>(description.radius / kPixelsPerMetre);
            fixture.shape = &disc;
        } else {
            const b2Vec2 half = core_half_size(description);
            box.SetAsBox(half.x, half.y);
            fixture.shape = &box;
        }
        // Box2D takes a density; this one gives the body the scene's mass.
        fixture.density = fixed ? 0.0f : static_cast<float>(description.mass / area_m2(description));
        fixture.friction = static_cast<float>(description.friction);
        fixture.restitution = static_cast<float>(description.restitution);
        if (!resting_possible) fixture.restitutionThreshold = 0.0f;
        body->CreateFixture(&fixture);
        bodies_.push_back(body);
    }

    b2World world_;
    float dt_;
    std::vector<bench::BodyDescription> descriptions_;
    std::vector<b2Body*> bodies_;  // owned by world_, in scene order
};

}  // namespace

bool box2d_available() { return true; }

// Major and minor only: Debian's 2.4.1 calls itself 2.4.0 in b2_version.
std::string box2d_version() {
    std::string name = "Box2D ";
    return name.append(std::to_string(b2_version.major)).append(".").append(std::to_string(b2_version.minor));
}

std::unique_ptr<BenchWorld> box2d_world(const SceneDescription& scene, bool sleeping) {
    return std::make_unique<Box2dWorld>(scene, sleeping);
}

}  // namespace bench
