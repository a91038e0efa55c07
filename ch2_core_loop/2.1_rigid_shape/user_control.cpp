#include "user_control.h"

#include "circle.h"
#include "rectangle.h"

namespace engine {

namespace {
// Random places fall in the top-left 80% of the canvas; rectangle sides are 10 to
// 40 px, circle radii 20 to 30 px.
constexpr double kPlaceShare = 0.8;
constexpr double kSideMin = 10.0, kSideRange = 30.0;
constexpr double kRadiusMin = 20.0, kRadiusRange = 10.0;
}  // namespace

void UserControl::onKeyDown(browser::Key key) {
    using browser::Key;
    if (const auto digit = browser::digit_value(key)) core_.select(static_cast<std::size_t>(*digit));
    if (key == Key::Up && core_.selectedIndex() > 0) core_.select(core_.selectedIndex() - 1);
    if (key == Key::Down) core_.select(core_.selectedIndex() + 1);  // select() ignores the end
    if (key == Key::F) spawnRectangle();
    if (key == Key::G) spawnCircle();
}

Vec2 UserControl::randomPlace() {
    const double x = random_.next() * core_.width() * kPlaceShare;
    const double y = random_.next() * core_.height() * kPlaceShare;
    return {x, y};
}

void UserControl::spawnRectangle() {
    const Vec2 center = randomPlace();
    const double width = random_.next() * kSideRange + kSideMin;
    const double height = random_.next() * kSideRange + kSideMin;
    core_.add(Rectangle(center, width, height));
}

void UserControl::spawnCircle() {
    const Vec2 center = randomPlace();
    core_.add(Circle(center, random_.next() * kRadiusRange + kRadiusMin));
}

}  // namespace engine
