// The overlay of motion (4.1 on): each moving shape's velocity as an arrow from its
// centre to where it would be in half a second, and its angular velocity as a curved
// arrow round it, turning as far as the shape turns in half a second.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>

#include "circle.h"
#include "expect.h"
#include "legend_color.h"
#include "world_fixture.h"

namespace motion_overlay_test {

TEST_CASE("motion overlay: a velocity arrow half a second long, a spin arc as far as half a second turns") {
    // Movement off (5.1's demo starts it on), so nothing moves.
    test::WorldFixture page(test::world(false));
    engine::Circle& ball = page.core.add(engine::Circle({300.5, 200.5}, 10));
    ball.setVelocity({60, 0});     // 30 px in 0.5 s: the tip at (330.5, 200.5)
    ball.setAngularVelocity(2.0);  // 1 rad in 0.5 s
    page.window.overlay = true;
    page.window.overlay_all = true;  // every layer: this one may be an earlier stage's
    page.window.clock.advanceFrame();
    page.core.runGameLoop();
    const browser::Document& document = page.window.document;
    const browser::Image& pixels = document.canvas.pixels();
    const browser::Color velocity = test::legendColor(document, "velocity");
    // On the shaft, 9.5 px outside the circle and 10 px before the tip: fully covered.
    test::expectEqual("pixel (320, 200), on the velocity arrow (half a second of motion): the legend's colour",
                      velocity, pixels.at(320, 200));
    // Past the tip, nothing.
    test::expectEqual("pixel (333, 200), past the arrow's tip", browser::colors::kWhite, pixels.at(333, 200));
    // The spin's arc: radius 10 + 4 px, from straight up (-pi/2) clockwise by 1 rad.
    // Halfway, at -pi/2 + 0.5, it passes (307.21, 188.22): that pixel is mostly the
    // velocity colour. The same radius a quarter turn before the start is untouched.
    const auto on_arc = [](double angle) {
        return lib::Vec2{300.5 + 14 * std::cos(angle), 200.5 + 14 * std::sin(angle)};
    };
    const lib::Vec2 middle = on_arc(-std::acos(-1.0) / 2 + 0.5);
    const browser::Color arc = pixels.at(static_cast<int>(middle.x), static_cast<int>(middle.y));
    // white would be 255 in each channel
    test::expectBelow("the spin arc's pixel halfway round, green channel: drawn (white would be 255)", 200, int{arc.g});
    test::expectBelow("the spin arc's pixel halfway round, red channel: drawn", 200, int{arc.r});
    const lib::Vec2 before = on_arc(-std::acos(-1.0));
    test::expectEqual("the pixel on the arc's radius a quarter turn before its start: untouched",
                      browser::colors::kWhite, pixels.at(static_cast<int>(before.x), static_cast<int>(before.y)));
}

}  // namespace motion_overlay_test
