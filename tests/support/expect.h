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

#include "checked_at.h"

namespace test {

template <class Value>
std::string shown(const Value& value) {
    return Catch::Detail::stringify(value);
}

// `got` == `expected`.
template <class Expected, class Got>
bool expectEqual(const char* quantity, const Expected& expected, const Got& got,
                 std::source_location where = std::source_location::current()) {
    const bool passed = got == expected;
    checkedAt(where, quantity, passed, "expected " + shown(expected) + ", got " + shown(got));
    return passed;
}

// `got` <= `most`.
template <class Bound, class Got>
bool expectAtMost(const char* quantity, const Bound& most, const Got& got,
                  std::source_location where = std::source_location::current()) {
    const bool passed = got <= most;
    checkedAt(where, quantity, passed, "expected at most " + shown(most) + ", got " + shown(got));
    return passed;
}

// `got` >= `least`.
template <class Bound, class Got>
bool expectAtLeast(const char* quantity, const Bound& least, const Got& got,
                   std::source_location where = std::source_location::current()) {
    const bool passed = got >= least;
    checkedAt(where, quantity, passed, "expected at least " + shown(least) + ", got " + shown(got));
    return passed;
}

// The same, ending the test case on failure, as REQUIRE does.
template <class Expected, class Got>
void requireEqual(const char* quantity, const Expected& expected, const Got& got,
                  std::source_location where = std::source_location::current()) {
    checkedAt(where, quantity, got == expected, "expected " + shown(expected) + ", got " + shown(got), true);
}

}  // namespace test
