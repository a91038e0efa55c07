// to_precision and to_js_string against what JavaScript prints: toPrecision(3), and a
// number's default text (String(x)). Every expected string here is what a browser's
// console prints for the same expression.
#include <catch2/catch.hpp>

#include <limits>

#include "number_format.h"

using browser::to_js_string;
using browser::to_precision;

TEST_CASE("number_format: fixed notation keeps trailing zeros") {
    CHECK(to_precision(400, 3) == "400");
    CHECK(to_precision(225.5, 3) == "226");  // an exact tie rounds up, as JavaScript does,
    CHECK(to_precision(300.5, 3) == "301");  // not to even, as printf would
    CHECK(to_precision(-300.5, 3) == "-301");
    CHECK(to_precision(1.5, 3) == "1.50");
    CHECK(to_precision(0, 3) == "0.00");
    CHECK(to_precision(-0.0, 3) == "0.00");
    CHECK(to_precision(-12.345678, 3) == "-12.3");
    CHECK(to_precision(0.000123456, 3) == "0.000123");
}

TEST_CASE("number_format: exponent notation when the integer part has too many digits") {
    CHECK(to_precision(1234, 3) == "1.23e+3");
    CHECK(to_precision(-98765, 3) == "-9.88e+4");
    CHECK(to_precision(999.6, 3) == "1.00e+3");  // rounding carries into a new digit
    CHECK(to_precision(1.5e-7, 3) == "1.50e-7");
}

TEST_CASE("number_format: rounding that carries is read after rounding") {
    CHECK(to_precision(9.996, 3) == "10.0");
    CHECK(to_precision(99.96, 3) == "100");
}

TEST_CASE("number_format: non-finite numbers print as JavaScript does") {
    CHECK(to_precision(std::numeric_limits<double>::quiet_NaN(), 3) == "NaN");
    CHECK(to_precision(std::numeric_limits<double>::infinity(), 3) == "Infinity");
    CHECK(to_precision(-std::numeric_limits<double>::infinity(), 3) == "-Infinity");
}

TEST_CASE("number_format: a number's default text is its shortest round-trip digits") {
    CHECK(to_js_string(5) == "5");  // whole numbers without ".0"
    CHECK(to_js_string(-42) == "-42");
    CHECK(to_js_string(0.1) == "0.1");
    CHECK(to_js_string(0.1 + 0.2) == "0.30000000000000004");
    CHECK(to_js_string(1 / 0.143) == "6.993006993006993");  // the echo's mass 7
    CHECK(to_js_string(2.5) == "2.5");
    CHECK(to_js_string(123.456) == "123.456");
    CHECK(to_js_string(0.0012345679012345679) == "0.0012345679012345679");
    CHECK(to_js_string(-0.0) == "0");
}

TEST_CASE("number_format: a number's default text goes to exponent form from 1e21 and below 1e-6") {
    CHECK(to_js_string(1e20) == "100000000000000000000");
    CHECK(to_js_string(123456789012345680000.0) == "123456789012345680000");
    CHECK(to_js_string(1e21) == "1e+21");
    CHECK(to_js_string(1.5e300) == "1.5e+300");
    CHECK(to_js_string(0.000001) == "0.000001");
    CHECK(to_js_string(0.0000015) == "0.0000015");
    CHECK(to_js_string(1e-7) == "1e-7");
    CHECK(to_js_string(-1.5e-7) == "-1.5e-7");
    CHECK(to_js_string(5e-324) == "5e-324");
    CHECK(to_js_string(std::numeric_limits<double>::max()) == "1.7976931348623157e+308");
}

TEST_CASE("number_format: a number's default text for the non-finite numbers") {
    CHECK(to_js_string(std::numeric_limits<double>::quiet_NaN()) == "NaN");
    CHECK(to_js_string(std::numeric_limits<double>::infinity()) == "Infinity");
    CHECK(to_js_string(-std::numeric_limits<double>::infinity()) == "-Infinity");
}
