#pragma once
// The live session's window, made with SDL2 (Debian: libsdl2-dev). SDL2 is optional
// like giflib: a build without it still has this header, but live_window_supported()
// (build_features.h) says no and --live is refused with the one line kNoLiveSupport.
//
// The left mouse button pressed, the pointer moved and the button let go go to the
// session as pointer inputs at window px, which are the picture's (live.h).
// Keys: a-z, 0-9 (and the keypad's), comma, Up, Down and slash go to the page, held keys
// repeating as a browser repeats them; Space pauses, period steps, F12 saves the page
// shown as a PNG, Escape ends, and so does the window's close button (live.h says what
// each does to the frames).
//
// Two test hooks, hidden from --help, let a test drive the window where no one types:
//   --live-events FILE       tokens NAME@REFRESH separated by spaces: before it looks
//                            for input at refresh REFRESH (1 is the first after frame 0
//                            shows), the window pushes a key-down event for the SDL key
//                            named NAME ("F", "Space", ",", ".", "F12", "Escape", "Up") into
//                            SDL's event queue, or for NAME "close" the close button's
//                            event, or for "press:X,Y", "move:X,Y", "release:X,Y" the left
//                            mouse button's at window px (X, Y); from there on they go the
//                            way a real key's or mouse's do.
//   --live-screenshot FILE   when the session ends, writes the last picture the window
//                            showed, as SDL reads it back from the renderer, as a PNG.

#include <filesystem>
#include <memory>
#include <stdexcept>
#include <string>

#include "build_features.h"  // kNoLiveSupport
#include "live.h"

namespace browser {

struct LiveWindowError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

struct LiveWindowSettings {
    std::string title;
    double frame_ms = 1000.0 / 60.0;   // the shortest real time between two frames
    std::filesystem::path events;      // test hook: --live-events
    std::filesystem::path screenshot;  // test hook: --live-screenshot
};

// Starts SDL's video; the window itself opens at the first picture shown, sized to
// it. Throws LiveWindowError with a one-line reason (no display, a bad events file).
std::unique_ptr<Screen> open_live_window(const LiveWindowSettings& settings);

}  // namespace browser
