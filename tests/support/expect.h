#pragma once
// Checks that say what they measure, in the book's words, with the value expected and
// the value got, where Catch alone would print "2 == 0":
//
//   test::expectEqual("pairs still overlapping 30 frames after M", 0, overlapping());
//
// prints, on failure,
//   s4_2_test.cpp:81: FAILED:
//     CHECK( pairs still overlapping 30 frames after M )
//   with expansion:
//     expected 0, got 2
// The quantity is a string literal (Catch keeps it as it is); anything more a reader
// needs (the case, the setting) goes in an INFO around the check.

#include <catch2/catch.hpp>

#include <source_location>
#include <string>
#include <type_traits>
#include <utility>

#include "checked_at.h"
#include "color_text.h"  // colours print as "(255, 165, 0) orange"
#include "near.h"        // Vec2s print as "(x, y)"

namespace test {

template <class Value>
std::string shown(const Value& value) {
    return Catch::Detail::stringify(value);
}

namespace detail {
// Whole numbers compare by value, signed or not (std::cmp_*): a count of 3 written as 3
// equals an object count of type std::size_t. Everything else compares as it is.
template <class A, class B>
constexpr bool integers =
    std::is_integral_v<A>&& std::is_integral_v<B> && !std::is_same_v<A, bool> && !std::is_same_v<B, bool>;
template <class A, class B>
bool same(const A& a, const B& b) {
    if constexpr (integers<A, B>) return std::cmp_equal(a, b);
    else return a == b;
}
template <class A, class B>
bool less(const A& a, const B& b) {
    if constexpr (integers<A, B>) return std::cmp_less(a, b);
    else return a < b;
}
// Not written as !less: a NaN is neither at most nor at least anything.
template <class A, class B>
bool atMost(const A& a, const B& b) {
    if constexpr (integers<A, B>) return std::cmp_less_equal(a, b);
    else return a <= b;
}
}  // namespace detail

// `got` == `expected`.
template <class Expected, class Got>
bool expectEqual(const char* quantity, const Expected& expected, const Got& got,
                 std::source_location where = std::source_location::current()) {
    const bool passed = detail::same(got, expected);
    checkedAt(where, quantity, passed, "expected " + shown(expected) + ", got " + shown(got));
    return passed;
}

// `got` <= `most`.
template <class Bound, class Got>
bool expectAtMost(const char* quantity, const Bound& most, const Got& got,
                  std::source_location where = std::source_location::current()) {
    const bool passed = detail::atMost(got, most);
    checkedAt(where, quantity, passed, "expected at most " + shown(most) + ", got " + shown(got));
    return passed;
}

// `got` >= `least`.
template <class Bound, class Got>
bool expectAtLeast(const char* quantity, const Bound& least, const Got& got,
                   std::source_location where = std::source_location::current()) {
    const bool passed = detail::atMost(least, got);
    checkedAt(where, quantity, passed, "expected at least " + shown(least) + ", got " + shown(got));
    return passed;
}

// `got` < `bound`.
template <class Bound, class Got>
bool expectBelow(const char* quantity, const Bound& bound, const Got& got,
                 std::source_location where = std::source_location::current()) {
    const bool passed = detail::less(got, bound);
    checkedAt(where, quantity, passed, "expected below " + shown(bound) + ", got " + shown(got));
    return passed;
}

// `got` > `bound`.
template <class Bound, class Got>
bool expectAbove(const char* quantity, const Bound& bound, const Got& got,
                 std::source_location where = std::source_location::current()) {
    const bool passed = detail::less(bound, got);
    checkedAt(where, quantity, passed, "expected above " + shown(bound) + ", got " + shown(got));
    return passed;
}

// The same, ending the test case on failure, as REQUIRE does.
template <class Expected, class Got>
void requireEqual(const char* quantity, const Expected& expected, const Got& got,
                  std::source_location where = std::source_location::current()) {
    checkedAt(where, quantity, detail::same(got, expected), "expected " + shown(expected) + ", got " + shown(got),
              true);
}

}  // namespace test
