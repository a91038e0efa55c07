// A stage's engine behind bench::StageEngine. Written once, compiled once per stage:
// each time against that stage's engine library, which puts its folder on the include
// path and defines `engine` as a name of its own (engine_s5_1, ...), and with
// BENCH_STAGE_ENGINE as the factory to define (s5_1_engine, ...); bench/CMakeLists.txt
// says why. Where the stages differ (5.1
// counts no pairs, 5.3 has sub-steps), the code asks the stage's types what they have
// rather than which stage it is.

#include <cmath>
#include <optional>

#include "browser.h"
#include "core.h"
#include "scene_io.h"
#include "scene_json.h"
#include "shape_outline.h"
#include "stage_engine.h"

namespace bench {
namespace {

// What a refusal names in place of a file: the bench's scene, read by the stage.
constexpr std::string_view kSource = "the bench's scene";

int pixels(double size) { return static_cast<int>(std::ceil(size)); }

// The pairs the physics handed to its passes over the last step, where it counts them
// (5.2 on: pairStatistics, the one thing the engine keeps for the bench alone: the
// counts cannot be seen from outside, and cost an addition each); stage 5.1 is the
// book's and counts nothing.
template <class Physics>
std::optional<BenchWorld::PairCounts> pairs_counted(const Physics& physics) {
    if constexpr (requires { physics.pairStatistics(); }) {
        const auto& counted = physics.pairStatistics();
        return BenchWorld::PairCounts{static_cast<double>(counted.candidates),
                                      static_cast<double>(counted.narrow_tests),
                                      static_cast<double>(counted.skipped_tests), static_cast<double>(counted.passes)};
    } else {
        return std::nullopt;
    }
}

// Steps of dt / substeps per fixed step, where the stage has sub-steps (5.3); one before.
template <class Settings>
double substeps(const Settings& settings) {
    if constexpr (requires { settings.substeps; }) {
        return settings.substeps;
    } else {
        return 1.0;
    }
}

class StageWorld final : public BenchWorld {
public:
    StageWorld(const engine::WorldSettings& settings, const std::vector<engine::BodyDescription>& bodies)
        : window_(settings.dt * 1000.0,
                  browser::Document{browser::Canvas(pixels(settings.width), pixels(settings.height))}),
          core_(window_, settings) {
        engine::buildScene(core_, bodies);
    }

    Snapshot snapshot() const override {
        Snapshot bodies;
        bodies.reserve(core_.objectCount());
        for (std::size_t i = 0; i < core_.objectCount(); ++i) {
            const engine::RigidShape& shape = core_.object(i);
            bodies.push_back({.shape = oracle::outline(shape),
                              .is_static = shape.isStatic(),
                              .mass = shape.mass(),
                              .inertia = shape.isStatic() ? 0.0 : 1.0 / shape.invInertia(),
                              .velocity = shape.velocity(),
                              .angular_velocity = shape.angularVelocity()});
        }
        return bodies;
    }

    std::optional<PairCounts> pair_counts() const override {
        if (!totals_ || steps_ == 0) return std::nullopt;
        const auto steps = static_cast<double>(steps_);
        return PairCounts{totals_->candidates / steps, totals_->narrow_tests / steps, totals_->skipped_tests / steps,
                          totals_->passes / steps};
    }

protected:
    void advance(long steps) override {
        // The physics counts what its last collision pass did, which with sub-steps is
        // the last sub-step; the others did about as much.
        const double looks = substeps(core_.settings());
        for (long i = 0; i < steps; ++i) {
            core_.update();
            if (const auto pairs = pairs_counted(core_.physics())) {
                if (!totals_) totals_ = PairCounts{};
                totals_->candidates += looks * pairs->candidates;
                totals_->narrow_tests += looks * pairs->narrow_tests;
                totals_->skipped_tests += looks * pairs->skipped_tests;
                totals_->passes += looks * pairs->passes;
            }
        }
        steps_ += steps;
    }

private:
    browser::Window window_;
    engine::Core core_;
    std::optional<PairCounts> totals_;  // over steps_ steps; none where the stage counts none
    long steps_ = 0;
};

// The world as the stage reads it from the scene JSON of `world`.
engine::WorldSettings settings_of(const WorldDescription& world) {
    return engine::readScene(scene_json({world, {}}), kSource).world;
}

// The book's keys of the stage's world, as the bench describes them.
WorldDescription book_keys_of(const engine::WorldSettings& world) {
    return {.width = world.width,
            .height = world.height,
            .gravity = world.gravity,
            .dt = world.dt,
            .movement = world.movement,
            .relaxation_iterations = world.relaxation_iterations,
            .correction_rate = world.correction_rate,
            .positional_correction = world.positional_correction,
            .remove_out_of_bounds = world.remove_out_of_bounds};
}

BodyDescription body_of(const engine::BodyDescription& body) {
    return {.shape = body.shape == engine::ShapeType::Circle ? Shape::circle : Shape::rectangle,
            .center = body.center,
            .width = body.width,
            .height = body.height,
            .radius = body.radius,
            .mass = body.mass,
            .friction = body.friction,
            .restitution = body.restitution,
            .angle = body.angle,
            .velocity = body.velocity,
            .angular_velocity = body.angular_velocity};
}

class Adapter final : public StageEngine {
public:
    std::vector<std::string> world_keys() const override {
        engine::WorldSettings settings = engine::kBookWorld;
        std::vector<std::string> names;
        for (const browser::SceneKey& key : engine::worldKeys(settings)) names.emplace_back(key.name());
        return names;
    }

    WorldDescription book_world() const override { return book_keys_of(engine::kBookWorld); }

    std::unique_ptr<BenchWorld> world(const SceneDescription& scene) const override {
        const engine::Scene read = engine::readScene(scene_json(scene), kSource);
        return std::make_unique<StageWorld>(read.world, read.bodies);
    }

    SceneDescription read_scene(const std::string& text, std::string_view source) const override {
        const engine::Scene read = engine::readScene(text, source);
        SceneDescription scene{.world = book_keys_of(read.world)};
        for (const engine::BodyDescription& body : read.bodies) scene.bodies.push_back(body_of(body));
        return scene;
    }

    bool same_settings(const WorldDescription& a, const WorldDescription& b) const override {
        return settings_of(a) == settings_of(b);
    }
};

}  // namespace

std::unique_ptr<StageEngine> BENCH_STAGE_ENGINE() { return std::make_unique<Adapter>(); }

}  // namespace bench
