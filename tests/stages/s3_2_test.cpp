// Stage 3.2: the pass now runs the narrow phase, from object 0 on, and draws each
// collision as an orange line; only circles can collide yet.
#include <catch2/catch.hpp>

#include "book_scene.h"
#include "circle.h"
#include "expect.h"
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
    test::requireEqual("pairs the pass found: the two circles (a rectangle reports nothing yet)", 1u, found.size());
    test::expectEqual("the pair's first object: the pass starts at object 0", 0u, found[0].first);
    test::expectEqual("the pair's second object", 1u, found[0].second);
    // From circle 0 to circle 1 is to the left.
    test::expectEqual("the collision normal, from the first circle (x 130) to the second (x 100)", Vec2{-1, 0},
                      found[0].info.normal());
    test::expectEqual("the collision depth, px: radii 20 + 20, centres 30 apart", 10.0, found[0].info.depth());
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
    test::expectEqual("pixel (115, 100), the middle of the collision line from start to end", browser::colors::kOrange,
                      middle);
    // Pulled apart, the line goes.
    page.press(browser::Key::Digit2);
    page.press(browser::Key::D, 2);
    page.frame();
    test::expectEqual("pixel (115, 100) once the circles are pulled apart: no line", browser::colors::kWhite,
                      page.window.document.canvas.pixels().at(115, 100));
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
        INFO("frame " << k << ", at " << 5 * (k + 1) << " ms");
        test::expectEqual("the collision line's middle, pixel (115, 100), in a frame that ran no update",
                          browser::colors::kWhite, middle());
    }
    page.frame();  // 20 ms: one step, and its pass's line
    test::expectEqual("the collision line's middle, pixel (115, 100), in the frame at 20 ms, which ran an update",
                      browser::colors::kOrange, middle());
    page.frame();  // 25 ms: no step
    test::expectEqual("the collision line's middle, pixel (115, 100), at 25 ms: no update, no line",
                      browser::colors::kWhite, middle());
}

// The README's walkthrough ("Play it live"): two circles 30 px apart, two rectangles.
TEST_CASE("s3_2: README walkthrough: the two circles collide, the rectangles report nothing") {
    test::StageFixture page;
    test::buildBookScene(page.core, page.random);
    test::playScript(page, "g d*3 g d*8 f d*2 f", 1);
    const auto& first = static_cast<const engine::Circle&>(page.core.object(5));
    const auto& second = static_cast<const engine::Circle&>(page.core.object(6));
    test::requireEqual("the distance between the two circles' centres after the walkthrough's keys, px", 30.0,
                       second.center().x - first.center().x);
    const auto& found = page.core.physics().collisions();
    test::requireEqual("pairs the pass found: the two circles (the rectangles report nothing yet)", 1u, found.size());
    test::expectEqual("the pair's first object: the first circle", 5u, found[0].first);
    test::expectEqual("the pair's second object: the second circle", 6u, found[0].second);
    // Radii of 20 px and more, 30 px apart: they overlap by the radii minus 30, along +x.
    CHECK_THAT(found[0].info.depth(), test::near(first.radius() + second.radius() - 30.0, 1e-12));
    CHECK_THAT(found[0].info.normal(), test::near(Vec2{1, 0}, 1e-12));
}

}  // namespace s3_2_test
