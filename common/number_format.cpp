#include "number_format.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <system_error>

namespace browser {

std::string to_precision(double value, int digits) {
    if (std::isnan(value)) return "NaN";
    if (std::isinf(value)) return value > 0 ? "Infinity" : "-Infinity";
    const std::string sign = value < 0 ? "-" : "";  // -0 prints as "0", as in JavaScript

    // The decimal digits of |value|, far more than needed: "d.ddd...e+XX".
    constexpr int kSpareDigits = 40;
    char buffer[96];
    std::snprintf(buffer, sizeof buffer, "%.*e", kSpareDigits, std::fabs(value));
    std::string mantissa = std::string(1, buffer[0]) + std::string(buffer + 2, kSpareDigits);
    int exponent = std::atoi(std::strchr(buffer, 'e') + 1);

    // Keep `digits` digits. JavaScript rounds a tie up (it picks the larger candidate),
    // where printf would round it to even, so the rounding is done here by hand.
    const bool round_up = mantissa[static_cast<std::size_t>(digits)] >= '5';
    mantissa.resize(static_cast<std::size_t>(digits));
    if (round_up) {
        int i = digits - 1;
        for (; i >= 0 && mantissa[static_cast<std::size_t>(i)] == '9'; --i) mantissa[static_cast<std::size_t>(i)] = '0';
        if (i >= 0) {
            ++mantissa[static_cast<std::size_t>(i)];
        } else {  // 9.99 -> 10.0: one digit more in front, the exponent grows
            mantissa.insert(mantissa.begin(), '1');
            mantissa.pop_back();
            ++exponent;
        }
    }
    if (value == 0.0) exponent = 0;

    if (exponent < -6 || exponent >= digits) {  // exponent form: "1.23e+3"
        std::string text = sign;
        text += mantissa.front();
        if (digits > 1) text.append(".").append(mantissa, 1);
        text.append(exponent < 0 ? "e-" : "e+").append(std::to_string(std::abs(exponent)));
        return text;
    }
    if (exponent < 0)  // "0.000123": zeros between the point and the first digit
        return sign + "0." + std::string(static_cast<std::size_t>(-exponent - 1), '0') + mantissa;
    const auto integer_digits = static_cast<std::size_t>(exponent + 1);
    if (integer_digits == mantissa.size()) return sign + mantissa;
    return sign + mantissa.substr(0, integer_digits) + "." + mantissa.substr(integer_digits);
}

// ECMAScript's Number::toString: with the shortest digits s (k of them) and the
// exponent n such that the value is 0.s times 10^n, the digits are placed by n.
std::string to_js_string(double value) {
    if (std::isnan(value)) return "NaN";
    if (value == 0.0) return "0";  // -0 too
    std::string text = value < 0 ? "-" : "";
    if (std::isinf(value)) return text.append("Infinity");

    // std::to_chars without a precision gives the shortest digits that read back as the
    // same double, and among those the nearest, which is the rule JavaScript follows.
    char buffer[64];
    const auto [end, error] =
        std::to_chars(buffer, buffer + sizeof buffer, std::fabs(value), std::chars_format::scientific);
    if (error != std::errc()) return "NaN";     // cannot happen: 64 characters hold any double
    const std::string scientific(buffer, end);  // "d.ddde+XX" or "de-XX"
    const std::size_t e = scientific.find('e');
    std::string digits = scientific.substr(0, 1);
    if (e > 1) digits.append(scientific, 2, e - 2);  // the digits after the point
    const int k = static_cast<int>(digits.size());
    const int n = std::atoi(scientific.c_str() + e + 1) + 1;

    // JavaScript's exponent form starts at 1e21 and below 1e-6.
    constexpr int kLargestPlainExponent = 21;
    constexpr int kSmallestPlainExponent = -5;
    if (k <= n && n <= kLargestPlainExponent) {  // a whole number: "5", "120"
        return text.append(digits).append(static_cast<std::size_t>(n - k), '0');
    }
    if (0 < n && n <= kLargestPlainExponent) {  // "6.993006993006993"
        const auto whole = static_cast<std::size_t>(n);
        return text.append(digits, 0, whole).append(".").append(digits, whole);
    }
    if (kSmallestPlainExponent <= n && n <= 0) {  // "0.00123"
        return text.append("0.").append(static_cast<std::size_t>(-n), '0').append(digits);
    }
    text += digits.front();  // "1.5e-7", "1e+21"
    if (k > 1) text.append(".").append(digits, 1);
    return text.append(n - 1 < 0 ? "e-" : "e+").append(std::to_string(std::abs(n - 1)));
}

void append_round_trip(std::string& line, double value) {
    constexpr int kRoundTripDigits = 17;  // enough to tell any two doubles apart
    char digits[32];                      // the longest, "-2.2250738585072014e-308", needs 24
    const auto end =
        std::to_chars(digits, digits + sizeof digits, value, std::chars_format::general, kRoundTripDigits).ptr;
    line.append(digits, end);
}

}  // namespace browser
