// Stage 2.2: the stand-in behaviour that shows the loop running (a shape sinks 1 px per
// update while it is above the bottom and not fixed) and the H key that fixes it.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

#include "circle.h"
#include "core.h"
#include "my_game.h"
#include "rectangle.h"
#include "stage_fixture.h"
#include "walkthrough.h"

namespace s2_2_test {

using browser::Key;
using engine::Vec2;

namespace {
// How many updates the core's loop has run so far: every whole step of the elapsed
// time, less the lag it still carries. (Counted rather than assumed: the simulated
// clock's frames of 1000/60 ms do not always run exactly one update each.)
int updatesSoFar(const test::StageFixture& page) {
    const double run_ms = page.window.clock.nowMs() - page.core.timer().lagMs();
    return static_cast<int>(std::lround(run_ms / engine::kMPF));
}
}  // namespace

TEST_CASE("s2_2: a free shape sinks 1 px per update until its centre reaches the bottom") {
    test::StageFixture page;
    engine::Circle& ball = page.core.add(engine::Circle({100, 440}, 20));
    const engine::Rectangle& pinned = page.core.add(engine::Rectangle({300, 100}, 20, 20, true));
    for (int k = 1; k <= 5; ++k) {
        page.frame();
        CHECK(ball.center() == Vec2{100, 440.0 + updatesSoFar(page)});
    }
    for (int k = 0; k < 20; ++k) page.frame();
    CHECK(ball.center() == Vec2{100, 450});  // 450 is not above the bottom: it stops there
    CHECK(pinned.center() == Vec2{300, 100});
}

TEST_CASE("s2_2: a 50 ms frame runs two updates, then draws the result once") {
    // Three steps of 1000/60 ms add up to a hair more than 50 ms in floating point, so
    // the book's loop runs two and carries almost a whole step to the next frame.
    test::StageFixture page(1, 50.0);
    page.core.add(engine::Circle({100, 100}, 20));
    page.frame();
    CHECK(page.core.object(0).center() == Vec2{100, 102});
    CHECK(page.window.document.ui_echo.find("Center: 100,102") != std::string::npos);
    // The drawing shows the circle after the two updates: its lowest point is at y = 122.
    const browser::Image& pixels = page.window.document.canvas.pixels();
    CHECK(pixels.at(100, 121).r > 128);                    // selected (object 0), so red
    CHECK(pixels.at(100, 80) == browser::colors::kWhite);  // its old top, y = 80, is clear
}

TEST_CASE("s2_2: H toggles whether the selected object is fixed") {
    test::StageFixture page;
    engine::RigidShape& box = page.core.add(engine::Rectangle({200, 200}, 30, 30));
    page.press(Key::H);
    CHECK(box.isFixed());
    page.frame();
    CHECK(box.center() == Vec2{200, 200});
    page.press(Key::H);
    CHECK_FALSE(box.isFixed());
    page.frame();
    CHECK(box.center() == Vec2{200, 201});
}

TEST_CASE("s2_2: R keeps the cursor and the four borders, and nothing after them") {
    // The book's scene: the cursor at the canvas centre, then the borders along the top,
    // bottom, left and right edges of the 800 x 450 canvas. Shapes made with F and G
    // (from the selected, moved cursor) come after them, and R takes them all away.
    test::StageFixture page;
    engine::buildScene(page.core);
    const std::vector<Vec2> kept{{400, 225}, {400, 0}, {400, 450}, {0, 225}, {800, 225}};
    page.press(Key::Digit0);
    page.press(Key::A, 3);
    page.press(Key::F, 4);
    page.press(Key::G, 3);
    REQUIRE(page.core.objectCount() == 12);
    page.press(Key::Down, 20);
    REQUIRE(page.core.selectedIndex() == 11);
    page.press(Key::R);
    REQUIRE(page.core.objectCount() == kept.size());
    CHECK(page.core.selectedIndex() == 0);
    CHECK(page.core.object(0).center() == Vec2{370, 225});  // the cursor, where A left it
    for (std::size_t i = 1; i < kept.size(); ++i) CHECK(page.core.object(i).center() == kept[i]);
    page.press(Key::R);  // nothing left to take
    CHECK(page.core.objectCount() == kept.size());
}

// The README's walkthrough ("Play it live"): two shapes at the cursor (5, 6), two more
// 150 px to the right at frame 20 (7, 8), then shape 8 fixed at frame 60.
TEST_CASE("s2_2: README walkthrough: the shapes sink, and the fixed one stays where it was fixed") {
    test::StageFixture page;
    engine::buildScene(page.core);
    const std::string script = "f g 0@20 d*15 f g 8@60 h";
    test::playScript(page, script, 0, 21);
    REQUIRE(page.core.objectCount() == 9);
    CHECK(page.core.object(7).center().x - page.core.object(5).center().x == 150.0);
    test::playScript(page, script, 21, 61);  // H pressed before frame 60
    const Vec2 fixed_at = page.core.object(8).center();
    const double first_at = page.core.object(5).center().y, third_at = page.core.object(7).center().y;
    test::playScript(page, script, 61, 150);
    CHECK(page.core.object(8).center() == fixed_at);
    CHECK(page.core.object(5).center().y > first_at);
    CHECK(page.core.object(7).center().y > third_at);
}

}  // namespace s2_2_test
