#include "number_format.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>

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

}  // namespace browser
