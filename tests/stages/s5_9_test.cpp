// Stage 5.9: joints (in progress). So far the stage is 5.8, copied: 5.8's stage tests run
// on it (s5_9.s5_8_stage), and every scene of the library still moves to the bit as in
// 5.1 (s5_9.identity).
#include <catch2/catch.hpp>

#include "stage_program.h"

namespace s5_9_test {

TEST_CASE("s5_9: the program runs the book's demo and exits 0") {
    const test::ScratchFolder folder("s5_9-demo");
    const test::ProgramRun run =
        test::runStageProgram(folder, "--frames 2 --every 0 --no-gif --out " + test::quoted(folder.path / "out"));
    CHECK(run.status == 0);
}

}  // namespace s5_9_test
