#include "chart_axes.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <initializer_list>

namespace bench::chart {
namespace {

// A step of 1, 2 or 5 times a power of ten, the smallest such at least `rough`: ticks
// then fall on round numbers.
double round_step(double rough) {
    const double power = std::pow(10.0, std::floor(std::log10(rough)));
    for (double multiple : {1.0, 2.0, 5.0}) {
        if (multiple * power >= rough * (1.0 - 1e-9)) return multiple * power;
    }
    return 10.0 * power;
}

// "0.25", "1500"; for very large or very fine numbers "2.5e6", "3e-5", "1e7".
std::string linear_label(double value, double step) {
    char text[64];
    const int step_digit = static_cast<int>(std::floor(std::log10(step) + 1e-9));
    const bool scientific = std::abs(value) >= 1e6 || step < 1e-4;
    if (std::abs(value) < 1e-6 * step) value = 0.0;  // what rounding left of a zero; also keeps "-0" away
    if (scientific && value == 0.0) return "0";
    if (!scientific) {
        std::snprintf(text, sizeof text, "%.*f", std::max(0, -step_digit), value);
        return text;
    }
    const int exponent = static_cast<int>(std::floor(std::log10(std::abs(value)) + 1e-9));
    const int decimals = std::clamp(exponent - step_digit, 0, 6);
    std::snprintf(text, sizeof text, "%.*f", decimals, value / std::pow(10.0, exponent));
    std::string mantissa = text;
    if (mantissa.find('.') != std::string::npos) {  // "2.50" -> "2.5", "1.0" -> "1": each label as short as it can be
        mantissa.erase(mantissa.find_last_not_of('0') + 1);
        if (mantissa.back() == '.') mantissa.pop_back();
    }
    return mantissa + "e" + std::to_string(exponent);
}

// Round numbers a step apart, the step chosen for about one tick per `spacing` pixels.
// `to_units` places a value on the axis (the identity on a linear axis).
template <typename ToUnits>
std::vector<Tick> linear_ticks(double low_value, double high_value, double length, double spacing, ToUnits to_units) {
    const double step = round_step((high_value - low_value) / std::max(2.0, length / spacing));
    std::vector<Tick> ticks;
    constexpr int kMostTicks = 50;  // a span below the values' precision repeats values
    const double first = std::ceil(low_value / step);
    for (int k = 0; k < kMostTicks && (first + k) * step <= high_value; ++k) {
        const double value = (first + k) * step;
        ticks.push_back({to_units(value), linear_label(value, step), 0, first + k});
    }
    return ticks;
}

// Decades as "0.01" ... "1000", wider ones as "1e4", "1e-3"; with a leading multiple ("2e5")
// for the ticks between decades.
std::string log_label(int multiple, int decade) {
    char text[64];
    if (decade >= -2 && decade <= 3) {
        std::snprintf(text, sizeof text, "%.*f", std::max(0, -decade), multiple * std::pow(10.0, decade));
    } else {
        std::snprintf(text, sizeof text, "%de%d", multiple, decade);
    }
    return text;
}

// Ticks at whole decades. A short axis also gets 2 and 5 times them (and, if that is still
// too few to read a scale from, every multiple); a long one with room to spare gets faint
// lines at 2 ... 9 times each decade, which show the axis is logarithmic at a glance.
AxisMarks log_marks(const Axis& axis) {
    AxisMarks marks;
    const double decade_pixels = axis.length() / (axis.high - axis.low);
    int stride = 1;  // decades apart, so that ticks stay at least 24 px apart
    for (int next : {2, 5, 10, 20, 50, 100}) {
        if (stride * decade_pixels >= 24.0) break;
        stride = next;
    }
    const int first = static_cast<int>(std::ceil(axis.low)), last = static_cast<int>(std::floor(axis.high));
    const auto inside = [&](double u) { return u >= axis.low && u <= axis.high; };
    for (int decade = first; decade <= last; ++decade) {
        if (decade % stride == 0) {
            marks.ticks.push_back(
                {static_cast<double>(decade), log_label(1, decade), 0, static_cast<double>(decade / stride)});
        }
    }
    const auto add_multiples = [&](std::initializer_list<int> multiples, int priority) {
        for (int decade = first - 1; decade <= last; ++decade) {
            for (int multiple : multiples) {
                const double u = decade + std::log10(multiple);
                if (inside(u)) marks.ticks.push_back({u, log_label(multiple, decade), priority, 0.0});
            }
        }
    };
    if (marks.ticks.size() < 3) add_multiples({2, 5}, 1);
    if (marks.ticks.size() < 2) add_multiples({3, 4, 6, 7, 8, 9}, 2);
    if (marks.ticks.size() < 2) {  // less than a factor of two: round values, placed by their logarithm
        marks.ticks = linear_ticks(std::pow(10.0, axis.low), std::pow(10.0, axis.high), axis.length(), 60.0,
                                   [](double value) { return std::log10(value); });
    }
    if (stride == 1 && decade_pixels >= 60.0 && marks.ticks.size() >= 2) {
        for (int decade = first - 1; decade <= last; ++decade) {
            for (int multiple = 2; multiple <= 9; ++multiple) {
                const double u = decade + std::log10(multiple);
                if (inside(u)) marks.minor_units.push_back(u);
            }
        }
    }
    return marks;
}

}  // namespace

bool on_scale(double value, bool log) {
    if (!std::isfinite(value)) return false;
    return log ? value > 0.0 : std::abs(value) <= kLargestLinear;
}

std::pair<double, double> axis_ends(const std::vector<double>& units, bool log) {
    if (units.empty()) return {0.0, 1.0};
    const auto [least, most] = std::minmax_element(units.begin(), units.end());
    double low = *least, high = *most;
    if (low == high) {
        const double room = log ? 0.5 : (low == 0.0 ? 1.0 : 0.1 * std::abs(low));
        return {low - room, high + room};
    }
    const double spare = 0.05 * (high - low);
    return {low - spare, high + spare};
}

AxisMarks axis_marks(const Axis& axis, double spacing) {
    if (axis.log) return log_marks(axis);
    return {linear_ticks(axis.low, axis.high, axis.length(), spacing, [](double value) { return value; }), {}};
}

std::vector<bool> labels_that_fit(const std::vector<Tick>& ticks, const Axis& axis, const std::vector<int>& extent,
                                  double gap) {
    const auto clear_of_shown = [&](const std::vector<bool>& shown, std::size_t i) {
        for (std::size_t j = 0; j < ticks.size(); ++j) {
            if (j == i || !shown[j]) continue;
            const double apart = std::abs(axis.pixel_of_units(ticks[i].units) - axis.pixel_of_units(ticks[j].units));
            if (apart < 0.5 * (extent[i] + extent[j]) + gap) return false;
        }
        return true;
    };
    std::vector<bool> shown(ticks.size(), false);
    for (std::size_t every = 1; every <= ticks.size(); ++every) {
        for (std::size_t i = 0; i < ticks.size(); ++i) {
            shown[i] = ticks[i].priority == 0 && std::fmod(ticks[i].place, static_cast<double>(every)) == 0.0;
        }
        bool any = false, clear = true;
        for (std::size_t i = 0; i < ticks.size(); ++i) {
            if (!shown[i]) continue;
            any = true;
            clear = clear && clear_of_shown(shown, i);
        }
        if (any && clear) break;
        std::fill(shown.begin(), shown.end(), false);
    }
    for (int priority = 1; priority <= 2; ++priority) {
        for (std::size_t i = 0; i < ticks.size(); ++i) {
            if (ticks[i].priority == priority) shown[i] = clear_of_shown(shown, i);
        }
    }
    return shown;
}

}  // namespace bench::chart
