// Stage 5.3: what its README promises of the knobs, played as the README plays it.
#include <catch2/catch.hpp>

#include <algorithm>
#include <string>
#include <vector>

#include "near.h"
#include "stage_program.h"

namespace s5_3_test {

// The README's "Try it": tunnelling.json with 4 sub-steps, where the fast ball bounces
// back too. At 1500 px/s a step of 1/60 s carries it 25 px, more than its 16 px diameter
// and the 4 px wall together, so with one step it is never seen overlapping the wall;
// a quarter step carries it 6.25 px, so some sub-step finds it in the wall. Then, the
// wall static and nothing rubbing (friction 0), Newton's law of restitution leaves it
// -e times its speed: -0.5 x 1500 = -750 px/s. It rolls back to the left wall, whose
// restitution is 0, and stops against its face: x = 60 + its radius 8 = 68.
TEST_CASE("s5_3: README: with 4 sub-steps the fast ball bounces off the thin wall at -e v") {
    const test::ScratchFolder folder("s5_3-tunnelling");
    std::string scene = test::readText(std::string(SCENE_LIBRARY_DIR) + "/tunnelling.json");
    const std::string world = R"("world": {)";
    REQUIRE(scene.find(world) != std::string::npos);
    scene.replace(scene.find(world), world.size(), world + R"("substeps": 4, )");
    folder.write("tunnelling4.json", scene);
    const test::ProgramRun run = test::runStageProgram(
        folder, "--scene " + test::quoted(folder.path / "tunnelling4.json") +
                    " --frames 120 --every 0 --no-gif --out " + test::quoted(folder.path / "out") + " --dump " +
                    test::quoted(folder.path / "dump.csv"));
    REQUIRE(run.status == 0);
    const double wall_left_face = 400 - 2;
    double first_speed_back = 0, farthest = 0, last_x = 0, last_vx = 0;
    for (const test::DumpRow& row : test::readDump(folder.path / "dump.csv")) {
        if (row.index != 3) continue;  // the fast ball
        if (first_speed_back == 0 && row.vx < 0) first_speed_back = row.vx;
        farthest = std::max(farthest, row.cx);
        last_x = row.cx;
        last_vx = row.vx;
    }
    CHECK(farthest < wall_left_face);  // its centre never got past the wall's near face
    CHECK_THAT(first_speed_back, test::near(-750, 1e-9));
    CHECK_THAT(last_x, test::near(68, 1e-6));
    CHECK_THAT(last_vx, test::near(0, 1e-9));
}

}  // namespace s5_3_test
