// Selecting objects and creating shapes with the keys (every stage from 2.1 on).
#include <catch2/catch.hpp>

#include "my_game.h"
#include "stage_fixture.h"

using browser::Key;

TEST_CASE("object selection: digit keys select an existing object, and only one") {
    test::StageFixture page;
    engine::buildScene(page.core);
    const std::size_t count = page.core.objectCount();
    REQUIRE(count >= 4);
    page.press(Key::Digit3);
    CHECK(page.core.selectedIndex() == 3);
    page.press(Key::Digit9);  // past the end of the scene: ignored
    CHECK(page.core.selectedIndex() == 3);
    page.press(Key::Digit0);
    CHECK(page.core.selectedIndex() == 0);
}

TEST_CASE("object selection: Up and Down step through the list and stop at its ends") {
    test::StageFixture page;
    engine::buildScene(page.core);
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
    engine::buildScene(page.core);
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

TEST_CASE("object selection: every key on an empty world does nothing and does not crash") {
    test::StageFixture page;
    for (Key key : {Key::Digit0, Key::Digit5, Key::Up, Key::Down, Key::W, Key::A, Key::S, Key::D, Key::Q,
                    Key::E, Key::H, Key::R, Key::Comma, Key::M, Key::I, Key::U, Key::Z, Key::X, Key::C, Key::V,
                    Key::B, Key::N}) {
        page.press(key);
        CHECK(page.core.selectedIndex() == 0);
    }
    page.frame();  // the echo and the drawing cope with nothing to show
}
