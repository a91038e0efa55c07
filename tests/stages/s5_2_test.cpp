// Stage 5.2: what its overlay shows of the grid (grid_overlay.h), held to numbers worked
// out by hand from the grid's rules (spatial_grid.cpp): cells of 3 median radii plus
// two skins, a skin of a fifth of a radius, and a pair listed when the shapes' boxes,
// widened by the skin, overlap.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "circle.h"
#include "grid_overlay.h"
#include "near.h"
#include "stage_program.h"
#include "world_fixture.h"

namespace s5_2_test {

namespace {

// Three still balls of radius 10: two 22 px apart (their circles miss by 2 px, but
// their boxes, 12 px each way of the centre, overlap by 2), one far away.
struct ThreeBalls {
    ThreeBalls() : page(still()) {
        page.core.add(engine::Circle({100, 100}, 10));
        page.core.add(engine::Circle({122, 100}, 10));
        page.core.add(engine::Circle({600, 300}, 10));
        page.steps(1);
    }
    static engine::WorldSettings still() {
        engine::WorldSettings world = engine::kBookWorld;
        world.movement = false;
        world.broad_phase = engine::BroadPhaseKind::grid;
        return world;
    }
    test::WorldFixture page;
};

}  // namespace

TEST_CASE("s5_2: the overlay's grid: cells of 34 px, boxes reaching 12 px, one candidate pair of three") {
    const ThreeBalls balls;
    const engine::SpatialGrid& grid = balls.page.core.physics().broadPhase().grid();
    // median radius 10: skin 2, cell 3 x 10 + 2 x 2 = 34 px, reach 10 + 2 = 12 px
    // (and a margin of 1e-9 of the coordinates).
    CHECK_THAT(grid.cellSize(), test::near(34, 1e-12));
    CHECK_THAT(grid.reach(0), test::near(12, 1e-6));
    REQUIRE(grid.listedCount() == 3);
    CHECK(grid.rowBegin(3) == 1);  // one pair on the list
    CHECK(grid.rowEnd(0) - grid.rowBegin(0) == 1);
    CHECK(grid.partner(grid.rowBegin(0)) == 1);
}

TEST_CASE("s5_2: the overlay's count: a pass tests the one listed pair, not all three, and saves two") {
    ThreeBalls balls;
    std::vector<browser::LegendEntry> legend;
    engine::drawGrid(balls.page.window.document.canvas, balls.page.core, legend);
    REQUIRE(legend.size() >= 2);
    CHECK(legend[legend.size() - 2].text == "pair tests a pass: 1 of 3");
    CHECK(legend.back().text == "saved a pass: 2");
    // The first pass tests the one listed pair, which misses: a pass that changed
    // nothing is the step's last (physics.cpp), so the step handed out one pair in all,
    // where the book's 15 passes would test three each.
    CHECK(balls.page.core.physics().pairStatistics().candidates == 1);
}

// The README's walkthrough ("Play it live"): the rain, and H at frame 120 stirs it up.
// H gives every moving shape a velocity whose two components are uniform in [-250, 250)
// px/s (user_control.h). The mean length of such a vector is
// 250 (sqrt 2 + ln(1 + sqrt 2)) / 3 = 191.3 px/s; over 200 shapes the sample mean is
// within 3% of it (its spread: 250 x 0.33 / sqrt 200 = 5.8 px/s), and the step's
// collisions take a little off. No component exceeds 250: no speed exceeds 354 px/s.
TEST_CASE("s5_2: README walkthrough: H at frame 120 stirs the rain up to the speeds H draws") {
    const test::ScratchFolder folder("s5_2-walkthrough");
    const test::ProgramRun run = test::runStageProgram(
        folder, "--scene " + test::quoted(std::string(SCENE_LIBRARY_DIR) + "/rain.json") +
                    " --keys h@120 --frames 240 --every 0 --no-gif --out " + test::quoted(folder.path / "out") +
                    " --dump " + test::quoted(folder.path / "dump.csv"));
    REQUIRE(run.status == 0);
    const std::vector<test::DumpRow> rows = test::readDump(folder.path / "dump.csv");
    // The mean and the largest speed of the shapes that move, after fixed step `step`.
    struct Speeds {
        double mean = 0, largest = 0;
    };
    const auto speedsAt = [&rows](long step) {
        Speeds speeds;
        int moving = 0;
        for (const test::DumpRow& row : rows) {
            const double speed = std::hypot(row.vx, row.vy);
            if (row.step != step || speed == 0) continue;  // the three walls never move
            speeds.mean += speed;
            speeds.largest = std::max(speeds.largest, speed);
            ++moving;
        }
        REQUIRE(moving == 200);
        speeds.mean /= moving;
        return speeds;
    };
    const Speeds before = speedsAt(119), after = speedsAt(120);
    INFO("mean speed before H " << before.mean << " px/s, after " << after.mean << " px/s");
    CHECK(before.mean < 100);  // falling for two seconds at 20 px/s^2, some bouncing
    CHECK(after.mean > 0.9 * 191.3);
    CHECK(after.mean < 1.03 * 191.3);
    CHECK(after.largest < 354);
}

}  // namespace s5_2_test
