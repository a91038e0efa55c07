#pragma once
// What this build can do beyond writing PNG pictures. Two Debian packages are optional,
// so that a reader's first build needs as little as possible: giflib (libgif-dev) writes
// animation.gif and SDL2 (libsdl2-dev) opens the --live window. CMake finds them or says
// it did not (common/CMakeLists.txt); the answer is a fact of the build, asked here by
// whoever needs it (the command line, the page's writers, the tests), so none of them
// has to reach into the GIF writer or the window to learn it.

#include <string_view>

namespace browser {

// True when this build was made with giflib (BROWSER_HAS_GIF=1).
bool gif_supported();

// True when this build was made with SDL2 (BROWSER_HAS_SDL=1).
bool live_window_supported();

inline constexpr std::string_view kNoGifSupport =
    "--gif: this build has no GIF support; install the Debian package libgif-dev and rebuild";

inline constexpr std::string_view kNoLiveSupport =
    "--live: this build has no window (SDL2); install the Debian package libsdl2-dev and rebuild";

}  // namespace browser
