// Selecting objects and creating shapes with the keys (every stage from 2.1 on).
#include <catch2/catch.hpp>

#include <string>

#include "book_scene.h"
#include "my_game.h"
#include "rectangle.h"
#include "stage_fixture.h"

namespace object_selection_test {

using browser::Key;

TEST_CASE("object selection: digit keys select an existing object, and only one") {
    test::StageFixture page;
    for (double x : {100.0, 200.0, 300.0, 400.0}) page.core.add(engine::Rectangle({x, 100}, 20, 20));
    page.press(Key::Digit3);
    CHECK(page.core.selectedIndex() == 3);
    page.press(Key::Digit9);  // past the end of the four: ignored
    CHECK(page.core.selectedIndex() == 3);
    page.press(Key::Digit0);
    CHECK(page.core.selectedIndex() == 0);
}

TEST_CASE("object selection: Up and Down step through the list and stop at its ends") {
    test::StageFixture page;
    test::buildBookScene(page.core, page.random);
    const std::size_t last = page.core.objectCount() - 1;
    page.press(Key::Up);
    CHECK(page.core.selectedIndex() == 0);
    page.press(Key::Down, 2);
    CHECK(page.core.selectedIndex() == 2);
    page.press(Key::Down, 100);
    CHECK(page.core.selectedIndex() == last);
    page.press(Key::Up);
    CHECK(page.core.selectedIndex() == last - 1);
}

TEST_CASE("object selection: F adds one rectangle and G one circle at the end of the list") {
    test::StageFixture page;
    test::buildBookScene(page.core, page.random);
    const std::size_t before = page.core.objectCount();
    page.press(Key::F);
    REQUIRE(page.core.objectCount() == before + 1);
    CHECK(page.core.object(before).type() == engine::ShapeType::Rectangle);
    page.press(Key::G);
    REQUIRE(page.core.objectCount() == before + 2);
    CHECK(page.core.object(before + 1).type() == engine::ShapeType::Circle);
    page.press(Key::Digit0);
    page.press(Key::Down, static_cast<int>(before + 5));
    CHECK(page.core.selectedIndex() == before + 1);
}

TEST_CASE("object selection: every key on an empty world leaves it empty, and the frame shows nothing") {
    // The keys that act on the selected object must not reach for object 0 when there
    // is none (core.object() would throw), nor make one.
    test::StageFixture page;
    for (Key key :
         {Key::Digit0, Key::Digit5, Key::Up, Key::Down, Key::W, Key::A, Key::S, Key::D, Key::Q, Key::E, Key::H,
          Key::R,      Key::Comma,  Key::M,  Key::I,    Key::U, Key::Z, Key::X, Key::C, Key::V, Key::B, Key::N}) {
        page.press(key);
        CHECK(page.core.objectCount() == 0);
        CHECK(page.core.selectedIndex() == 0);
    }
    page.frame();
    CHECK(page.window.document.ui_echo.find("Id: none\n") != std::string::npos);
    const browser::Image& pixels = page.window.document.canvas.pixels();
    int drawn = 0;
    for (int y = 0; y < pixels.height; ++y) {
        for (int x = 0; x < pixels.width; ++x) drawn += pixels.at(x, y) == browser::colors::kWhite ? 0 : 1;
    }
    CHECK(drawn == 0);
}

}  // namespace object_selection_test
