#include "study.h"

namespace bench {

std::vector<Study> all_studies() {
    return {
        {"pyramid_10", [](const StudyContext& c) { return stacking_study(c, 10); }},
        {"pyramid_20", [](const StudyContext& c) { return stacking_study(c, 20); }},
        {"rain_100", [](const StudyContext& c) { return rain_study(c, 100); }},
        {"rain_400", [](const StudyContext& c) { return rain_study(c, 400); }},
        {"rain_1600", [](const StudyContext& c) { return rain_study(c, 1600); }},
        {"rain_1000", box2d_target_study},
        {"gas", gas_study},
        {"projectile", trajectory_study},
        {"slide", slide_study},
        {"heavy_on_light", heavy_on_light_study},
        {"slope", slope_study},
        {"thin_wall", tunnelling_study},
        {"scale", scale_study},
        {"pairs", pair_cost_study},
        {"speed", speed_study},
    };
}

}  // namespace bench
