// A stage's engine behind bench::StageEngine. Written once, compiled once per stage:
// each time against that stage's engine library, which puts its folder on the include
// path and defines `engine` as a name of its own (engine_s5_1, ...), and with
// BENCH_STAGE_ENGINE as the factory to define (s5_1_engine, ...); bench/CMakeLists.txt
// says why. Where the stages differ (5.1
// counts no pairs, 5.3 has sub-steps, 5.7 tells collision events), the code asks the
// stage's types what they have rather than which stage it is.

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

// Whether the stage's core tells collision events to whoever reads them (5.7 on:
// Core::keepEvents, contact_events.h).
template <class Core>
constexpr bool tells_events() {
    return requires(Core & core) {
        core.keepEvents(true);
        core.events().events();
    };
}

// Asks the core to keep its events for a reader (the program's, as --events FILE does).
template <class Core>
void start_reading_events(Core& core) {
    if constexpr (tells_events<Core>()) core.keepEvents(true);
}

// What a game does with the step's events, at the least: goes through the list and
// looks at each (here, its kind), so that the cost timed is a reader's.
template <class Core>
void read_events(const Core& core, BenchWorld::EventCounts& counts) {
    if constexpr (tells_events<Core>()) {
        for (const auto& event : core.events().events()) {
            using Kind = decltype(event.kind);
            switch (event.kind) {
                case Kind::begin: counts.begins += 1; break;
                case Kind::end: counts.ends += 1; break;
                case Kind::hit: counts.hits += 1; break;
            }
        }
    }
}

class StageWorld final : public BenchWorld {
public:
    // With `read_events`, the step's collision events are read after every step (the
    // stage must tell them: world() checks).
    StageWorld(const engine::WorldSettings& settings, const std::vector<engine::BodyDescription>& bodies,
               bool read_events)
        : window_(settings.dt * 1000.0,
                  browser::Document{browser::Canvas(pixels(settings.width), pixels(settings.height))}),
          core_(window_, settings) {
        engine::buildScene(core_, bodies);
        if (read_events) {
            start_reading_events(core_);
            events_ = EventCounts{};
        }
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

    std::optional<EventCounts> event_counts() const override {
        if (!events_ || steps_ == 0) return std::nullopt;
        const auto steps = static_cast<double>(steps_);
        return EventCounts{events_->begins / steps, events_->ends / steps, events_->hits / steps};
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
            if (events_) read_events(core_, *events_);
        }
        steps_ += steps;
    }

private:
    browser::Window window_;
    engine::Core core_;
    std::optional<PairCounts> totals_;   // over steps_ steps; none where the stage counts none
    std::optional<EventCounts> events_;  // over steps_ steps; none where no one reads them
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
        const bool read_events = scene.world.events.value_or(false);
        if (read_events && !has_events()) {
            throw browser::SceneError(std::string(kSource) + ": events read after every step: this stage tells none");
        }
        const engine::Scene read = engine::readScene(scene_json(scene), kSource);
        return std::make_unique<StageWorld>(read.world, read.bodies, read_events);
    }

    SceneDescription read_scene(const std::string& text, std::string_view source) const override {
        const engine::Scene read = engine::readScene(text, source);
        SceneDescription scene{.world = book_keys_of(read.world)};
        for (const engine::BodyDescription& body : read.bodies) scene.bodies.push_back(body_of(body));
        return scene;
    }

    bool same_settings(const WorldDescription& a, const WorldDescription& b) const override {
        return settings_of(a) == settings_of(b) && a.events.value_or(false) == b.events.value_or(false);
    }

    bool has_events() const override { return tells_events<engine::Core>(); }
};

}  // namespace

std::unique_ptr<StageEngine> BENCH_STAGE_ENGINE() { return std::make_unique<Adapter>(); }

}  // namespace bench
