#pragma once
// Number.prototype.toPrecision, which the book's UI echo uses to print positions and
// angles: `digits` significant digits, trailing zeros kept ("1.50"), switching to
// exponent notation ("1.23e+3") when the number has more integer digits than that.

#include <string>

namespace browser {

std::string to_precision(double value, int digits);

}  // namespace browser
