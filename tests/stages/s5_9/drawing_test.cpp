// Stage 5.9's pictures of its own things (README.md, "Kinematic bodies", "Events at a
// joint's limit", "The mouse"), pixel by pixel: a kinematic body is drawn in its own
// colour with arrows for its velocity and its turn, and a dynamic body with the same
// motion is not; the band under the panel names the kinematic bodies only where there
// are some; a limit event gets a diamond at the joint's anchor on the events' layer,
// and the legend names it; the joints' legend names the kinematic colour and the mouse
// joint's line in the colours the page draws them in.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <numbers>
#include <string>
#include <vector>

#include "circle.h"
#include "events_overlay.h"
#include "joints.h"
#include "joints_overlay.h"
#include "kinematic_drawing.h"
#include "overlay_draw.h"
#include "rectangle.h"
#include "world_fixture.h"

namespace s5_9_drawing_test {

using browser::Color;
using engine::Vec2;

namespace {

constexpr double kPi = std::numbers::pi;

// Whether `pixel` is `color` laid over the white page at `share` 0.4 or more (the canvas
// smooths its lines: a line between two rows of pixels paints each about half), within
// 3 of 255 in every channel.
bool paintedWith(Color pixel, Color color) {
    const auto channel = [](std::uint8_t value) { return static_cast<double>(value); };
    const double pixel_rgb[] = {channel(pixel.r), channel(pixel.g), channel(pixel.b)};
    const double color_rgb[] = {channel(color.r), channel(color.g), channel(color.b)};
    int strongest = 0;  // the channel the colour takes the most white from
    for (int c = 1; c < 3; ++c) {
        if (color_rgb[c] < color_rgb[strongest]) strongest = c;
    }
    const double share = (255.0 - pixel_rgb[strongest]) / (255.0 - color_rgb[strongest]);
    if (share < 0.4) return false;
    for (int c = 0; c < 3; ++c) {
        if (std::abs(255.0 - share * (255.0 - color_rgb[c]) - pixel_rgb[c]) > 3.0) return false;
    }
    return true;
}

// Whether a pixel within `reach` px of `at` is painted with `color`.
bool colourNear(const browser::Canvas& canvas, Vec2 at, Color color, int reach = 1) {
    const browser::Image& pixels = canvas.pixels();
    const int x = static_cast<int>(std::lround(at.x)), y = static_cast<int>(std::lround(at.y));
    for (int dy = -reach; dy <= reach; ++dy) {
        for (int dx = -reach; dx <= reach; ++dx) {
            if (paintedWith(pixels.at(x + dx, y + dy), color)) return true;
        }
    }
    return false;
}

// How many pixels of the canvas are painted with `color`.
long pixelsOf(const browser::Canvas& canvas, Color color) {
    const browser::Image& pixels = canvas.pixels();
    long count = 0;
    for (int y = 0; y < pixels.height; ++y) {
        for (int x = 0; x < pixels.width; ++x) count += paintedWith(pixels.at(x, y), color) ? 1 : 0;
    }
    return count;
}

// A world at rest for the page to draw (movement off: the frame drawn is the state set).
engine::WorldSettings stillWorld() {
    engine::WorldSettings world = test::world(false);
    world.solver = engine::SolverKind::sequential_impulse;
    return world;
}

// The legend's entry that starts with `start`.
const browser::LegendEntry& entryOf(const std::vector<browser::LegendEntry>& legend, const std::string& start) {
    for (const browser::LegendEntry& entry : legend) {
        if (entry.text.rfind(start, 0) == 0) return entry;
    }
    FAIL("no legend entry starting \"" << start << "\"");
    return legend.front();
}

}  // namespace

// A floor (object 0, selected: red), a kinematic plank 100 x 20 at (200, 200) moving at
// 60 px/s, a dynamic one as large at (200, 350) moving as fast, and a kinematic disc of
// radius 40 at (550, 200) turning at 1 rad/s (clockwise on the canvas). In one second the
// plank's centre goes 60 px: its arrow runs from (200, 200) to (260, 200). The disc's
// curved arrow runs round its centre at 0.75 of its radius, 30 px, from straight up
// (-pi/2) clockwise through 1 rad: a point of it 0.5 rad clockwise of the top, none
// 0.5 rad the other way.
TEST_CASE("s5_9: a kinematic body is drawn in its own colour with arrows for its motion; a dynamic one is not",
          "[drawing]") {
    test::WorldFixture page(stillWorld());
    page.core.add(engine::Rectangle({400, 440}, 800, 20, {.mass = 0}));
    engine::RigidShape& plank = page.core.add(engine::Rectangle({200, 200}, 100, 20));
    plank.makeKinematic();
    plank.setVelocity({60, 0});
    engine::RigidShape& twin = page.core.add(engine::Rectangle({200, 350}, 100, 20));
    twin.setVelocity({60, 0});
    engine::RigidShape& disc = page.core.add(engine::Circle({550, 200}, 40));
    disc.makeKinematic();
    disc.setAngularVelocity(1.0);
    page.core.runGameLoop();
    const browser::Canvas& canvas = page.window.document.canvas;
    const Color purple = engine::kKinematicColor;

    CHECK(colourNear(canvas, {200, 190}, purple));                  // the plank's top edge
    CHECK(colourNear(canvas, {230, 200}, purple));                  // its velocity's arrow, half way
    CHECK(colourNear(canvas, {200, 200}, purple, 2));               // the dot at its centre
    CHECK(colourNear(canvas, {200, 340}, browser::colors::kBlue));  // the dynamic twin: the book's blue
    CHECK_FALSE(colourNear(canvas, {200, 340}, purple));
    CHECK_FALSE(colourNear(canvas, {230, 350}, purple));  // and no arrow
    CHECK(colourNear(canvas, {550, 160}, purple));        // the disc's rim
    constexpr double kArc = 30.0;                         // 0.75 of the radius
    const auto onArc = [&](double angle) { return Vec2{550 + kArc * std::cos(angle), 200 + kArc * std::sin(angle)}; };
    CHECK(colourNear(canvas, onArc(-kPi / 2 + 0.5), purple));
    CHECK_FALSE(colourNear(canvas, onArc(-kPi / 2 - 0.5), purple));
    // The band under the panel names them, with their colour and the arrows' time.
    CHECK(page.window.document.beyond_echo.find("  Kinematic (purple): 2, arrows 1 s\n") != std::string::npos);

    // Turned dynamic, the plank loses its colour, its arrow and its line in the band
    // (here the world never had one: a world without kinematic bodies draws as 5.8's).
    test::WorldFixture plain(stillWorld());
    plain.core.add(engine::Rectangle({400, 440}, 800, 20, {.mass = 0}));
    plain.core.add(engine::Rectangle({200, 200}, 100, 20)).setVelocity({60, 0});
    plain.core.add(engine::Circle({550, 200}, 40)).setAngularVelocity(1.0);
    plain.core.runGameLoop();
    CHECK(pixelsOf(plain.window.document.canvas, purple) == 0);
    CHECK(plain.window.document.beyond_echo.find("Kinematic") == std::string::npos);
}

// A disc on a pin 150 px from a post level with it, its limit 45 degrees past the
// bottom (s5_9_test.cpp's pendulum, told at step 105): in the step it is told, the
// events' layer draws a diamond round the event's point, the pin at (300, 100), its
// corners 9 px away (a fresh event's size), and writes the speed it closed at in rad/s;
// the legend counts it. Before it, no diamond.
TEST_CASE("s5_9: a limit event is drawn as a diamond at the joint's anchor, and named in the legend", "[drawing]") {
    engine::WorldSettings world = stillWorld();
    world.movement = true;
    world.gravity = {0, 300};
    world.remove_out_of_bounds = false;
    world.sleep = false;
    test::WorldFixture page(world);
    const engine::RigidShape& post = page.core.add(engine::Circle({300, 100}, 2, {.mass = 0}));
    const engine::RigidShape& bob = page.core.add(engine::Circle({450, 100}, 10));
    engine::JointDefinition pin = engine::pinAt(engine::JointType::revolute, post, bob, {300, 100});
    pin.limit = engine::JointRange{-1.0, 3.0 * kPi / 4.0};
    page.core.join(pin);
    page.core.keepEvents(true, engine::EventReader::overlay);

    const auto drawn = [&page](browser::Canvas& canvas) {
        browser::overlay::LabelLayout labels;
        std::vector<browser::LegendEntry> legend;
        engine::drawEvents(canvas, labels, page.core, legend);
        return legend;
    };
    browser::Canvas before;
    const std::vector<browser::LegendEntry> quiet = drawn(before);
    const Color limit_colour = entryOf(quiet, "limit: ").color;
    CHECK(entryOf(quiet, "limit: ").text == "limit: a joint's limit holds (diamond): 0");
    CHECK(pixelsOf(before, limit_colour) == 0);

    const engine::ContactEvent* told = nullptr;
    for (int step = 0; step < 200 && told == nullptr; ++step) {
        page.steps(1);
        for (const engine::ContactEvent& event : page.core.events().events()) {
            if (event.kind == engine::EventKind::limit) told = &event;
        }
    }
    REQUIRE(told != nullptr);
    const Vec2 at = told->point;
    CHECK(at.distance({300, 100}) < 0.5);
    browser::Canvas canvas;
    const std::vector<browser::LegendEntry> legend = drawn(canvas);
    CHECK(entryOf(legend, "limit: ").text == "limit: a joint's limit holds (diamond): 1");
    for (const Vec2 corner : {Vec2{0, -9}, Vec2{9, 0}, Vec2{0, 9}, Vec2{-9, 0}}) {
        CHECK(colourNear(canvas, at + corner, limit_colour));
    }
    CHECK(colourNear(canvas, at + Vec2{4.5, -4.5}, limit_colour));  // half way along an edge
    CHECK_FALSE(colourNear(canvas, at, limit_colour));              // hollow: the pin shows through
    // Its label, in the limit's colour, up and to the right of the pin (kLabelOffset).
    long labelled = 0;
    for (int y = 80; y < 100; ++y) {
        for (int x = 300; x < 380; ++x) labelled += paintedWith(canvas.pixels().at(x, y), limit_colour) ? 1 : 0;
    }
    CHECK(labelled > 20);
}

// The joints' legend names what the page draws for 5.9 in the colours it draws them in:
// a kinematic body's outline, and the mouse joint's line from the grabbed point (a box's
// centre, (300, 300)) to the pointer, 100 px to its right.
TEST_CASE("s5_9: the joints' legend names the kinematic colour and the mouse's line as the page draws them",
          "[drawing]") {
    test::WorldFixture page(stillWorld());
    page.core.add(engine::Rectangle({400, 440}, 800, 20, {.mass = 0}));
    page.core.add(engine::Rectangle({300, 300}, 40, 40));
    page.core.add(engine::Rectangle({600, 200}, 100, 10)).makeKinematic();
    REQUIRE(page.core.grab({300, 300}));
    page.core.dragTo({400, 300});
    page.core.runGameLoop();
    const browser::Canvas& canvas = page.window.document.canvas;

    browser::Canvas sheet;
    browser::overlay::LabelLayout labels;
    std::vector<browser::LegendEntry> legend;
    engine::drawJoints(sheet, labels, page.core, legend);
    const browser::LegendEntry& mouse = entryOf(legend, "mouse joint: ");
    CHECK(mouse.text == "mouse joint: grabbed point to pointer");
    CHECK(colourNear(canvas, {350, 300}, mouse.color));  // half way along the line
    const browser::LegendEntry& kinematic = entryOf(legend, "kinematic body");
    CHECK(kinematic.text == "kinematic body; arrows: its motion in 1 s");
    CHECK(colourNear(canvas, {600, 195}, kinematic.color));  // the plank's top edge
}

}  // namespace s5_9_drawing_test
