#include "page_scripts.h"

namespace browser {

Window::Window(const Options& options, Document page) : Window(options.frame_ms, std::move(page)) {
    document.canvas.setScale(options.scale);
}

}  // namespace browser
