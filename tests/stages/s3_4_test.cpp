// Stage 3.4: rectangles and circles collide with each other too. Here: the README's
// walkthrough.
#include <catch2/catch.hpp>

#include <optional>

#include "book_scene.h"
#include "collision_checks.h"
#include "collision_info.h"
#include "expect.h"
#include "physics.h"
#include "stage_fixture.h"
#include "walkthrough.h"

namespace s3_4_test {

namespace {

std::optional<engine::CollisionInfo> infoOf(const engine::Physics& physics, std::size_t first, std::size_t second) {
    for (const engine::Collision& pair : physics.collisions()) {
        if (pair.first == first && pair.second == second) return pair.info;
    }
    return std::nullopt;
}

bool same(const engine::CollisionInfo& a, const engine::CollisionInfo& b) {
    return a.depth() == b.depth() && a.normal() == b.normal() && a.start() == b.start();
}

}  // namespace

// A rectangle (5) and a circle (6) 30 px to its right; the circle turned at frame 30,
// the rectangle at frame 60.
TEST_CASE("s3_4: README walkthrough: turning the circle leaves the line, turning the rectangle moves it") {
    test::StageFixture page;
    test::buildBookScene(page.core, page.random);
    test::playScript(page, "f d*3 g", 30);
    const auto start = infoOf(page.core.physics(), 5, 6);
    test::requireEqual("a collision of the rectangle (object 5) and the circle (6) 30 px to its right", true,
                       start.has_value());
    // Only the circle's centre and radius count: not a bit of the info changes.
    test::playScript(page, "6 e*5", 30);
    const auto circle_turned = infoOf(page.core.physics(), 5, 6);
    test::requireEqual("a collision of the rectangle and the circle once the circle is turned", true,
                       circle_turned.has_value());
    INFO("before: " << Catch::Detail::stringify(*start) << "; after: " << Catch::Detail::stringify(*circle_turned));
    test::expectEqual("the collision info, unchanged when the circle turns (only its centre and radius count)", true,
                      same(*circle_turned, *start));
    // The rectangle's faces do count.
    test::playScript(page, "5 e*3", 30);
    const auto box_turned = infoOf(page.core.physics(), 5, 6);
    test::requireEqual("a collision of the rectangle and the circle once the rectangle is turned", true,
                       box_turned.has_value());
    INFO("before: " << Catch::Detail::stringify(*start) << "; after: " << Catch::Detail::stringify(*box_turned));
    test::expectEqual("the collision info, changed when the rectangle turns (its faces count)", false,
                      same(*box_turned, *start));
}

}  // namespace s3_4_test
