// Stage 5.9's pictures of its own things (README.md, "Kinematic bodies", "Events at a
// joint's limit", "The mouse"), pixel by pixel: a kinematic body is drawn in its own
// colour with arrows for its velocity and its turn, and a dynamic body with the same
// motion is not; the band under the panel names the kinematic bodies only where there
// are some; a limit event gets a diamond at the joint's anchor on the events' layer,
// and the legend names it; the joints' legend names the kinematic colour and the mouse
// joint's line in the colours the page draws them in. With every layer on, the legend's
// entries each lie on the page in a column of their own, and GJK's panels keep off the
// pendulums' pins.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include "circle.h"
#include "events_overlay.h"
#include "gjk_overlay.h"
#include "joints.h"
#include "joints_overlay.h"
#include "kinematic_drawing.h"
#include "legend_layout.h"
#include "overlay.h"
#include "overlay_draw.h"
#include "page.h"
#include "rectangle.h"
#include "scene_io.h"
#include "text.h"
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

namespace {

// A scene of the stage's folder run `frames` frames as `build/s5_9_joints --scene FILE
// --overlay-all` runs it: its canvas, every layer on, the legend's band kept.
struct EveryLayerRun {
    explicit EveryLayerRun(const std::string& file)
        : scene(engine::loadScene(std::filesystem::path(SCENE_LIBRARY_DIR).parent_path() / "5.9_joints" / file)),
          page(scene.world) {
        page.window.document.canvas =
            browser::Canvas(static_cast<int>(scene.world.width), static_cast<int>(scene.world.height));
        engine::buildScene(page.core, scene);
        page.window.overlay = page.window.overlay_all = page.window.every_layer_possible = true;
        page.window.document.legend_room = true;
    }
    void run(int frames) {
        for (int frame = 0; frame < frames; ++frame) {
            page.window.clock.advanceFrame();
            page.core.runGameLoop();
        }
    }
    engine::Scene scene;
    test::WorldFixture page;
};

// Whether an entry that goes on from the one before (its text starts with spaces, as the
// joints' second line of counts) lies under it, in the same column.
bool continuedInItsColumn(const browser::Document& document) {
    const std::vector<browser::LegendBox> boxes = browser::legend_boxes(document);
    for (std::size_t i = 1; i < boxes.size(); ++i) {
        if (!document.legend[i].text.starts_with(" ")) continue;
        if (boxes[i].left != boxes[i - 1].left || boxes[i].top != boxes[i - 1].bottom) return false;
    }
    return true;
}

}  // namespace

// The ragdoll's page is 800 + 380 = 1180 px wide. Its legend with every layer on has
// entries up to 440 px of text (5.7's counts: "in 0.5 s: begins 5, ends 5, hits 5;
// touching 0"): in columns 390 px apart, the stages' before 5.7, the third column starts
// at 790 and such an entry ends past 1180. In columns made for 460 px of text (overlay.h's
// kLegendTextWidth), 484 px apart, two fit, and every entry ends inside the frame; the
// joints' counts, two lines, stay in one column, with every layer and with their own.
TEST_CASE("s5_9: every entry of the ragdoll's legend, every layer on, lies on the page in its own column",
          "[drawing]") {
    EveryLayerRun ragdoll("ragdoll.json");
    ragdoll.run(141);
    browser::Document document = ragdoll.page.window.document;
    REQUIRE(document.legend.size() == engine::kLegendEntries);
    const int page_width = document.canvas.width() + browser::kPanelWidth;
    CHECK(page_width == 1180);
    CHECK(document.legend_text_width == engine::kLegendTextWidth);
    for (const browser::LegendEntry& entry : document.legend) {
        INFO(entry.text);
        CHECK(browser::text_width(entry.text) <= engine::kLegendTextWidth);
    }
    const std::vector<browser::LegendBox> boxes = browser::legend_boxes(document);
    REQUIRE(boxes.size() == document.legend.size());
    CHECK(boxes[0].left == 10);
    CHECK(boxes[(engine::kLegendEntries + 1) / 2].left == 10 + 12 + 6 + 460 + 6);  // the second column
    CHECK(test::entryOffThePage(document, page_width).value_or("none") == "none");
    CHECK(browser::render_page(document).width == page_width);
    CHECK(continuedInItsColumn(document));
    // The same legend in the narrower columns of the stages before runs off the page.
    document.legend_text_width = browser::kLegendTextWidth;
    CHECK(test::entryOffThePage(document, page_width).has_value());
    // The joints' layer alone, in a run that shows no other: 7 entries in rows of 4.
    ragdoll.page.window.overlay_all = ragdoll.page.window.every_layer_possible = false;
    ragdoll.run(1);
    const browser::Document& own = ragdoll.page.window.document;
    REQUIRE(own.legend.size() == engine::kOwnLegendEntries);
    CHECK(test::entryOffThePage(own, page_width).value_or("none") == "none");
    CHECK(continuedInItsColumn(own));
}

// The pendulums hang from pins on the canvas's top edge, y = 50: the bracket's at x =
// 640, where its limit events are drawn. GJK's row of panels (two: one pass and the
// answer, for the selected pin and its bob) in the top right corner would reach from
// x = 900 - 8 - 278 = 614 to 892 and from y = 8 to 116, over that pin; the top left
// holds two pins (80 and 230), the bottom right nothing: the panels go there.
TEST_CASE("s5_9: GJK's panels keep off the pendulums' pins, in the corner the scene leaves empty", "[drawing]") {
    EveryLayerRun pendulum("pendulum.json");
    pendulum.run(141);
    const engine::Core& core = pendulum.page.core;
    const std::optional<engine::GjkDiagram> diagram = engine::gjkDiagram(core);
    REQUIRE(diagram);
    const std::size_t panels = diagram->steps.size() + 1;
    const std::vector<Vec2> corners = engine::gjkPanelCorners(panels, 900, 450, engine::shapeBoxes(core));
    REQUIRE(corners.size() == panels);
    const auto covers = [&](const std::vector<Vec2>& at, Vec2 point) {
        return std::any_of(at.begin(), at.end(), [&](Vec2 corner) {
            return corner.x <= point.x && point.x <= corner.x + engine::kGjkPanelWidth && corner.y <= point.y &&
                   point.y <= corner.y + engine::kGjkPanelHeight;
        });
    };
    for (const Vec2 pin : {Vec2{80, 50}, Vec2{230, 50}, Vec2{420, 50}, Vec2{640, 50}}) {
        INFO("pin at " << pin.x << ", " << pin.y);
        CHECK_FALSE(covers(corners, pin));
    }
    CHECK(corners.back().y == 450 - 8 - 108);  // the bottom row
    CHECK(corners.back().x == 900 - 8 - 136);  // right-aligned
    // Along the top edge, as before, they cover the bracket's pin.
    CHECK(covers(engine::gjkPanelCorners(panels, 900), Vec2{640, 50}));
}

}  // namespace s5_9_drawing_test
