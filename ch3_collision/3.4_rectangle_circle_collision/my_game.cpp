#include "my_game.h"

#include "rectangle.h"

namespace engine {

namespace {
constexpr double kBorderThickness = 3.0;
constexpr double kCursorSize = 3.0;
}  // namespace

void buildScene(Core& core) {
    const double width = core.width();
    const double height = core.height();
    core.add(Rectangle({width / 2, height / 2}, kCursorSize, kCursorSize));
    core.add(Rectangle({width / 2, 0}, width, kBorderThickness));        // top
    core.add(Rectangle({width / 2, height}, width, kBorderThickness));   // bottom
    core.add(Rectangle({0, height / 2}, kBorderThickness, height));      // left
    core.add(Rectangle({width, height / 2}, kBorderThickness, height));  // right
}

}  // namespace engine
