// Stage 2.1: F and G create shapes of the book's random sizes at random places.
#include <catch2/catch.hpp>

#include <algorithm>
#include <string>

#include "circle.h"
#include "my_game.h"
#include "rectangle.h"
#include "stage_fixture.h"
#include "walkthrough.h"

namespace s2_1_test {

using browser::Key;

TEST_CASE("s2_1: F creates a 10-40 px rectangle centred in the top-left 80% of the canvas") {
    double smallest = 1e9, largest = 0;
    for (std::uint64_t seed = 1; seed <= 300; ++seed) {
        test::StageFixture page(seed);
        page.press(Key::F);
        REQUIRE(page.core.objectCount() == 1);
        const auto& box = dynamic_cast<const engine::Rectangle&>(page.core.object(0));
        CHECK(box.center().x >= 0);
        CHECK(box.center().x < 640);  // 0.8 * 800
        CHECK(box.center().y >= 0);
        CHECK(box.center().y < 360);  // 0.8 * 450
        for (double side : {box.width(), box.height()}) {
            CHECK(side >= 10);
            CHECK(side < 40);
            smallest = std::min(smallest, side);
            largest = std::max(largest, side);
        }
    }
    CHECK(smallest < 11);  // 600 uniform draws reach both ends of the range
    CHECK(largest > 39);
}

TEST_CASE("s2_1: G creates a circle of radius 20-30 px centred in the top-left 80%") {
    double smallest = 1e9, largest = 0;
    for (std::uint64_t seed = 1; seed <= 300; ++seed) {
        test::StageFixture page(seed);
        page.press(Key::G);
        const auto& ball = dynamic_cast<const engine::Circle&>(page.core.object(0));
        CHECK(ball.center().x < 640);
        CHECK(ball.center().y < 360);
        CHECK(ball.radius() >= 20);
        CHECK(ball.radius() < 30);
        smallest = std::min(smallest, ball.radius());
        largest = std::max(largest, ball.radius());
    }
    CHECK(smallest < 20.5);
    CHECK(largest > 29.5);
}

TEST_CASE("s2_1: the selected object is red, the others blue, and the echo names it") {
    test::StageFixture page;
    // Left sides on x = 80.5 and 280.5, through the middle of pixel columns 80 and 280.
    page.core.add(engine::Rectangle({100.5, 100}, 40, 40));
    page.core.add(engine::Rectangle({300.5, 100}, 40, 40));
    page.press(Key::Digit1);
    page.frame();
    const browser::Image& pixels = page.window.document.canvas.pixels();
    CHECK(pixels.at(280, 100).r > 200);  // red
    CHECK(pixels.at(280, 100).b < 60);
    CHECK(pixels.at(80, 100).b > 200);  // blue
    CHECK(pixels.at(80, 100).r < 60);
    CHECK(page.window.document.ui_echo.find("Id: 1") != std::string::npos);
    CHECK(page.window.document.ui_echo.find("Center: 301,100") != std::string::npos);
}

// The README's walkthrough ("Play it live"): two of each shape, then object 6 selected.
TEST_CASE("s2_1: README walkthrough: the selected shape turns red, the echo names it") {
    test::StageFixture page;
    engine::buildScene(page.core);
    test::playScript(page, "f g f g 6", 1);
    REQUIRE(page.core.objectCount() >= 7);
    CHECK(page.core.selectedIndex() == 6);
    CHECK(page.window.document.ui_echo.find("Id: 6") != std::string::npos);
    // Red is drawn for the selected shape only: some pixels are red, and blue ones remain.
    const browser::Image& pixels = page.window.document.canvas.pixels();
    int red = 0, blue = 0;
    for (int j = 0; j < pixels.height; ++j) {
        for (int i = 0; i < pixels.width; ++i) {
            const browser::Color c = pixels.at(i, j);
            if (c.r > 200 && c.g < 60 && c.b < 60) ++red;
            if (c.b > 200 && c.r < 60 && c.g < 60) ++blue;
        }
    }
    CHECK(red > 0);
    CHECK(blue > 0);
}

}  // namespace s2_1_test
