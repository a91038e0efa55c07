#pragma once
// How JavaScript turns numbers into text, for the book's UI echo.

#include <string>

namespace browser {

// Number.prototype.toPrecision, which the echo uses to print positions and angles:
// `digits` significant digits, trailing zeros kept ("1.50"), switching to exponent
// notation ("1.23e+3") when the number has more integer digits than that.
std::string to_precision(double value, int digits);

// What JavaScript prints for a number with no format asked for (String(x), or x joined
// to a string with +): the fewest digits that still read back as exactly the same
// double ("0.1", "6.993006993006993"), no ".0" on whole numbers ("5"), exponent
// notation from 1e21 up and below 1e-6 ("1e+21", "1.5e-7"), and "Infinity",
// "-Infinity" and "NaN".
std::string to_js_string(double value);

}  // namespace browser
