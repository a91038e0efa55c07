// Stage 3.2: the pass now runs the narrow phase, from object 0 on, and draws each
// collision as an orange line; only circles can collide yet.
#include <catch2/catch.hpp>

#include "book_scene.h"
#include "circle.h"
#include "physics.h"
#include "rectangle.h"
#include "near.h"
#include "stage_fixture.h"
#include "walkthrough.h"

namespace s3_2_test {

using engine::Vec2;

TEST_CASE("s3_2: rectangles report no collision yet, with rectangles or circles") {
    const engine::Rectangle box({100, 100}, 40, 20);
    const engine::Circle ball({100, 100}, 10);
    CHECK_FALSE(box.collisionTest(box).has_value());
    CHECK_FALSE(box.collisionTest(ball).has_value());
    CHECK_FALSE(ball.collisionTest(box).has_value());
    CHECK_FALSE(engine::findCollision(box, box).has_value());
    CHECK_FALSE(engine::findCollision(ball, box).has_value());
}

TEST_CASE("s3_2: the pass starts at object 0 and keeps each normal from first to second") {
    test::StageFixture page;
    page.core.add(engine::Circle({130, 100}, 20));         // 0
    page.core.add(engine::Circle({100, 100}, 20));         // 1: overlaps 0 by 10
    page.core.add(engine::Rectangle({115, 100}, 50, 50));  // 2: over both, but a rectangle
    page.frame();
    const auto& found = page.core.physics().collisions();
    REQUIRE(found.size() == 1);
    CHECK(found[0].first == 0);
    CHECK(found[0].second == 1);
    // From circle 0 to circle 1 is to the left.
    CHECK(found[0].info.normal() == Vec2{-1, 0});
    CHECK(found[0].info.depth() == 10);
}

TEST_CASE("s3_2: each collision is drawn as an orange line from start to end") {
    test::StageFixture page;
    page.core.add(engine::Rectangle({700, 400}, 3, 3));  // a selected object away from the rest
    // Centres on pixel centres, 30 apart on the row y = 100.5, radii 20: depth 10, and
    // the segment runs from x = 110.5 (the right circle's rim) to 120.5 (the left one's).
    page.core.add(engine::Circle({100.5, 100.5}, 20));
    page.core.add(engine::Circle({130.5, 100.5}, 20));
    page.frame();
    const browser::Color middle = page.window.document.canvas.pixels().at(115, 100);
    CHECK(middle == browser::colors::kOrange);
    // Pulled apart, the line goes.
    page.press(browser::Key::Digit2);
    page.press(browser::Key::D, 2);
    page.frame();
    CHECK(page.window.document.canvas.pixels().at(115, 100) == browser::colors::kWhite);
}

TEST_CASE("s3_2: a frame that runs no update draws no collision line") {
    // As in the book, the lines come from the frame's own collision pass: a frame too
    // short for a step (5 ms of 16.7) shows the shapes alone.
    test::StageFixture page(1, 5.0);
    page.core.add(engine::Rectangle({700, 400}, 3, 3));
    page.core.add(engine::Circle({100.5, 100.5}, 20));
    page.core.add(engine::Circle({130.5, 100.5}, 20));
    const auto middle = [&] { return page.window.document.canvas.pixels().at(115, 100); };
    for (int k = 0; k < 3; ++k) {  // 5, 10 and 15 ms: no step yet
        page.frame();
        CHECK(middle() == browser::colors::kWhite);
    }
    page.frame();  // 20 ms: one step, and its pass's line
    CHECK(middle() == browser::colors::kOrange);
    page.frame();  // 25 ms: no step
    CHECK(middle() == browser::colors::kWhite);
}

// The README's walkthrough ("Play it live"): two circles 30 px apart, two rectangles.
TEST_CASE("s3_2: README walkthrough: the two circles collide, the rectangles report nothing") {
    test::StageFixture page;
    test::buildBookScene(page.core, page.random);
    test::playScript(page, "g d*3 g d*8 f d*2 f", 1);
    const auto& first = static_cast<const engine::Circle&>(page.core.object(5));
    const auto& second = static_cast<const engine::Circle&>(page.core.object(6));
    REQUIRE(second.center().x - first.center().x == 30.0);
    const auto& found = page.core.physics().collisions();
    REQUIRE(found.size() == 1);
    CHECK(found[0].first == 5);
    CHECK(found[0].second == 6);
    // Radii of 20 px and more, 30 px apart: they overlap by the radii minus 30, along +x.
    CHECK_THAT(found[0].info.depth(), test::near(first.radius() + second.radius() - 30.0, 1e-12));
    CHECK_THAT(found[0].info.normal(), test::near(Vec2{1, 0}, 1e-12));
}

}  // namespace s3_2_test
