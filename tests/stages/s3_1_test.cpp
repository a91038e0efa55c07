// Stage 3.1: the collision pass of the broad phase. It starts after the cursor and the
// borders, reports every pair of overlapping bounding circles once, and the colliding
// shapes are drawn green. Nothing moves by itself any more, and H is gone.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdlib>
#include <string>

#include "book_scene.h"
#include "circle.h"
#include "my_game.h"
#include "physics.h"
#include "rectangle.h"
#include "stage_fixture.h"
#include "walkthrough.h"

namespace s3_1_test {

using browser::Key;
using engine::Vec2;

namespace {

bool reported(const engine::Physics& physics, std::size_t first, std::size_t second) {
    return std::ranges::any_of(physics.collisions(), [&](const engine::Collision& pair) {
        return pair.first == first && pair.second == second;
    });
}

bool looksGreen(browser::Color c) { return c.g > c.r + 40 && c.g > c.b + 40; }
bool looksBlue(browser::Color c) { return c.b > c.r + 40 && c.b > c.g + 40; }

}  // namespace

TEST_CASE("s3_1: the pass leaves out the cursor and the borders, and reports a pair once") {
    test::StageFixture page;
    test::buildBookScene(page.core, page.random);
    REQUIRE(engine::Physics::kFirstTestedObject == 5);
    // Objects 5 and 6 sit on the cursor (object 0); 7 is far from both.
    page.core.add(engine::Circle({400, 225}, 20));
    page.core.add(engine::Rectangle({400, 225}, 30, 10));
    page.core.add(engine::Circle({100, 100}, 20));
    page.frame();
    const auto& found = page.core.physics().collisions();
    REQUIRE(found.size() == 1);
    CHECK(reported(page.core.physics(), 5, 6));
}

TEST_CASE("s3_1: every overlapping pair, in the order i < j, and no other") {
    test::StageFixture page;
    test::buildBookScene(page.core, page.random);
    // Three circles of radius 10 on a line, 15 apart: neighbours overlap, the ends (30
    // apart, 20 needed) do not. A fourth touches the third exactly (20 apart).
    page.core.add(engine::Circle({100, 100}, 10));  // 5
    page.core.add(engine::Circle({115, 100}, 10));  // 6
    page.core.add(engine::Circle({130, 100}, 10));  // 7
    page.core.add(engine::Circle({150, 100}, 10));  // 8
    page.frame();
    const auto& found = page.core.physics().collisions();
    CHECK(found.size() == 3);
    CHECK(reported(page.core.physics(), 5, 6));
    CHECK(reported(page.core.physics(), 6, 7));
    CHECK(reported(page.core.physics(), 7, 8));
}

TEST_CASE("s3_1: colliding shapes are drawn green, the others keep their colour") {
    test::StageFixture page;
    test::buildBookScene(page.core, page.random);
    // Centres on pixel centres, so the leftmost point of each outline is the centre of a
    // pixel that the pen covers fully: (180.5, 100.5) is pixel (180, 100).
    page.core.add(engine::Circle({200.5, 100.5}, 20));  // 5
    page.core.add(engine::Circle({230.5, 100.5}, 20));  // 6: overlaps 5
    page.core.add(engine::Circle({500.5, 300.5}, 20));  // 7: alone
    page.frame();
    const browser::Image& pixels = page.window.document.canvas.pixels();
    CHECK(looksGreen(pixels.at(180, 100)));
    CHECK(looksBlue(pixels.at(480, 300)));
    // Moving circle 6 away turns both back to blue at the next pass.
    page.press(Key::Digit6);
    page.press(Key::D, 5);  // 50 px: centres 80 apart
    page.press(Key::Digit0);
    page.frame();
    CHECK(page.core.physics().collisions().empty());
    CHECK(looksBlue(page.window.document.canvas.pixels().at(180, 100)));
}

TEST_CASE("s3_1: nothing moves by itself, and H is gone from the keys and the echo") {
    test::StageFixture page;
    test::buildBookScene(page.core, page.random);
    engine::Circle& ball = page.core.add(engine::Circle({300, 100}, 20));
    page.press(Key::Digit5);
    page.press(Key::H);
    for (int k = 0; k < 30; ++k) page.frame();
    CHECK(ball.center() == Vec2{300, 100});
    const std::string& echo = page.window.document.ui_echo;
    CHECK(echo.find("H:") == std::string::npos);
    CHECK(echo.find("R: Reset System") != std::string::npos);
}

TEST_CASE("s3_1: a reset in a frame that runs no update draws no removed shape") {
    test::StageFixture page(1, 5.0);  // 5 ms frames: most run no update
    test::buildBookScene(page.core, page.random);
    page.press(Key::F);
    page.press(Key::G);
    for (int k = 0; k < 4; ++k) page.frame();  // 20 ms: one pass has seen objects 5 and 6
    REQUIRE_FALSE(page.core.physics().collisions().empty());
    page.press(Key::R);
    page.frame();
    CHECK(page.core.objectCount() == 5);
}

TEST_CASE("s3_1: the overlay joins each pair the broad phase passed, and rings each rectangle's bounding circle") {
    test::StageFixture page;
    test::buildBookScene(page.core, page.random);
    // Two circles of radius 15 whose centres are 25 apart (25 <= 30: they pass), on the
    // row of pixel centres y = 100.5; a 30 x 40 rectangle alone, bounding radius
    // sqrt(15^2 + 20^2) = 25.
    page.core.add(engine::Circle({100.5, 100.5}, 15));         // 5
    page.core.add(engine::Circle({125.5, 100.5}, 15));         // 6
    page.core.add(engine::Rectangle({300.5, 300.5}, 30, 40));  // 7
    page.frame();
    const browser::Image& off = page.window.document.canvas.pixels();
    CHECK(off.at(103, 100) == browser::colors::kWhite);  // off by default: the book's picture
    CHECK(off.at(325, 300) == browser::colors::kWhite);
    CHECK(page.window.document.legend.empty());

    page.window.overlay = true;
    page.frame();
    const browser::Image& on = page.window.document.canvas.pixels();
    // (103.5, 100.5) is on the line between the centres and 12 px from circle 5's outline
    // (at x = 85.5 and 115.5) and circle 6's (110.5): the pair's purple, fully.
    CHECK(on.at(103, 100) == browser::Color{160, 0, 200, 255});
    // The ring of radius 25 about (300.5, 300.5) passes through the centre of pixel
    // (325, 300), 10 px right of the rectangle's side: gray, to a few levels.
    CHECK(on.at(325, 300).r == on.at(325, 300).b);
    CHECK(std::abs(on.at(325, 300).r - 150) <= 4);
    // Three tested shapes make three pairs; one passed.
    const auto& legend = page.window.document.legend;
    REQUIRE(legend.size() == 3);
    CHECK(legend[2].text == "1 of 3 pairs passed");
}

// The README's walkthrough ("Play it live"): a rectangle (5) and a circle (6) at the
// cursor, then the circle moved right 10 px a press, then the rectangle turned.
TEST_CASE("s3_1: README walkthrough: green while the bounding circles overlap, and turning changes nothing") {
    test::StageFixture page;
    test::buildBookScene(page.core, page.random);
    test::playScript(page, "f g", 1);
    const engine::RigidShape& box = page.core.object(5);
    const engine::RigidShape& ball = page.core.object(6);
    CHECK(reported(page.core.physics(), 5, 6));
    // Ten presses of D, 10 px each: the pair is reported exactly while the centres are
    // no farther apart than the two bounding radii, and by the tenth (100 px) they are.
    for (int press = 1; press <= 10; ++press) {
        test::playScript(page, "6 d 0", 1);
        const double apart = ball.center().x - box.center().x;
        CHECK(apart == 10.0 * press);
        CHECK(reported(page.core.physics(), 5, 6) == (apart <= box.boundRadius() + ball.boundRadius()));
    }
    CHECK_FALSE(reported(page.core.physics(), 5, 6));
    // A bounding circle is the same at every angle: turning the box decides nothing.
    test::playScript(page, "5 e*2 0", 1);
    CHECK_FALSE(reported(page.core.physics(), 5, 6));
}

}  // namespace s3_1_test
