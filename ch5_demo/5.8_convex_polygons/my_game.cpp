#include "my_game.h"

#include <algorithm>
#include <vector>

#include "circle.h"
#include "polygon.h"
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

namespace {

// The book's four platforms, objects 0 to 3.
void addPlatforms(Core& core) {
    core.add(Rectangle({500, 200}, 400, 20, {.mass = 0, .friction = 0.3, .restitution = 0})).rotate(2.8);
    core.add(Rectangle({200, 400}, 400, 20, {.mass = 0, .friction = 1, .restitution = 0.5}));
    core.add(Rectangle({100, 200}, 200, 20, {.mass = 0}));
    core.add(Rectangle({10, 360}, 20, 100, {.mass = 0, .friction = 0, .restitution = 1}));
}

// The book's ten rectangles and ten circles.
void addRandomShapes(Core& core, browser::Random& random) {
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

// 5.8: five convex polygons join the book's shapes, drawn after them from the same
// random numbers (so the book's are the book's): polygon.h's random corners, then the
// book's mass, friction, restitution and velocity.
constexpr int kPolygons = 5;

void addRandomPolygons(Core& core, browser::Random& random) {
    for (int i = 0; i < kPolygons; ++i) {
        const Vec2 place = randomPlaceInTopHalf(core, random);
        const std::vector<Vec2> corners = randomCorners(random);
        const PhysicalAttributes attributes = randomAttributes(random);
        core.add(Polygon(place, corners, attributes)).setVelocity(randomVelocity(random));
    }
}

// The game's two sensors, static: the zone lies on the left floor (its top at y = 390)
// and reaches 60 px above it; the goal spans the bottom right, where shapes leave the
// long slide and fall off the canvas.
constexpr Vec2 kZoneCenter{200, 360};
constexpr double kZoneWidth = 400, kZoneHeight = 60;
constexpr Vec2 kGoalCenter{620, 425};
constexpr double kGoalWidth = 300, kGoalHeight = 40;

BodyId addSensor(Core& core, Vec2 center, double width, double height) {
    Rectangle& sensor = core.add(Rectangle(center, width, height, {.mass = 0}));
    sensor.setSensor(true);
    return sensor.id();
}

void insertSorted(std::vector<BodyId>& ids, BodyId id) {
    const auto place = std::lower_bound(ids.begin(), ids.end(), id);
    if (place == ids.end() || *place != id) ids.insert(place, id);
}

void eraseSorted(std::vector<BodyId>& ids, BodyId id) {
    const auto place = std::lower_bound(ids.begin(), ids.end(), id);
    if (place != ids.end() && *place == id) ids.erase(place);
}

bool containsSorted(const std::vector<BodyId>& ids, BodyId id) {
    return std::binary_search(ids.begin(), ids.end(), id);
}

}  // namespace

void buildScene(Core& core, browser::Random& random) {
    addPlatforms(core);
    addRandomShapes(core, random);
}

DemoGame::DemoGame(Core& core, browser::Random& random) {
    addPlatforms(core);
    zone_ = addSensor(core, kZoneCenter, kZoneWidth, kZoneHeight);
    goal_ = addSensor(core, kGoalCenter, kGoalWidth, kGoalHeight);
    addRandomShapes(core, random);
    addRandomPolygons(core, random);
}

void DemoGame::afterStep(Core& core) {
    std::vector<BodyId> scoring;
    for (const ContactEvent& event : core.events().events()) {
        const bool zone = event.id_a == zone_ || event.id_b == zone_;
        const bool goal = event.id_a == goal_ || event.id_b == goal_;
        const BodyId other = event.id_a == zone_ || event.id_a == goal_ ? event.id_b : event.id_a;
        if (event.kind == EventKind::begin && !zone && !goal) {
            insertSorted(touched_, event.id_a);
            insertSorted(touched_, event.id_b);
        }
        if (zone && event.kind == EventKind::begin) insertSorted(inside_, other);
        if (zone && event.kind == EventKind::end) eraseSorted(inside_, other);
        if (goal && event.kind == EventKind::begin) scoring.push_back(other);
    }
    // Removed only now, after the loop over the list: removing changes the world the
    // events describe, and each removal tells its own ends with the next step's events.
    for (const BodyId id : scoring) {
        if (core.remove(id)) ++scored_;
    }
}

std::optional<browser::Color> DemoGame::colourOf(const RigidShape& shape) const {
    // The platforms keep the book's blue: only what moves shows it has met something.
    if (!shape.isStatic() && containsSorted(touched_, shape.id())) return browser::colors::kOrange;
    return std::nullopt;
}

std::string DemoGame::echo() const {
    return "  Zone: " + std::to_string(inside_.size()) + " inside, Goal: " + std::to_string(scored_) + " scored\n";
}

}  // namespace engine
