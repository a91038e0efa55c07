#include "page_scripts.h"

namespace browser {

Window::Window(const Options& options, Document page) : Window(options.frame_ms, std::move(page)) {
    document.canvas.setScale(options.scale);
    overlay = options.overlay;
}

void press_key(PageScripts& scripts, Window& window, const Options& options, Key key) {
    if (options.overlay_offered && key == kOverlayKey) {
        window.overlay = !window.overlay;
    } else {
        scripts.onKeyDown(key);
    }
}

}  // namespace browser
