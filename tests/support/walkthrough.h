#pragma once
// A README's walkthrough as a test runs it: the stage's program with the README's key
// script and frames, and the state dump (--dump) to check what the text promises.
// From 4.1 on, where the programs write state dumps; from 2.1 on, the script played on
// a page in the test itself (playScript), for what a dump does not hold.

#include <catch2/catch.hpp>

#include <cstddef>
#include <string>
#include <vector>

#include "expect.h"
#include "keys.h"
#include "scratch_folder.h"
#include "stage_program.h"

namespace test {

// Every row of the dump of `script` run for `frames` frames.
inline std::vector<DumpRow> runWalkthrough(const ScratchFolder& folder, const std::string& script, int frames) {
    const ProgramRun run =
        runStageProgram(folder, "--keys \"" + script + "\" --frames " + std::to_string(frames) + " --out " +
                                    quoted(folder.path / "out") + " --dump " + quoted(folder.path / "dump.csv"));
    INFO("the stage's program with the walkthrough's keys \"" << script << "\" for " << frames
                                                              << " frames; it said: " << run.error_text);
    test::requireEqual("the program's exit status (0: the run succeeded)", 0, run.status);
    return readDump(folder.path / "dump.csv");
}

// Object `index` after fixed step `step`.
inline DumpRow stateAt(const std::vector<DumpRow>& rows, long step, std::size_t index) {
    for (const DumpRow& row : rows) {
        if (row.step == step && row.index == index) return row;
    }
    FAIL("no row for step " << step << ", object " << index);
    return {};
}

// Plays frames `from` to `to` - 1 of `script` on a page with a window, a core and a
// user control script (stage_fixture.h's StageFixture), as the browser does: the clock
// moves on a frame, that frame's keys are pressed, the frame runs. A test that looks
// at the page between frames plays the script in pieces.
template <class Page>
void playScript(Page& page, const std::string& script, int from, int to) {
    const browser::KeyScript keys = browser::KeyScript::parse(script);
    for (int k = from; k < to; ++k) {
        page.window.clock.advanceFrame();
        for (const browser::Key key : keys.pressesAt(k)) page.control.onKeyDown(key);
        page.core.runGameLoop();
    }
}

// The whole of a script's first `frames` frames.
template <class Page>
void playScript(Page& page, const std::string& script, int frames) {
    playScript(page, script, 0, frames);
}

}  // namespace test
