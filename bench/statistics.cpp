#include "statistics.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace bench {

std::vector<ChartPoint> pareto_front(const std::vector<ChartPoint>& points) {
    // b beats a when it is no worse on either axis and better on one.
    const auto beats = [](const ChartPoint& b, const ChartPoint& a) {
        return b.x <= a.x && b.y <= a.y && (b.x < a.x || b.y < a.y);
    };
    std::vector<ChartPoint> front;
    for (const ChartPoint& a : points) {
        if (std::isnan(a.x) || std::isnan(a.y)) continue;
        const bool beaten = std::any_of(points.begin(), points.end(), [&](const ChartPoint& b) { return beats(b, a); });
        if (!beaten) front.push_back(a);
    }
    std::stable_sort(front.begin(), front.end(),
                     [](const ChartPoint& a, const ChartPoint& b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
    return front;
}

double fitted_exponent(const std::vector<ChartPoint>& points, double x_min, double x_max) {
    // With u = log x and v = log y the power law is the line v = log a + b u, and the
    // least-squares slope is b = sum (u - mean u)(v - mean v) / sum (u - mean u)^2.
    std::vector<std::pair<double, double>> logs;
    for (const ChartPoint& p : points) {
        const bool usable =
            p.x >= x_min && p.x <= x_max && p.x > 0.0 && p.y > 0.0 && std::isfinite(p.x) && std::isfinite(p.y);
        if (usable) logs.emplace_back(std::log(p.x), std::log(p.y));
    }
    if (logs.empty()) return std::nan("");
    double mean_u = 0.0, mean_v = 0.0;
    for (const auto& [u, v] : logs) {
        mean_u += u;
        mean_v += v;
    }
    mean_u /= static_cast<double>(logs.size());
    mean_v /= static_cast<double>(logs.size());
    double spread_uv = 0.0, spread_uu = 0.0;
    for (const auto& [u, v] : logs) {
        spread_uv += (u - mean_u) * (v - mean_v);
        spread_uu += (u - mean_u) * (u - mean_u);
    }
    if (spread_uu == 0.0) return std::nan("");  // one x only: every slope fits as well
    return spread_uv / spread_uu;
}

}  // namespace bench
