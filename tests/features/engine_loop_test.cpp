// The engine loop's fixed-step timing (every stage from 2.2 on): how many updates each
// frame runs and what lag it carries, against hand calculation with a 1000/60 ms step.
#include <catch2/catch.hpp>

#include "circle.h"
#include "core.h"
#include "near.h"
#include "stage_fixture.h"

namespace engine_loop_test {

namespace {
constexpr double kStep = 1000.0 / 60.0;
constexpr double kExact = 1e-9;  // ms
}  // namespace

TEST_CASE("engine loop: updates per frame and carried lag for mixed frame lengths") {
    engine::FixedStepTimer timer(0.0);
    double now = 0.0;
    // A table, a frame a line, which the layout would pack:
    // clang-format off
    struct Frame { double length_ms; int updates; double lag_ms; };
    const Frame frames[] = {
        // 1000/60 has no exact binary form: the step is a hair above 50/3 ms, and three
        // of them a hair more than 50 ms. So, as in the book (which compares the lag
        // with the step exactly), a 50 ms frame runs two updates, not three, and
        // carries almost a whole step to the next frame.
        {50.0, 2, 50.0 - 2 * kStep},
        {5.0, 1, 55.0 - 3 * kStep},                  // the carried step is due: 5 ms left
        {5.0, 0, 60.0 - 3 * kStep},                  // too short for a step: it waits
        {5.0, 0, 65.0 - 3 * kStep},
        {5.0, 1, 70.0 - 4 * kStep},                  // 3.33 ms carried
        {1000.0, 60, 1070.0 - 64 * kStep},           // a 1 s stall: 1003.33 ms owes 60 steps
    };
    // clang-format on
    for (const Frame& frame : frames) {
        now += frame.length_ms;
        CHECK(timer.updatesDue(now) == frame.updates);
        CHECK_THAT(timer.lagMs(), test::near(frame.lag_ms, kExact));
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
        // Every whole step of the elapsed time ran, and the lag is what is left. (1e-6 ms:
        // up to 3,000 frames' and 45,000 steps' roundings on times up to 750,000 ms.)
        CHECK_THAT(updates * kStep + timer.lagMs(), test::near(elapsed, 1e-6));
        CHECK(timer.lagMs() < kStep);
    }
}

namespace {

// What shows that the core ran its updates, not only counted them, in each stage: from
// 4.1 on the core counts its steps; in 2.2 every free shape sinks 1 px a step; in
// chapter 3 the step's collision pass finds two overlapping shapes.
template <class Page, class Shape>
void checkUpdatesRan(const Page& page, const Shape& sinker, int updates) {
    if constexpr (requires { page.core.stepCount(); }) {
        CHECK(page.core.stepCount() == updates);
    } else if constexpr (requires { sinker.isFixed(); }) {
        CHECK(sinker.center().y == 100.0 + updates);
    } else {
        CHECK(page.core.physics().collisions().size() == 1);
    }
}

}  // namespace

TEST_CASE("engine loop: the core keeps time with the browser's clock") {
    // 50 ms frames: two updates in the first (see above), then three a frame, with
    // almost a whole step always carried over. Every step of the elapsed time but that
    // one has run.
    test::StageFixture page(1, 50.0);
    const engine::RigidShape& sinker = page.core.add(engine::Circle({100, 100}, 10));
    // Chapter 3's passes leave out the book's first objects (3.1 the cursor and the four
    // borders), so the overlapping pair comes after four more shapes far apart.
    for (int i = 1; i <= 4; ++i) page.core.add(engine::Circle({100.0 + 100 * i, 100}, 10));
    page.core.add(engine::Circle({300, 300}, 10));
    page.core.add(engine::Circle({310, 300}, 10));
    for (int k = 1; k <= 10; ++k) {
        page.frame();
        const double lag = page.core.timer().lagMs();
        CHECK(lag < kStep);
        CHECK(lag > kStep - kExact);
        // 1e-9 updates: the lag is right to 1e-13 ms or so (a few roundings of 500 ms).
        CHECK_THAT((50.0 * k - lag) / kStep, test::near(3 * k - 1, 1e-9));
        checkUpdatesRan(page, sinker, 3 * k - 1);
    }
}

}  // namespace engine_loop_test
