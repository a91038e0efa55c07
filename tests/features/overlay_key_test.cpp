// A stage with an overlay: --overlay turns it on from the first frame, the key t does
// the same from a key script (so a recorded live session replays the same pictures),
// and pressing t again brings back the book's picture exactly.
#include <catch2/catch.hpp>

#include <filesystem>
#include <string>

#include "expect.h"
#include "png_io.h"
#include "stage_program.h"

namespace overlay_key_test {

namespace {

// final.png of a two-frame run of the stage's program with `arguments`.
browser::Image finalPicture(const test::ScratchFolder& folder, const std::string& name, const std::string& arguments) {
    const std::filesystem::path out = folder.path / name;
    const test::ProgramRun run =
        test::runStageProgram(folder, "--frames 2 --out " + test::quoted(out) + " " + arguments);
    test::requireEqual("the program's exit status (0: the run succeeded)", 0, run.status);
    return browser::read_png(out / "final.png");
}

}  // namespace

TEST_CASE("overlay key: --overlay and the key t show the same overlay; t again takes it off") {
    test::ScratchFolder folder("overlay_key");
    // A rectangle and a circle at the cursor (F and G do that on every stage from 3.1).
    const browser::Image book = finalPicture(folder, "book", "--keys \"f g\"");
    const browser::Image option = finalPicture(folder, "option", "--overlay --keys \"f g\"");
    const browser::Image key = finalPicture(folder, "key", "--keys \"f g t\"");
    const browser::Image twice = finalPicture(folder, "twice", "--keys \"f g t t@1\"");
    const browser::Image option_then_key = finalPicture(folder, "option_then_key", "--overlay --keys \"f g t@1\"");
    // the overlay draws something on the default scene
    test::expectEqual("the picture with --overlay differs from the book's: the overlay draws something", true,
                      option.rgba != book.rgba);
    test::expectEqual("the picture after the key T: as with --overlay", true, key.rgba == option.rgba);
    test::expectEqual("the picture after T twice: the book's again", true, twice.rgba == book.rgba);
    test::expectEqual("the picture with --overlay and then T: the book's", true, option_then_key.rgba == book.rgba);
}

}  // namespace overlay_key_test
