#include "bench_world.h"

#include <cmath>

#include "browser.h"
#include "circle.h"
#include "core.h"
#include "rectangle.h"
#include "scene_io.h"
#include "shape_outline.h"

namespace bench {
namespace {

int pixels(double size) { return static_cast<int>(std::ceil(size)); }

class EngineWorld final : public BenchWorld {
public:
    explicit EngineWorld(const browser::SceneDescription& scene)
        : window_(scene.world.dt * 1000.0,
                  browser::Document{browser::Canvas(pixels(scene.world.width), pixels(scene.world.height))}),
          core_(window_, scene.world) {
        engine::buildScene(core_, scene.bodies);
    }

    Snapshot snapshot() const override {
        Snapshot bodies;
        bodies.reserve(core_.objectCount());
        for (std::size_t i = 0; i < core_.objectCount(); ++i) {
            const engine::RigidShape& shape = core_.object(i);
            bodies.push_back({.shape = test::outline(shape),
                              .is_static = shape.isStatic(),
                              .mass = shape.mass(),
                              .inertia = shape.isStatic() ? 0.0 : 1.0 / shape.invInertia(),
                              .velocity = shape.velocity(),
                              .angular_velocity = shape.angularVelocity()});
        }
        return bodies;
    }

    std::optional<PairCounts> pair_counts() const override {
        if (steps_ == 0) return std::nullopt;
        const auto steps = static_cast<double>(steps_);
        return PairCounts{totals_.candidates / steps, totals_.narrow_tests / steps};
    }

protected:
    void advance(long steps) override {
        // The physics counts what its last collision pass did, which with sub-steps is
        // the last sub-step; the others did about as much.
        const double substeps = core_.settings().substeps;
        for (long i = 0; i < steps; ++i) {
            core_.update();
            totals_.candidates += substeps * static_cast<double>(core_.physics().candidatePairs());
            totals_.narrow_tests += substeps * static_cast<double>(core_.physics().narrowPhaseTests());
        }
        steps_ += steps;
    }

private:
    browser::Window window_;
    engine::Core core_;
    PairCounts totals_;  // over steps_ steps
    long steps_ = 0;
};

}  // namespace

std::unique_ptr<BenchWorld> engine_world(const browser::SceneDescription& scene) {
    return std::make_unique<EngineWorld>(scene);
}

}  // namespace bench
