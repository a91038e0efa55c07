// to_precision against what JavaScript's Number.prototype.toPrecision(3) prints.
#include <catch2/catch.hpp>

#include <limits>

#include "number_format.h"

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
