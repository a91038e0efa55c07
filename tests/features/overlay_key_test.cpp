// A stage with an overlay: --overlay turns it on from the first frame, its own layer,
// and --overlay-all every layer; the key t takes it round from a key script (so a
// recorded live session replays the same pictures): once the stage's own layer, twice
// every layer, and a third time the book's picture exactly.
#include <catch2/catch.hpp>

#include <filesystem>
#include <string>

#include "expect.h"
#include "overlay.h"
#include "page.h"
#include "png_io.h"
#include "stage_fixture.h"
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

// Whether `page` is `book` with the legend's room under it, blank: the page of a run in
// which the overlay came on and went off again (page.h's Document::legend_room).
bool bookWithRoom(const browser::Image& page, const browser::Image& book) {
    if (page.width != book.width || page.height <= book.height) return false;
    for (int y = 0; y < page.height; ++y) {
        for (int x = 0; x < page.width; ++x) {
            if (page.at(x, y) != (y < book.height ? book.at(x, y) : browser::colors::kWhite)) return false;
        }
    }
    return true;
}

// How wide the stage makes its legend's columns for (page.h's Document::legend_text_width):
// what its overlay sets on the page, on or off.
int legendTextWidth() {
    test::StageFixture page;
    engine::drawOverlay(page.window, page.core);
    return page.window.document.legend_text_width;
}

}  // namespace

TEST_CASE(
    "overlay key: t shows the stage's own layer as --overlay does, t again every layer as --overlay-all, "
    "a third t takes it off") {
    test::ScratchFolder folder("overlay_key");
    // A rectangle and a circle at the cursor (F and G do that on every stage from 3.1).
    const browser::Image book = finalPicture(folder, "book", "--keys \"f g\"");
    const browser::Image option = finalPicture(folder, "option", "--overlay --keys \"f g\"");
    const browser::Image option_all = finalPicture(folder, "option_all", "--overlay-all --keys \"f g\"");
    const browser::Image key = finalPicture(folder, "key", "--keys \"f g t\"");
    const browser::Image twice = finalPicture(folder, "twice", "--keys \"f g t t@1\"");
    const browser::Image thrice = finalPicture(folder, "thrice", "--keys \"f g t t@1 t@1\"");
    const browser::Image option_then_key = finalPicture(folder, "option_then_key", "--overlay --keys \"f g t@1\"");
    const browser::Image all_then_key = finalPicture(folder, "all_then_key", "--overlay-all --keys \"f g t@1\"");
    // the overlay draws something on the default scene
    test::expectEqual("the picture with --overlay differs from the book's: the overlay draws something", true,
                      option.rgba != book.rgba);
    test::expectEqual("the picture after the key T: as with --overlay", true, key.rgba == option.rgba);
    test::expectEqual("the picture after T twice: as with --overlay-all", true, twice.rgba == option_all.rgba);
    test::expectEqual("the picture after T three times: the book's again, the legend's room under it blank", true,
                      bookWithRoom(thrice, book));
    test::expectEqual("the picture with --overlay and then T: as with --overlay-all", true,
                      option_then_key.rgba == option_all.rgba);
    test::expectEqual("the picture with --overlay-all and then T: the book's, the legend's room under it blank", true,
                      bookWithRoom(all_then_key, book));
}

TEST_CASE("overlay key: the legend's band under the page is as tall as the largest legend the run can show needs") {
    test::ScratchFolder folder("overlay_band");
    const browser::Image book = finalPicture(folder, "book", "--keys \"f g\"");
    const browser::Image all = finalPicture(folder, "all", "--overlay-all --keys \"f g\"");
    const browser::Image own = finalPicture(folder, "own", "--overlay --keys \"f g\"");
    // The page is the canvas and the panel (page.h) at scale 1: its width is theirs.
    test::expectEqual("the band's height: the page's with every layer on, less the book's page",
                      browser::legend_band_height(engine::kLegendEntries, book.width, legendTextWidth()),
                      all.height - book.height);
    test::expectEqual("the band's height: the page's with its own layer alone, less the book's page",
                      browser::legend_band_height(engine::kOwnLegendEntries, book.width, legendTextWidth()),
                      own.height - book.height);
}

}  // namespace overlay_key_test
