#include "measures.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <variant>
#include <vector>

namespace bench {
namespace {

// Radius of the smallest circle about the centre that holds the outline: two shapes
// whose circles are apart cannot overlap, which spares the exact test for most pairs.
double reach(const oracle::Shape& shape) {
    if (const auto* disc = std::get_if<oracle::Disc>(&shape)) return disc->radius;
    const auto& box = std::get<oracle::Box>(shape);
    return std::hypot(box.width, box.height) / 2;
}

}  // namespace

Penetration penetration(const Snapshot& bodies) {
    std::vector<double> reaches;
    reaches.reserve(bodies.size());
    for (const BodyState& body : bodies) reaches.push_back(reach(body.shape));

    Penetration found;
    double total = 0.0;
    for (std::size_t i = 0; i < bodies.size(); ++i) {
        const Vec2 ci = oracle::center(bodies[i].shape);
        for (std::size_t j = i + 1; j < bodies.size(); ++j) {
            if (bodies[i].is_static && bodies[j].is_static) continue;
            if (ci.distance(oracle::center(bodies[j].shape)) >= reaches[i] + reaches[j]) continue;
            const double depth = oracle::depth(bodies[i].shape, bodies[j].shape);
            if (depth <= 0) continue;
            found.max = std::max(found.max, depth);
            total += depth;
            ++found.pairs;
        }
    }
    if (found.pairs > 0) found.mean = total / static_cast<double>(found.pairs);
    return found;
}

double kinetic_energy(const Snapshot& bodies) {
    double energy = 0.0;
    for (const BodyState& body : bodies) {
        if (body.is_static) continue;
        energy += 0.5 * body.mass * body.velocity.dot(body.velocity);
        energy += 0.5 * body.inertia * body.angular_velocity * body.angular_velocity;
    }
    return energy;
}

std::size_t top_body(const Snapshot& bodies) {
    std::size_t top = bodies.size();
    double highest = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < bodies.size(); ++i) {
        const double y = oracle::center(bodies[i].shape).y;
        if (!bodies[i].is_static && y < highest) {
            highest = y;
            top = i;
        }
    }
    if (top == bodies.size()) throw std::invalid_argument("top_body: the scene has no moving body");
    return top;
}

}  // namespace bench
