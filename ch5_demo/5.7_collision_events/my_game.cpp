#include "my_game.h"

#include "circle.h"
#include "rectangle.h"

namespace engine {

namespace {
constexpr int kShapePairs = 10;
// The random shapes: sides 10 to 60 px, radii 10 to 30 px, mass 0 to 30, friction and
// restitution 0 to 1, each velocity component -30 to 30 px/s.
constexpr double kSideMin = 10.0, kSideRange = 50.0;
constexpr double kRadiusMin = 10.0, kRadiusRange = 20.0;
constexpr double kMassRange = 30.0;
constexpr double kSpeedRange = 30.0;

Vec2 randomPlaceInTopHalf(const Core& core, browser::Random& random) {
    const double x = random.next() * core.width();
    const double y = random.next() * core.height() / 2;
    return {x, y};
}

// Drawn in the book's order: mass, friction, restitution.
PhysicalAttributes randomAttributes(browser::Random& random) {
    PhysicalAttributes attributes;
    attributes.mass = random.next() * kMassRange;
    attributes.friction = random.next();
    attributes.restitution = random.next();
    return attributes;
}

Vec2 randomVelocity(browser::Random& random) {
    const double vx = random.next() * 2 * kSpeedRange - kSpeedRange;
    const double vy = random.next() * 2 * kSpeedRange - kSpeedRange;
    return {vx, vy};
}
}  // namespace

void buildScene(Core& core, browser::Random& random) {
    core.add(Rectangle({500, 200}, 400, 20, {.mass = 0, .friction = 0.3, .restitution = 0})).rotate(2.8);
    core.add(Rectangle({200, 400}, 400, 20, {.mass = 0, .friction = 1, .restitution = 0.5}));
    core.add(Rectangle({100, 200}, 200, 20, {.mass = 0}));
    core.add(Rectangle({10, 360}, 20, 100, {.mass = 0, .friction = 0, .restitution = 1}));

    // Every random number is drawn in the order the book's constructor calls take them:
    // place, size, attributes, then the velocity set after construction.
    for (int i = 0; i < kShapePairs; ++i) {
        const Vec2 box_place = randomPlaceInTopHalf(core, random);
        const double width = random.next() * kSideRange + kSideMin;
        const double height = random.next() * kSideRange + kSideMin;
        const PhysicalAttributes box_attributes = randomAttributes(random);
        core.add(Rectangle(box_place, width, height, box_attributes)).setVelocity(randomVelocity(random));

        const Vec2 ball_place = randomPlaceInTopHalf(core, random);
        const double radius = random.next() * kRadiusRange + kRadiusMin;
        const PhysicalAttributes ball_attributes = randomAttributes(random);
        core.add(Circle(ball_place, radius, ball_attributes)).setVelocity(randomVelocity(random));
    }
}

}  // namespace engine
