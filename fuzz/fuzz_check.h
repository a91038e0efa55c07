#pragma once
// What a fuzz target does when a property fails: say which, and stop the run with a
// crash, so that libFuzzer keeps the input that did it (crash-<hash>) and reports it.

#include <cstddef>
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

// A message a terminal shows as one line of text: valid UTF-8 with no control
// character at all (no line feed, carriage return, escape sequence or DEL), so what a
// user typed or a file held can neither break the line nor repaint the terminal.
inline bool one_line(std::string_view message) {
    std::size_t i = 0;
    while (i < message.size()) {
        const auto lead = static_cast<unsigned char>(message[i]);
        if (lead < 0x20 || lead == 0x7f) return false;
        // A lead byte says how many continuation bytes (10xxxxxx) follow; overlong
        // forms (C0, C1, E0 80.., F0 80..), surrogates (ED A0..) and code points above
        // U+10FFFF (F4 90.., F5..) are not UTF-8.
        std::size_t extra = 0;
        unsigned char low = 0x80, high = 0xbf;  // the range of the first continuation byte
        if (lead < 0x80) extra = 0;
        else if (lead >= 0xc2 && lead <= 0xdf) extra = 1;
        else if (lead >= 0xe0 && lead <= 0xef) {
            extra = 2;
            if (lead == 0xe0) low = 0xa0;
            if (lead == 0xed) high = 0x9f;
        } else if (lead >= 0xf0 && lead <= 0xf4) {
            extra = 3;
            if (lead == 0xf0) low = 0x90;
            if (lead == 0xf4) high = 0x8f;
        } else return false;
        if (extra > message.size() - 1 - i) return false;  // cut off at the end
        for (std::size_t k = 1; k <= extra; ++k) {
            const auto next = static_cast<unsigned char>(message[i + k]);
            const unsigned char lowest = k == 1 ? low : 0x80, highest = k == 1 ? high : 0xbf;
            if (next < lowest || next > highest) return false;
        }
        i += extra + 1;
    }
    return true;
}

}  // namespace fuzz
