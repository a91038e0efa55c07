#include "sweep.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "markdown.h"

namespace bench {
namespace {

struct Variant {
    std::string label;
    WorldDescription world;
};

// One case per knob, each a line or two: the list of every value the bench tries reads
// best as one table, so this function is long on purpose (over the house's 80 lines).
std::vector<Variant> variants(const WorldDescription& base, Knob knob) {
    std::vector<Variant> list;
    const auto add = [&](std::string label, auto change) {
        WorldDescription world = base;
        change(world);
        list.push_back({std::move(label), world});
    };
    using W = WorldDescription;
    switch (knob) {
        case Knob::relaxation_iterations:
            for (int passes : {1, 2, 4, 8, 15, 30}) {
                add("passes " + std::to_string(passes), [=](W& w) { w.relaxation_iterations = passes; });
            }
            break;
        case Knob::correction_rate:
            for (double rate : {0.2, 0.4, 0.6, 0.8, 1.0}) {
                add("correction " + figure(rate, 1), [=](W& w) { w.correction_rate = rate; });
            }
            break;
        case Knob::dt:
            for (int per_second : {30, 60, 120, 240}) {
                add(dt_label(1.0 / per_second), [=](W& w) { w.dt = 1.0 / per_second; });
            }
            break;
        case Knob::broad_phase:
            for (BroadPhase phase : {BroadPhase::bounding_circle, BroadPhase::all_pairs, BroadPhase::grid}) {
                add(std::string(spelling(phase)), [=](W& w) { w.broad_phase = phase; });
            }
            break;
        case Knob::substeps:
            for (int substeps : {1, 2, 4, 8}) {
                add("substeps " + std::to_string(substeps), [=](W& w) { w.substeps = substeps; });
            }
            break;
        case Knob::integrator:
            for (Integrator integrator : {Integrator::symplectic, Integrator::explicit_euler}) {
                add(std::string(spelling(integrator)), [=](W& w) { w.integrator = integrator; });
            }
            break;
        case Knob::friction_model:
            for (FrictionModel model : {FrictionModel::book, FrictionModel::coulomb}) {
                add("friction " + std::string(spelling(model)), [=](W& w) { w.friction_model = model; });
            }
            break;
        case Knob::rotation: add("rotation off", [](W& w) { w.rotation = false; }); break;
        case Knob::friction: add("friction off", [](W& w) { w.friction = false; }); break;
        case Knob::solver:
            // Where nothing rests (no gravity) every collision should bounce, so the
            // restitution threshold is 0 there, as for Box2D's row (box2d_world.cpp).
            add("sequential impulse", [](W& w) {
                w.solver = Solver::sequential_impulse;
                if (w.gravity == Vec2{}) w.restitution_threshold = 0.0;
            });
            break;
        case Knob::velocity_iterations:
            for (int iterations : {2, 4, 8, 12, 16}) {
                add("SI, iterations " + std::to_string(iterations), [=](W& w) {
                    w.solver = Solver::sequential_impulse;
                    w.velocity_iterations = iterations;
                });
            }
            break;
        case Knob::warm_starting:
            add("SI, no warm start", [](W& w) {
                w.solver = Solver::sequential_impulse;
                w.warm_starting = false;
            });
            break;
        case Knob::position_method:
            for (PositionMethod method :
                 {PositionMethod::split_impulse, PositionMethod::baumgarte, PositionMethod::relax}) {
                add("SI, " + std::string(spelling(method)), [=](W& w) {
                    w.solver = Solver::sequential_impulse;
                    w.position_method = method;
                });
            }
            break;
        case Knob::sleep:
            // 5.5 sleeps by default; the book's passes keep a pile creeping, so sleep pays
            // with the sequential impulses (ch5_demo/5.5_sleeping/README.md).
            add("sleep off", [](W& w) { w.sleep = false; });
            add("SI, sleep on", [](W& w) {
                w.solver = Solver::sequential_impulse;
                w.sleep = true;
            });
            break;
    }
    return list;
}

std::string knob_key(Knob knob) {
    switch (knob) {
        case Knob::relaxation_iterations: return "relaxation_iterations";
        case Knob::correction_rate: return "correction_rate";
        case Knob::dt: return "dt";
        case Knob::broad_phase: return "broad_phase";
        case Knob::substeps: return "substeps";
        case Knob::integrator: return "integrator";
        case Knob::friction_model: return "friction_model";
        case Knob::rotation: return "rotation";
        case Knob::friction: return "friction";
        case Knob::solver: return "solver";
        case Knob::velocity_iterations: return "velocity_iterations";
        case Knob::warm_starting: return "warm_starting";
        case Knob::position_method: return "position_method";
        case Knob::sleep: return "sleep";
    }
    return "";
}

// Settings in the order they are listed, each with its world as its stage reads it, so
// that two settings the stage reads alike compare equal.
class SettingList {
public:
    // False, and nothing added, when the stage reads the world as a setting already listed.
    bool add(Setting setting) {
        WorldDescription as_read = resolved(setting.stage, setting.world);
        for (std::size_t i = 0; i < settings_.size(); ++i) {
            if (settings_[i].stage == setting.stage && as_read_[i] == as_read) return false;
        }
        settings_.push_back(std::move(setting));
        as_read_.push_back(std::move(as_read));
        return true;
    }
    std::vector<Setting> settings() && { return std::move(settings_); }

private:
    std::vector<Setting> settings_;
    std::vector<WorldDescription> as_read_;
};

}  // namespace

std::vector<Setting> one_at_a_time(const WorldDescription& base, const std::vector<Stage>& stages,
                                   const std::vector<Sweep>& sweeps, bool quick) {
    SettingList list;
    // Stage 5.4 runs a scene's own world as 5.3 does, bit for bit (its solver is the
    // book's unless a scene says otherwise: the identity test), so it has no row of its
    // own for it; its rows are its solver's. Nor has 5.7, which runs it as 5.6 does
    // while no one reads its events (its rows are the speed study's, with them read).
    // Stages 5.5 and 5.6 do have one: they sleep, and 5.6 sweeps fast shapes, unless a
    // scene says otherwise.
    for (Stage stage : stages) {
        if (!runs_scene_as_stage_before(stage)) list.add({stage, "", "scene", base});
    }
    for (const Sweep& sweep : sweeps) {
        const bool one = quick || sweep.range == Range::one;
        for (Variant& variant : variants(base, sweep.knob)) {
            const std::optional<Stage> stage = oldest_expressing(stages, variant.world);
            if (!stage) continue;
            const bool added = list.add({*stage, knob_key(sweep.knob), std::move(variant.label), variant.world});
            if (added && one) break;
        }
    }
    // The scene on each stage first, then each stage's knobs, the stages in the order given.
    std::vector<Setting> settings = std::move(list).settings();
    const auto place = [&](const Setting& setting) {
        const auto stage = std::find(stages.begin(), stages.end(), setting.stage) - stages.begin();
        return std::pair{!setting.varied.empty(), stage};
    };
    std::stable_sort(settings.begin(), settings.end(),
                     [&](const Setting& a, const Setting& b) { return place(a) < place(b); });
    return settings;
}

std::string dt_label(double dt) {
    const double per_second = 1.0 / dt;
    if (std::abs(per_second - std::round(per_second)) < 1e-9 * per_second) {
        return "dt 1/" + std::to_string(static_cast<long>(std::round(per_second)));
    }
    return "dt " + std::to_string(dt);
}

std::string knob_title(const std::string& key) {
    if (key == "relaxation_iterations") return "passes";
    std::string title = key;
    std::replace(title.begin(), title.end(), '_', ' ');
    return title;
}

}  // namespace bench
