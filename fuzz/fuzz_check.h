#pragma once
// What a fuzz target does when a property fails: say which, and stop the run with a
// crash, so that libFuzzer keeps the input that did it (crash-<hash>) and reports it.

#include <cstdio>
#include <cstdlib>
#include <string_view>

namespace fuzz {

[[noreturn]] inline void property_failed(const char* property, const char* detail = "") {
    std::fprintf(stderr, "property failed: %s %s\n", property, detail);
    std::abort();
}

inline void require(bool holds, const char* property, const char* detail = "") {
    if (!holds) property_failed(property, detail);
}

// A message a terminal shows on one line: no line feed, no carriage return.
inline bool one_line(std::string_view message) { return message.find_first_of("\n\r") == std::string_view::npos; }

}  // namespace fuzz
