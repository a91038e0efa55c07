#include "user_control.h"

#include <algorithm>
#include <iterator>
#include <vector>

#include "circle.h"
#include "polygon.h"
#include "rectangle.h"

namespace engine {

namespace {
// Rectangle sides are 10 to 40 px, circle radii 20 to 30 px.
constexpr double kSideMin = 10.0, kSideRange = 30.0;
constexpr double kRadiusMin = 20.0, kRadiusRange = 10.0;
// New shapes get a mass of 0 to 30, and friction and restitution of 0 to 1.
constexpr double kSpawnMassRange = 30.0;
constexpr double kMoveStep = 10.0;     // px per W/A/S/D press
constexpr double kTurnStep = 0.1;      // rad per Q/E press
constexpr double kSpeedStep = 1.0;     // px/s per I/J/K/L press
constexpr double kSpinStep = 0.1;      // rad/s per U/O press
constexpr double kMassStep = 1.0;      // per Z/X press
constexpr double kSurfaceStep = 0.01;  // friction per C/V, restitution per B/N press

// The keys that move, turn, push or change the selected object, or make a new one on it.
bool changesSelected(browser::Key key) {
    using browser::Key;
    constexpr Key kChanging[] = {Key::W, Key::S, Key::A, Key::D, Key::Q, Key::E, Key::I,
                                 Key::K, Key::J, Key::L, Key::U, Key::O, Key::Z, Key::X,
                                 Key::C, Key::V, Key::B, Key::N, Key::F, Key::G, Key::Slash};
    return std::find(std::begin(kChanging), std::end(kChanging), key) != std::end(kChanging);
}
}  // namespace

void UserControl::onKeyDown(browser::Key key) {
    selectionKeys(key);
    worldKeys(key);
    // The remaining keys act on the selected object, so they need one.
    if (core_.objectCount() == 0) return;
    selectedObjectKeys(key, core_.object(core_.selectedIndex()));
}

void UserControl::selectionKeys(browser::Key key) {
    using browser::Key;
    if (const auto digit = browser::digit_value(key)) core_.select(static_cast<std::size_t>(*digit));
    if (key == Key::Up && core_.selectedIndex() > 0) core_.select(core_.selectedIndex() - 1);
    if (key == Key::Down) core_.select(core_.selectedIndex() + 1);  // select() ignores the end
}

void UserControl::worldKeys(browser::Key key) {
    using browser::Key;
    if (key == Key::R) {
        core_.keepFirstObjects(kKeptOnReset);
        core_.select(0);
    }
    if (key == Key::Comma) core_.toggleMovement();
    if (key == Key::M) core_.togglePositionalCorrection();
    if (key == Key::Y) core_.toggleSleep();
    if (key == Key::P) core_.toggleContinuous();
    if (key == Key::H) {
        core_.wakeAll();
        exciteAll();
    }
}

void UserControl::selectedObjectKeys(browser::Key key, RigidShape& selected) {
    using browser::Key;
    // Whatever changes a sleeping shape must wake it, or the change would wait, unseen,
    // for something else to wake it; and its island with it, since what it holds up, or
    // lies on, may now be pushed.
    if (changesSelected(key)) core_.wakeIslandOf(core_.selectedIndex());
    const bool was_moving = !selected.isStatic();
    if (key == Key::W) selected.move({0, -kMoveStep});
    if (key == Key::S) selected.move({0, +kMoveStep});
    if (key == Key::A) selected.move({-kMoveStep, 0});
    if (key == Key::D) selected.move({+kMoveStep, 0});
    if (key == Key::Q) selected.rotate(-kTurnStep);
    if (key == Key::E) selected.rotate(+kTurnStep);

    if (key == Key::I) selected.setVelocity(selected.velocity() + Vec2{0, -kSpeedStep});
    if (key == Key::K) selected.setVelocity(selected.velocity() + Vec2{0, +kSpeedStep});
    if (key == Key::J) selected.setVelocity(selected.velocity() + Vec2{-kSpeedStep, 0});
    if (key == Key::L) selected.setVelocity(selected.velocity() + Vec2{+kSpeedStep, 0});
    if (key == Key::U) selected.setAngularVelocity(selected.angularVelocity() - kSpinStep);
    if (key == Key::O) selected.setAngularVelocity(selected.angularVelocity() + kSpinStep);

    if (key == Key::Z) selected.updateMass(-kMassStep);
    if (key == Key::X) selected.updateMass(+kMassStep);
    // Friction below 0 and restitution outside [0, 1] mean nothing (or make energy),
    // so the keys stop there: the same ranges a scene file must keep to.
    if (key == Key::C) selected.setFriction(std::max(0.0, selected.friction() - kSurfaceStep));
    if (key == Key::V) selected.setFriction(selected.friction() + kSurfaceStep);
    if (key == Key::B) selected.setRestitution(std::max(0.0, selected.restitution() - kSurfaceStep));
    if (key == Key::N) selected.setRestitution(std::min(1.0, selected.restitution() + kSurfaceStep));

    // A shape put somewhere by hand, or made static, leaves its contacts (5.7's events):
    // its pairs end now, and whatever it touches next step begins anew.
    const bool teleported =
        key == Key::W || key == Key::A || key == Key::S || key == Key::D || key == Key::Q || key == Key::E;
    if (teleported || (key == Key::Z && selected.isStatic() && was_moving)) {
        core_.leaveContacts(core_.selectedIndex());
    }

    if (key == Key::F) spawnRectangle(selected.center());
    if (key == Key::G) spawnCircle(selected.center());
    if (key == Key::Slash) spawnPolygon(selected.center());
}

// A random kick for everything that can move, to stir a settled scene.
void UserControl::exciteAll() {
    for (std::size_t i = 0; i < core_.objectCount(); ++i) {
        RigidShape& shape = core_.object(i);
        if (!shape.isDynamic()) continue;  // nor a kinematic shape (5.9): it keeps its course
        shape.setVelocity(randomVelocity(kExciteSpeed));
    }
}

// Each component uniform in [-largest, largest), x drawn first.
Vec2 UserControl::randomVelocity(double largest_component) {
    const double vx = random_.next() * 2 * largest_component - largest_component;
    const double vy = random_.next() * 2 * largest_component - largest_component;
    return {vx, vy};
}

// Drawn in the book's order: mass, friction, restitution. (A mass of exactly 0, and so
// a static shape, is possible but rare.)
PhysicalAttributes UserControl::randomAttributes() {
    PhysicalAttributes attributes;
    attributes.mass = random_.next() * kSpawnMassRange;
    attributes.friction = random_.next();
    attributes.restitution = random_.next();
    return attributes;
}

// The random numbers are drawn in the book's order: the size, then the attributes,
// then the velocity, which the book sets once the shape is made.
void UserControl::spawnRectangle(Vec2 center) {
    const double width = random_.next() * kSideRange + kSideMin;
    const double height = random_.next() * kSideRange + kSideMin;
    core_.add(Rectangle(center, width, height, randomAttributes())).setVelocity(randomVelocity(kSpawnSpeed));
}

void UserControl::spawnCircle(Vec2 center) {
    const double radius = random_.next() * kRadiusRange + kRadiusMin;
    core_.add(Circle(center, radius, randomAttributes())).setVelocity(randomVelocity(kSpawnSpeed));
}

// The same order for a polygon: its corners, the attributes, the velocity.
void UserControl::spawnPolygon(Vec2 center) {
    const std::vector<Vec2> corners = randomCorners(random_);
    core_.add(Polygon(center, corners, randomAttributes())).setVelocity(randomVelocity(kSpawnSpeed));
}

}  // namespace engine
