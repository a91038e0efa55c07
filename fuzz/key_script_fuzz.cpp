// Fuzz target: the key scripts of --keys and the key lists of a page (common/keys.cpp).
// The input is the script's text.
//
// Properties, besides "no crash, no sanitizer report, no exception but KeyScriptError":
//  - a refusal is one line;
//  - an accepted script written back with text() reads back to the same presses, and
//    text() of that is the same text again;
//  - no press lies after lastFrame(), and the script's last frame has one.

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "fuzz_check.h"
#include "keys.h"

namespace {

void one_line(const browser::KeyScriptError& refusal) {
    fuzz::require(fuzz::one_line(refusal.what()), "a refusal is one line:", refusal.what());
}

void check_script(std::string_view text) {
    browser::KeyScript script;
    try {
        script = browser::KeyScript::parse(text);
    } catch (const browser::KeyScriptError& refusal) {
        one_line(refusal);
        return;
    }
    const std::string written = script.text();
    browser::KeyScript again;
    try {
        again = browser::KeyScript::parse(written);
    } catch (const browser::KeyScriptError& refusal) {
        fuzz::property_failed("text() of an accepted script reads back:", refusal.what());
    }
    fuzz::require(again == script, "text() reads back to the same presses:", written.c_str());
    fuzz::require(again.text() == written, "text() is stable:", written.c_str());
    const int last = script.lastFrame();
    fuzz::require(script.empty() == (last == -1), "an empty script has last frame -1");
    if (last >= 0) {
        // A drag's last point may repeat the one before (the pointer held still: no
        // event), so a drag ends at the last frame when its release is the frame after.
        const bool drag_ends_there = !script.drags().empty() && script.drags().back().releaseFrame() == last + 1;
        fuzz::require(!script.pressesAt(last).empty() || drag_ends_there,
                      "the last frame has a press or a drag's last point");
        fuzz::require(script.pressesAt(last + 1).empty(), "no press after the last frame");
        // A drag lets go one frame after its last point, so after the last frame the
        // pointer may still be released, and do nothing else.
        for (const browser::PointerEvent& event : script.pointerAt(last + 1))
            fuzz::require(event.kind == browser::PointerEvent::Kind::release,
                          "after the last frame the pointer is only let go");
    }
}

void check_key_set(std::string_view text) {
    try {
        const browser::KeySet keys = browser::KeySet::parse(text);
        // text() lists the members in a form parse() reads: ", " between them.
        std::string names = keys.text();
        for (char& c : names)
            if (c == ',') c = ' ';
        // "comma" is a key name, so the spaces put in above leave it whole.
        const browser::KeySet again = browser::KeySet::parse(names);
        fuzz::require(again.text() == keys.text(), "a key set's text() reads back:", keys.text().c_str());
    } catch (const browser::KeyScriptError& refusal) {
        one_line(refusal);
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    check_script(text);
    check_key_set(text);
    return 0;
}
