#include "overlay.h"

#include <vector>

#include "grid_overlay.h"

namespace engine {

void drawOverlay(browser::Window& window, const Core& core) {
    std::vector<browser::LegendEntry>& legend = window.document.legend;
    legend.clear();
    if (!window.overlay) return;
    drawGrid(window.document.canvas, core, legend);
}

}  // namespace engine
