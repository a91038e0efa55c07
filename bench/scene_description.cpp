#include "scene_description.h"

namespace bench {

std::string_view spelling(BroadPhase phase) {
    switch (phase) {
        case BroadPhase::bounding_circle: return "bounding_circle";
        case BroadPhase::all_pairs: return "all_pairs";
        case BroadPhase::grid: return "grid";
    }
    return "";
}

std::string_view spelling(Integrator integrator) {
    return integrator == Integrator::symplectic ? "symplectic" : "explicit";
}

std::string_view spelling(FrictionModel model) { return model == FrictionModel::book ? "book" : "coulomb"; }

std::string_view spelling(Solver solver) { return solver == Solver::book ? "book" : "sequential_impulse"; }

std::string_view spelling(PositionMethod method) {
    switch (method) {
        case PositionMethod::split_impulse: return "split_impulse";
        case PositionMethod::baumgarte: return "baumgarte";
        case PositionMethod::relax: return "relax";
    }
    return "";
}

std::string_view spelling(Shape shape) { return shape == Shape::circle ? "circle" : "rectangle"; }

int substeps_of(const WorldDescription& world) { return world.substeps.value_or(1); }

}  // namespace bench
