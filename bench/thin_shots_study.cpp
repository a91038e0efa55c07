// The thin-shape envelope of 5.6's continuous collision (ch5_demo/5.6_continuous_collision/
// README.md): the whole grid of tests/support/thin_shots.h (plates, needles and spinning
// rectangles at every turn, spin and speed, walls of 2 to 0.01 px, both solvers) and
// 200,000 random shots, each counted through or held. The stage test runs a slice of
// both (s5_6.stage).
//
//   build/thin_shots_study [random shots, default 200000]
//
// Linked with stage 5.6's engine alone (namespace engine), as ccd_study is.
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "thin_shots.h"
#include "thread_clock.h"

namespace {

struct Tally {
    int shots = 0, through = 0, held = 0;
    void add(const thin_shots::Outcome& outcome) {
        ++shots;
        through += outcome.through ? 1 : 0;
        held += outcome.held ? 1 : 0;
    }
};

const char* solverName(engine::SolverKind solver) {
    return solver == engine::SolverKind::book ? "book's passes" : "sequential impulse";
}

void printRow(const std::string& what, const Tally& tally) {
    std::printf("| %s | %d | %d | %d |\n", what.c_str(), tally.shots, tally.through, tally.held);
}

}  // namespace

int main(int argc, char** argv) {
    const long random_count = argc > 1 ? std::strtol(argv[1], nullptr, 10) : 200000;
    if (random_count < 0 || random_count > 10000000) {
        std::fprintf(stderr, "thin_shots_study: the number of random shots must be 0 to 10,000,000\n");
        return 2;
    }
    const double started = bench::thread_cpu_seconds();
    std::printf("| shots | tried | through | held 10 steps |\n| --- | --- | --- | --- |\n");
    const std::vector<thin_shots::Shot> grid = thin_shots::grid();
    for (const engine::SolverKind solver : thin_shots::kSolvers) {
        for (const thin_shots::Shape shape : thin_shots::kShapes) {
            Tally tally;
            for (const thin_shots::Shot& shot : grid) {
                if (shot.solver == solver && shot.width == shape.width && shot.height == shape.height)
                    tally.add(thin_shots::shoot(shot));
            }
            char what[96];
            std::snprintf(what, sizeof what, "grid, %g x %g px, %s", shape.width, shape.height, solverName(solver));
            printRow(what, tally);
        }
    }
    Tally random[2];
    for (const thin_shots::Shot& shot : thin_shots::randomShots(static_cast<std::size_t>(random_count), 36)) {
        random[shot.solver == engine::SolverKind::book ? 0 : 1].add(thin_shots::shoot(shot));
    }
    for (int i = 0; i < 2; ++i) {
        printRow(std::string("random, ") + solverName(thin_shots::kSolvers[i]), random[i]);
    }
    std::printf("(%.0f s of processor time)\n", bench::thread_cpu_seconds() - started);
    return 0;
}
