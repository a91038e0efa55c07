#include "image.h"

#include <algorithm>
#include <cstddef>

namespace browser {

Image::Image(int w, int h, Color fill) : width(std::max(w, 0)), height(std::max(h, 0)) {
    rgba.resize(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4);
    for (std::size_t i = 0; i < rgba.size(); i += 4) {
        rgba[i + 0] = fill.r;
        rgba[i + 1] = fill.g;
        rgba[i + 2] = fill.b;
        rgba[i + 3] = fill.a;
    }
}

void Image::paste(const Image& source, int x, int y) {
    // Only the part where the two pictures overlap is copied, one row at a time.
    const int first_column = std::max(0, -x);
    const int last_column = std::min(source.width, width - x);  // one past the end
    const int first_row = std::max(0, -y);
    const int last_row = std::min(source.height, height - y);
    if (first_column >= last_column) return;
    const std::size_t row_bytes = static_cast<std::size_t>(last_column - first_column) * 4;
    for (int row = first_row; row < last_row; ++row) {
        const auto from = source.rgba.begin() + static_cast<std::ptrdiff_t>(source.offset(first_column, row));
        std::copy(from, from + static_cast<std::ptrdiff_t>(row_bytes),
                  rgba.begin() + static_cast<std::ptrdiff_t>(offset(x + first_column, y + row)));
    }
}

}  // namespace browser
