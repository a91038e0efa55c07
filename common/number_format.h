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

// Appends `value` with 17 significant digits, what %.17g prints: enough for std::strtod
// to give back the very same double, so that files of numbers (the state dump, a stage's
// events) compare number for number. std::to_chars ignores the C locale, which with a
// decimal comma would otherwise break both the CSV and strtod in another locale.
void append_round_trip(std::string& line, double value);

}  // namespace browser
