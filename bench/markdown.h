#pragma once
// Markdown for results.md: tables, and numbers in as many digits as they deserve.

#include <optional>
#include <string>
#include <vector>

namespace bench {

class MarkdownTable {
public:
    explicit MarkdownTable(std::vector<std::string> headers);
    void add(std::vector<std::string> cells);  // one cell per header
    std::string text() const;                  // ends with a blank line

private:
    std::vector<std::string> headers_;
    std::vector<std::vector<std::string>> rows_;
};

// `significant` digits, without exponent for everyday sizes: 1234.5 -> "1230" (3),
// 0.000123 -> "0.000123", 1.5e-9 -> "1.5e-09". NaN and infinity are spelled out.
std::string figure(double value, int significant = 3);
// "" when there is no value.
std::string figure(const std::optional<double>& value, int significant = 3);
// 0.0123 -> "+1.23%": a relative error, signed.
std::string percent(const std::optional<double>& ratio);

}  // namespace bench
