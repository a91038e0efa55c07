#include "markdown.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace bench {

MarkdownTable::MarkdownTable(std::vector<std::string> headers) : headers_(std::move(headers)) {}

void MarkdownTable::add(std::vector<std::string> cells) {
    if (cells.size() != headers_.size()) throw std::invalid_argument("MarkdownTable::add: one cell per column");
    rows_.push_back(std::move(cells));
}

std::string MarkdownTable::text() const {
    const auto line = [](const std::vector<std::string>& cells) {
        std::string text = "|";
        for (const std::string& cell : cells) text += " " + cell + " |";
        return text + "\n";
    };
    std::string text = line(headers_);
    text += line(std::vector<std::string>(headers_.size(), "---"));
    for (const auto& row : rows_) text += line(row);
    return text + "\n";
}

std::string figure(double value, int significant) {
    if (std::isnan(value)) return "NaN";
    if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
    if (value == 0.0) return "0";
    const int magnitude = static_cast<int>(std::floor(std::log10(std::abs(value))));
    char text[48];
    if (magnitude < -5 || magnitude >= 9) {
        std::snprintf(text, sizeof text, "%.*e", significant - 1, value);
    } else {
        // Digits after the point: enough for `significant` in all, none below the units.
        const int decimals = std::max(0, significant - 1 - magnitude);
        const double unit = std::pow(10.0, magnitude - significant + 1);
        std::snprintf(text, sizeof text, "%.*f", decimals, std::round(value / unit) * unit);
    }
    return text;
}

std::string figure(const std::optional<double>& value, int significant) {
    return value ? figure(*value, significant) : "";
}

std::string percent(const std::optional<double>& ratio) {
    if (!ratio) return "";
    const std::string digits = figure(*ratio * 100.0, 3);
    return (*ratio > 0 ? "+" : "") + digits + "%";
}

}  // namespace bench
