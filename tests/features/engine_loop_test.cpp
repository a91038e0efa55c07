// The engine loop's fixed-step timing (every stage from 2.2 on): how many updates each
// frame runs and what lag it carries, against hand calculation with a 1000/60 ms step.
#include <catch2/catch.hpp>

#include "core.h"
#include "stage_fixture.h"

namespace {
constexpr double kStep = 1000.0 / 60.0;
constexpr double kExact = 1e-9;  // ms
}  // namespace

TEST_CASE("engine loop: updates per frame and carried lag for mixed frame lengths") {
    engine::FixedStepTimer timer(0.0);
    double now = 0.0;
    struct Frame { double length_ms; int updates; double lag_ms; };
    const Frame frames[] = {
        {kStep, 1, 0.0},                         // a 60 Hz frame: one update, nothing left
        {50.0, 3, 0.0},                          // 50 ms is three steps exactly
        {5.0, 0, 5.0},                           // too short for a step: it waits
        {5.0, 0, 10.0},
        {5.0, 0, 15.0},
        {5.0, 1, 20.0 - kStep},                  // 20 ms of lag: one step, 3.33 ms carried
        {1000.0, 60, 1000.0 + 20.0 - 61 * kStep},  // a 1 s stall: 1003.33 ms owes 60 steps
    };
    for (const Frame& frame : frames) {
        now += frame.length_ms;
        CHECK(timer.updatesDue(now) == frame.updates);
        CHECK(timer.lagMs() == Approx(frame.lag_ms).margin(kExact));
        CHECK(timer.lagMs() >= -kExact);
        CHECK(timer.lagMs() < kStep);
    }
}

TEST_CASE("engine loop: no update is ever lost, whatever the frame length") {
    for (double frame_ms : {1000.0 / 60.0, 50.0, 7.0, 33.0, 1000.0 / 144.0, 250.0}) {
        engine::FixedStepTimer timer(0.0);
        long updates = 0;
        constexpr int kFrames = 3000;
        for (int k = 1; k <= kFrames; ++k) updates += timer.updatesDue(k * frame_ms);
        const double elapsed = kFrames * frame_ms;
        // Every whole step of the elapsed time ran, and the lag is what is left.
        CHECK(updates * kStep + timer.lagMs() == Approx(elapsed).margin(1e-6));
        CHECK(timer.lagMs() < kStep);
    }
}

TEST_CASE("engine loop: the core keeps time with the browser's clock") {
    test::StageFixture page(1, 50.0);
    for (int k = 0; k < 10; ++k) {
        page.frame();
        CHECK(page.core.timer().lagMs() == Approx(0.0).margin(kExact));
    }
}
