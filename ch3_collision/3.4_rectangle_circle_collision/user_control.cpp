#include "user_control.h"

#include "circle.h"
#include "rectangle.h"

namespace engine {

namespace {
// Rectangle sides are 10 to 40 px, circle radii 20 to 30 px.
constexpr double kSideMin = 10.0, kSideRange = 30.0;
constexpr double kRadiusMin = 20.0, kRadiusRange = 10.0;
constexpr double kMoveStep = 10.0;  // px per W/A/S/D press
constexpr double kTurnStep = 0.1;   // rad per Q/E press
}  // namespace

void UserControl::onKeyDown(browser::Key key) {
    using browser::Key;
    if (const auto digit = browser::digit_value(key)) core_.select(static_cast<std::size_t>(*digit));
    if (key == Key::Up && core_.selectedIndex() > 0) core_.select(core_.selectedIndex() - 1);
    if (key == Key::Down) core_.select(core_.selectedIndex() + 1);  // select() ignores the end
    if (key == Key::R) {
        core_.keepFirstObjects(kKeptOnReset);
        core_.select(0);
    }

    // The remaining keys act on the selected object, so they need one.
    if (core_.objectCount() == 0) return;
    RigidShape& selected = core_.object(core_.selectedIndex());
    if (key == Key::W) selected.move({0, -kMoveStep});
    if (key == Key::S) selected.move({0, +kMoveStep});
    if (key == Key::A) selected.move({-kMoveStep, 0});
    if (key == Key::D) selected.move({+kMoveStep, 0});
    if (key == Key::Q) selected.rotate(-kTurnStep);
    if (key == Key::E) selected.rotate(+kTurnStep);
    if (key == Key::F) spawnRectangle(selected.center());
    if (key == Key::G) spawnCircle(selected.center());
}

void UserControl::spawnRectangle(Vec2 center) {
    const double width = random_.next() * kSideRange + kSideMin;
    const double height = random_.next() * kSideRange + kSideMin;
    core_.add(Rectangle(center, width, height));
}

void UserControl::spawnCircle(Vec2 center) { core_.add(Circle(center, random_.next() * kRadiusRange + kRadiusMin)); }

}  // namespace engine
