#pragma once
// What a feature test needs to drive any stage from 2.1 on the way its main.cpp does:
// a browser window, the engine core on it, a seeded Math.random and the user control
// script. Only names every stage shares are used here, so one test source compiles
// against every stage folder that has the feature.

#include <cstdint>

#include "browser.h"
#include "color_text.h"
#include "core.h"
#include "random.h"
#include "user_control.h"

namespace test {

inline constexpr double kFrameMs = 1000.0 / 60.0;

struct StageFixture {
    explicit StageFixture(std::uint64_t seed = 1, double frame_ms = kFrameMs) : window(frame_ms), random(seed) {}

    void press(browser::Key key, int times = 1) {
        for (int i = 0; i < times; ++i) control.onKeyDown(key);
    }
    // One animation frame, as the browser runs it.
    void frame() {
        window.clock.advanceFrame();
        core.runGameLoop();
    }

    browser::Window window;
    browser::Random random;
    engine::Core core{window};
    engine::UserControl control{core, random};
};

}  // namespace test
