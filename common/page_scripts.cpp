#include "page_scripts.h"

namespace browser {

Window::Window(const Options& options, Document page) : Window(options.frame_ms, std::move(page)) {
    document.canvas.setScale(options.scale);
    overlay = options.overlay || options.overlay_all;
    overlay_all = options.overlay_all;
    document.echo_notes = options.echo_notes;
    // Every picture of a run has one size: where the overlay can come on, the legend's
    // band is there from the first frame, the overlay on or off. (A live session's page
    // gets it when the key first turns the overlay on, and keeps it: press_key.)
    const std::size_t presses = options.keys.pressCount(KeySet::parse(key_name(kOverlayKey)));
    document.legend_room = options.overlay_offered && (overlay || presses > 0);
    // off -> own -> all: two presses reach every layer, one from --overlay.
    every_layer_possible =
        options.overlay_offered && (overlay_all || options.live.on || presses >= (overlay ? 1U : 2U));
}

void press_key(PageScripts& scripts, Window& window, const Options& options, Key key) {
    if (options.overlay_offered && key == kOverlayKey) {
        // off -> own -> all -> off
        window.document.legend_room = true;
        if (!window.overlay) {
            window.overlay = true;
            window.overlay_all = false;
        } else if (!window.overlay_all) {
            window.overlay_all = true;
            window.every_layer_possible = true;
        } else {
            window.overlay = false;
            window.overlay_all = false;
        }
    } else {
        scripts.onKeyDown(key);
    }
}

}  // namespace browser
