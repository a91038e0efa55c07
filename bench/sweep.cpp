#include "sweep.h"

#include <algorithm>
#include <cmath>

namespace bench {
namespace {

using browser::WorldSettings;

struct Variant {
    std::string label;
    WorldSettings world;
};

std::vector<Variant> variants(const WorldSettings& base, Knob knob) {
    std::vector<Variant> list;
    const auto add = [&](std::string label, auto change) {
        WorldSettings world = base;
        change(world);
        list.push_back({std::move(label), world});
    };
    switch (knob) {
        case Knob::relaxation_iterations:
            for (int passes : {1, 2, 4, 8, 15, 30}) {
                add("passes " + std::to_string(passes), [=](WorldSettings& w) { w.relaxation_iterations = passes; });
            }
            break;
        case Knob::dt:
            for (int per_second : {30, 60, 120, 240}) {
                add(dt_label(1.0 / per_second), [=](WorldSettings& w) { w.dt = 1.0 / per_second; });
            }
            break;
        case Knob::substeps:
            for (int substeps : {1, 2, 4, 8}) {
                add("substeps " + std::to_string(substeps), [=](WorldSettings& w) { w.substeps = substeps; });
            }
            break;
        case Knob::broad_phase:
            for (auto phase : {browser::BroadPhase::bounding_circle, browser::BroadPhase::all_pairs,
                               browser::BroadPhase::grid}) {
                add(std::string(browser::knob_name(phase)), [=](WorldSettings& w) { w.broad_phase = phase; });
            }
            break;
        case Knob::integrator:
            for (auto integrator : {browser::Integrator::symplectic, browser::Integrator::explicit_euler}) {
                add(std::string(browser::knob_name(integrator)), [=](WorldSettings& w) { w.integrator = integrator; });
            }
            break;
        case Knob::friction_model:
            for (auto model : {browser::FrictionModel::book, browser::FrictionModel::coulomb}) {
                add("friction " + std::string(browser::knob_name(model)),
                    [=](WorldSettings& w) { w.friction_model = model; });
            }
            break;
        case Knob::rotation:
            add("rotation off", [](WorldSettings& w) { w.rotation = false; });
            break;
        case Knob::friction:
            add("friction off", [](WorldSettings& w) { w.friction = false; });
            break;
    }
    return list;
}

std::string knob_key(Knob knob) {
    switch (knob) {
        case Knob::relaxation_iterations: return "relaxation_iterations";
        case Knob::dt: return "dt";
        case Knob::substeps: return "substeps";
        case Knob::broad_phase: return "broad_phase";
        case Knob::integrator: return "integrator";
        case Knob::friction_model: return "friction_model";
        case Knob::rotation: return "rotation";
        case Knob::friction: return "friction";
    }
    return "";
}

// One value besides the scene's: the first on the knob's list that differs from it, the
// cheapest (but for substeps, where it is 2).
std::vector<Variant> one_variant(const WorldSettings& base, std::vector<Variant> all) {
    std::erase_if(all, [&](const Variant& v) { return v.world == base; });
    if (all.size() > 1) all.resize(1);
    return all;
}

}  // namespace

std::vector<Setting> one_at_a_time(const WorldSettings& base, const std::vector<Sweep>& sweeps, bool quick) {
    std::vector<Setting> settings{{"", "scene", base}};
    for (const Sweep& sweep : sweeps) {
        std::vector<Variant> list = variants(base, sweep.knob);
        if (quick || sweep.range == Range::one) list = one_variant(base, std::move(list));
        for (Variant& variant : list) {
            const bool seen = std::any_of(settings.begin(), settings.end(),
                                          [&](const Setting& s) { return s.world == variant.world; });
            if (!seen) settings.push_back({knob_key(sweep.knob), std::move(variant.label), variant.world});
        }
    }
    return settings;
}

std::string dt_label(double dt) {
    const double per_second = 1.0 / dt;
    if (std::abs(per_second - std::round(per_second)) < 1e-9 * per_second) {
        return "dt 1/" + std::to_string(static_cast<long>(std::round(per_second)));
    }
    return "dt " + std::to_string(dt);
}

}  // namespace bench
