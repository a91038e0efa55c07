#pragma once
// The one way tests compare numbers that need not be bit for bit equal:
//
//   CHECK_THAT(ball.center().x, test::near(100 + 30 * dt, 1e-12));
//   CHECK_THAT(ball.center(), test::near(Vec2{100, 50}, 1e-12));  // each coordinate
//
// passes when |actual - expected| <= tolerance, and in no other case (NaN never
// passes). The tolerance is absolute, in the unit of the number: px, px/s, rad.
//
// Why not Catch2's Approx(x) with .margin(m) added: Approx keeps its default relative tolerance,
// about 1.2e-5 of x, next to the margin, and passes a value within either. "To 1e-9 px"
// written that way on a value near 20 px really allows 2.4e-4 px, and a bug of 1e-9 px
// slips through. Here the tolerance written is the tolerance applied.
//
// A failure prints the expected value to 17 digits, the tolerance, and by how much the
// actual value missed. Catch prints a Vec2 as "(x, y)" (the StringMaker below), each
// coordinate in the fewest digits that read back as the same double, as JavaScript
// prints numbers: (-0.6, -0.8), never {?}.

#include <catch2/catch.hpp>

#include <cmath>
#include <sstream>
#include <string>

#include "number_format.h"
#include "vec2.h"

namespace Catch {
template <>
struct StringMaker<lib::Vec2> {
    static std::string convert(const lib::Vec2& v) {
        // Appended piece by piece: g++ 12 warns wrongly about "(" + a temporary string.
        std::string text = "(";
        text += browser::to_js_string(v.x);
        text += ", ";
        text += browser::to_js_string(v.y);
        text += ")";
        return text;
    }
};
}  // namespace Catch

namespace test {

namespace detail {
inline std::string exactly(double value) {
    std::ostringstream text;
    text.precision(17);
    text << value;
    return text.str();
}
}  // namespace detail

class NearMatcher final : public Catch::MatcherBase<double> {
public:
    NearMatcher(double expected, double tolerance) : expected_(expected), tolerance_(tolerance) {}

    bool match(const double& actual) const override {
        missed_by_ = std::abs(actual - expected_);
        return missed_by_ <= tolerance_;
    }
    std::string describe() const override {
        return "is within " + detail::exactly(tolerance_) + " of " + detail::exactly(expected_) + " (it is " +
               detail::exactly(missed_by_) + " away)";
    }

private:
    double expected_;
    double tolerance_;
    mutable double missed_by_ = 0.0;  // of the value last matched, for the message
};

class NearVecMatcher final : public Catch::MatcherBase<lib::Vec2> {
public:
    NearVecMatcher(lib::Vec2 expected, double tolerance) : expected_(expected), tolerance_(tolerance) {}

    bool match(const lib::Vec2& actual) const override {
        return std::abs(actual.x - expected_.x) <= tolerance_ && std::abs(actual.y - expected_.y) <= tolerance_;
    }
    std::string describe() const override {
        return "is within " + detail::exactly(tolerance_) + " of " + Catch::Detail::stringify(expected_) +
               " in each coordinate";
    }

private:
    lib::Vec2 expected_;
    double tolerance_;
};

// |actual - expected| <= tolerance.
inline NearMatcher near(double expected, double tolerance) { return {expected, tolerance}; }
// Each coordinate within `tolerance` of the expected one.
inline NearVecMatcher near(lib::Vec2 expected, double tolerance) { return {expected, tolerance}; }

}  // namespace test
