#include "build_features.h"

namespace browser {

// The two macros come from common/CMakeLists.txt, which sets them to what it found;
// only this file reads them to answer, so a change of build recompiles one file.
bool gif_supported() { return BROWSER_HAS_GIF != 0; }

bool live_window_supported() { return BROWSER_HAS_SDL != 0; }

}  // namespace browser
