// W/A/S/D move and Q/E turn the selected object; R resets the world (every stage from 2.2 on).
#include <catch2/catch.hpp>

#include <string>

#include "book_scene.h"
#include "expect.h"
#include "my_game.h"
#include "near.h"
#include "rectangle.h"
#include "stage_fixture.h"

namespace user_control_move_test {

using browser::Key;
using engine::Vec2;

TEST_CASE("user control: W A S D move the selected object 10 px, Q E turn it 0.1 rad") {
    test::StageFixture page;
    test::buildBookScene(page.core, page.random);
    page.press(Key::Digit0);
    const engine::RigidShape& cursor = page.core.object(0);
    const Vec2 start = cursor.center();
    const double angle = cursor.angle();
    const Vec2 other = page.core.object(1).center();
    page.press(Key::W);
    CHECK(cursor.center() == Vec2{start.x, start.y - 10});  // up is -y on the canvas
    page.press(Key::D, 3);
    CHECK(cursor.center() == Vec2{start.x + 30, start.y - 10});
    page.press(Key::S, 2);
    page.press(Key::A);
    CHECK(cursor.center() == Vec2{start.x + 20, start.y + 10});
    page.press(Key::E, 3);
    // 1e-14 rad: three additions of 0.1 to an angle of up to 3 rad round by a few 1e-16.
    CHECK_THAT(cursor.angle(), test::near(angle + 0.3, 1e-14));
    page.press(Key::Q);
    CHECK_THAT(cursor.angle(), test::near(angle + 0.2, 1e-14));
    // Only the selected object moved.
    CHECK(page.core.object(1).center() == other);
}

TEST_CASE("user control: F and G create the new shape at the selected object") {
    test::StageFixture page;
    test::buildBookScene(page.core, page.random);
    page.press(Key::Digit0);
    page.press(Key::A, 5);
    const Vec2 cursor = page.core.object(0).center();
    page.press(Key::F);
    page.press(Key::G);
    const std::size_t n = page.core.objectCount();
    CHECK(page.core.object(n - 2).center() == cursor);
    CHECK(page.core.object(n - 1).center() == cursor);
}

TEST_CASE("user control: R keeps exactly the first kKeptOnReset objects and selects object 0") {
    constexpr std::size_t kKept = engine::UserControl::kKeptOnReset;
    test::StageFixture page;
    test::buildBookScene(page.core, page.random);
    page.press(Key::Digit0);
    page.press(Key::F, 6);
    page.press(Key::G, 6);
    REQUIRE(page.core.objectCount() > kKept);
    page.press(Key::Down, 100);
    page.press(Key::R);
    test::expectEqual("objects after R: the ones of the scene R keeps (UserControl::kKeptOnReset)", kKept,
                      page.core.objectCount());
    test::expectEqual("the selected index after R, which removed the selected shape: object 0", 0,
                      page.core.selectedIndex());
    page.press(Key::R);  // nothing more to remove
    test::expectEqual("objects after R again: nothing more to remove", kKept, page.core.objectCount());
}

TEST_CASE("user control: a world of one object takes every key without leaving the list") {
    // The selection keys cannot select past the only object, R keeps it, and the keys
    // that move and turn it still act on it.
    test::StageFixture page;
    const engine::RigidShape& box = page.core.add(engine::Rectangle({100, 100}, 20, 20));
    for (Key key : {Key::Up, Key::Down, Key::Digit1, Key::Digit9, Key::W, Key::Q, Key::R, Key::H}) {
        page.press(key);
        CHECK(page.core.selectedIndex() == 0);
        CHECK(page.core.objectCount() == 1);
    }
    CHECK(box.center() == Vec2{100, 90});
    CHECK(box.angle() == -0.1);
    page.frame();
    CHECK(page.window.document.ui_echo.find("Id: 0\n") != std::string::npos);
}

}  // namespace user_control_move_test
