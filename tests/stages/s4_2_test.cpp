// Stage 4.2: colliding shapes are pushed apart, but their velocities are left alone;
// the echo shows the positional-correction flag; two static shapes are still tested.
#include <catch2/catch.hpp>

#include <string>

#include "book_scene.h"
#include "circle.h"
#include "expect.h"
#include "my_game.h"
#include "physics.h"
#include "stage_fixture.h"
#include "walkthrough.h"
#include "world_fixture.h"

namespace s4_2_test {

using engine::Vec2;

TEST_CASE("s4_2: shapes that meet are kept apart, but keep their velocities") {
    test::WorldFixture page(test::world(true, {0, 0}));
    const test::ApproachingCircles pair(page);
    engine::Circle& left = pair.left;
    engine::Circle& right = pair.right;
    double closest = 30;
    for (int step = 0; step < 30; ++step) {
        page.steps(1);
        closest = std::min(closest, right.center().x - left.center().x);
    }
    // Each step moves them 2 px into each other and the next step's passes push them
    // out again: they never cross, and never overlap by more than those 2 px.
    CHECK(closest >= 20 - 2 - 1e-9);
    CHECK(right.center().x > left.center().x);
    CHECK(left.velocity() == Vec2{60, 0});
    CHECK(right.velocity() == Vec2{-60, 0});
}

TEST_CASE("s4_2: the echo shows the positional correction flag and the M key") {
    test::StageFixture page;
    test::buildBookScene(page.core, page.random);
    page.frame();
    CHECK(page.window.document.ui_echo.find("Positional Correction: true\n") != std::string::npos);
    CHECK(page.window.document.ui_echo.find("M: Positional Correction") != std::string::npos);
    page.press(browser::Key::M);
    page.frame();
    CHECK(page.window.document.ui_echo.find("Positional Correction: false\n") != std::string::npos);
}

TEST_CASE("s4_2: two static shapes are still tested, and their collision drawn: the borders' corners") {
    // As in the book's 4.2, only the resolution leaves a pair of static shapes alone: the
    // pass still finds the four corners where the borders overlap, 1.5 px deep, and the
    // frame draws their collision info, over the borders' outlines.
    test::StageFixture page;
    test::buildBookScene(page.core, page.random);
    page.frame();
    test::checkBorderCornersFound(page.core.physics().collisions());
    // At the bottom-left corner the line runs along the canvas's last rows but one.
    const browser::Image& pixels = page.window.document.canvas.pixels();
    CHECK(pixels.at(0, 448) == browser::colors::kOrange);
    CHECK(pixels.at(1, 448) == browser::colors::kOrange);
}

// The README's walkthrough ("Play it live"): correction off, twelve shapes at the
// cursor, correction on again at frame 30; movement stays off throughout.
TEST_CASE("s4_2: README walkthrough: a blob of overlapping shapes opens until none overlaps another") {
    test::StageFixture page;
    test::buildBookScene(page.core, page.random);
    // The pairs among the new shapes (5 on) that the last pass still found overlapping
    // by more than a rounding error: the passes leave touching shapes 1e-14 px deep.
    const auto overlapping = [&page] {
        int pairs = 0;
        for (const engine::Collision& pair : page.core.physics().collisions()) {
            if (pair.first >= 5 && pair.second >= 5 && pair.info.depth() > 1e-9) ++pairs;
        }
        return pairs;
    };
    test::playScript(page, "m f*6 g*6", 30);
    test::requireEqual("objects after F and G six times each: the cursor, the four borders and 12 new shapes", 17u,
                       page.core.objectCount());
    // Twelve shapes on one spot: every pair of them overlaps, 12 x 11 / 2.
    test::expectEqual("pairs of the 12 new shapes overlapping (deeper than 1e-9 px) with positional correction off", 66,
                      overlapping());
    test::playScript(page, "m", 30);
    // Which shapes F and G make depends on every random number drawn before: from 4.2
    // on each new shape also draws its random velocity (the book's UserControl.js).
    INFO(
        "F and G make the pile: from 4.2 on each new shape also gets a random velocity, -150..150 px/s a "
        "component, drawn after its size, mass, friction and restitution");
    test::expectEqual(
        "pairs of the 12 new shapes still overlapping (deeper than 1e-9 px) 30 frames after M turned "
        "positional correction on",
        0, overlapping());
}

}  // namespace s4_2_test
