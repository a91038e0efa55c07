#include "user_control.h"

#include <numbers>

namespace engine {

namespace {
// Random places stay within the top-left 80% of the canvas so shapes are seldom cut
// off at the right or bottom edge; sizes run from 10 to 40 px.
constexpr double kPlaceShare = 0.8;
constexpr double kSmallestSize = 10.0;
constexpr double kSizeRange = 30.0;
}  // namespace

void UserControl::onKeyDown(browser::Key key) {
    using browser::Key;
    if (key == Key::F) drawRandomRectangle();
    if (key == Key::G) drawRandomCircle();
}

void UserControl::drawRandomRectangle() {
    // strokeRect takes the top-left corner, so (x, y) is a corner, not the centre.
    // The four random numbers are drawn in argument order, as the book's call does.
    const double x = random_.next() * core_.width() * kPlaceShare;
    const double y = random_.next() * core_.height() * kPlaceShare;
    const double width = random_.next() * kSizeRange + kSmallestSize;
    const double height = random_.next() * kSizeRange + kSmallestSize;
    core_.context().strokeRect(x, y, width, height);
}

void UserControl::drawRandomCircle() {
    const double x = random_.next() * core_.width() * kPlaceShare;
    const double y = random_.next() * core_.height() * kPlaceShare;
    const double radius = random_.next() * kSizeRange + kSmallestSize;
    browser::Canvas& context = core_.context();
    context.beginPath();
    context.arc(x, y, radius, 0.0, 2.0 * std::numbers::pi, true);
    context.closePath();
    context.stroke();
}

}  // namespace engine
