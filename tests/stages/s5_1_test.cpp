// Stage 5.1: the demo's scene is the book's MyGame, shapes that leave the canvas are
// removed without costing anyone else a step, and a run repeats exactly for one seed.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <iterator>
#include <string>
#include <vector>

#include "circle.h"
#include "expect.h"
#include "image_compare.h"
#include "near.h"
#include "png_io.h"
#include "rectangle.h"
#include "scratch_folder.h"
#include "stage_program.h"
#include "world_fixture.h"
#include "book_scene.h"

namespace s5_1_test {

using engine::Vec2;

namespace {

// The angle a platform is turned by, read from its top face's normal (straight up,
// (0, -1), before any turn; a turn by a takes it to (sin a, -cos a)).
double turnOf(const engine::Rectangle& box) {
    const Vec2 n = box.faceNormals()[0];
    return std::atan2(n.x, -n.y);
}

}  // namespace

TEST_CASE("s5_1: the demo's scene is the book's MyGame") {
    test::WorldFixture page(engine::kBookWorld);
    test::buildBookScene(page.core, page.random);
    test::requireEqual("objects of the demo: four platforms and twenty random shapes", 4 + 20, page.core.objectCount());

    struct Platform {
        Vec2 center;
        double width, height, angle, friction, restitution;
    };
    const Platform platforms[] = {
        {{500, 200}, 400, 20, 2.8, 0.3, 0.0},
        {{200, 400}, 400, 20, 0.0, 1.0, 0.5},
        {{100, 200}, 200, 20, 0.0, 0.8, 0.2},  // the book's default friction and restitution
        {{10, 360}, 20, 100, 0.0, 0.0, 1.0},
    };
    for (std::size_t i = 0; i < 4; ++i) {
        INFO("platform " << i);
        const auto& box = dynamic_cast<const engine::Rectangle&>(page.core.object(i));
        test::expectEqual("static (mass 0)", true, box.isStatic());
        test::expectEqual("its centre, px", platforms[i].center, box.center());
        test::expectEqual("its width, px", platforms[i].width, box.width());
        test::expectEqual("its height, px", platforms[i].height, box.height());
        CHECK_THAT(turnOf(box), test::near(platforms[i].angle, 1e-12));  // atan2 of a turned normal: rounding
        test::expectEqual("its friction", platforms[i].friction, box.friction());
        test::expectEqual("its restitution", platforms[i].restitution, box.restitution());
    }
    test::expectEqual("the demo's gravity, px/s^2: the book's 5.1 doubles chapter 4's (0, 10)", Vec2{0, 20},
                      page.core.settings().gravity);
    test::expectEqual("movement as the demo starts: on", true, page.core.settings().movement);
    test::expectEqual("remove_out_of_bounds in the demo: on (the book removes shapes that leave the canvas)", true,
                      page.core.settings().remove_out_of_bounds);
    test::expectEqual("objects R keeps (UserControl::kKeptOnReset)", 7, engine::UserControl::kKeptOnReset);
    test::expectEqual("H's kick, px/s a component (UserControl::kExciteSpeed)", 250, engine::UserControl::kExciteSpeed);
}

TEST_CASE("s5_1: the twenty random shapes are the book's, drawn in its order") {
    for (const std::uint64_t seed : {std::uint64_t{1}, browser::Random::kDefaultSeed}) {
        INFO("seed " << seed);
        test::WorldFixture page(engine::kBookWorld, seed);
        test::buildBookScene(page.core, page.random);
        browser::Random book(seed);  // the same Math.random, drawn by hand
        const std::vector<test::DemoShape> shapes = test::demoShapesAsTheBookDraws(book);
        test::requireEqual("objects of the demo: four platforms and the twenty random shapes", 4 + shapes.size(),
                           page.core.objectCount());
        for (std::size_t k = 0; k < shapes.size(); ++k) {
            INFO("random shape " << k);
            const test::DemoShape& expected = shapes[k];
            const engine::RigidShape& shape = page.core.object(4 + k);
            test::expectEqual("its centre, px: the book's random numbers, drawn in its order", expected.center,
                              shape.center());
            if (expected.is_box) {
                const auto* box = dynamic_cast<const engine::Rectangle*>(&shape);
                REQUIRE(box != nullptr);
                test::expectEqual("its width, px", expected.width, box->width());
                test::expectEqual("its height, px", expected.height, box->height());
            } else {
                const auto* ball = dynamic_cast<const engine::Circle*>(&shape);
                REQUIRE(ball != nullptr);
                test::expectEqual("its radius, px", expected.radius, ball->radius());
            }
            // The shape keeps 1/m: m comes back to within a rounding or two of 30 (1e-13).
            CHECK_THAT(shape.mass(), test::near(expected.mass, 1e-13));
            test::expectEqual("its friction", expected.friction, shape.friction());
            test::expectEqual("its restitution", expected.restitution, shape.restitution());
            test::expectEqual("its velocity, px/s", expected.velocity, shape.velocity());
            test::expectEqual("its angular velocity, rad/s", 0, shape.angularVelocity());
        }
    }
}

TEST_CASE("s5_1: the random shapes stay within the book's ranges over many seeds") {
    double smallest_side = 1e9, largest_side = 0, smallest_radius = 1e9, largest_radius = 0, largest_mass = 0;
    for (std::uint64_t seed = 1; seed <= 200; ++seed) {
        test::WorldFixture page(engine::kBookWorld, seed);
        test::buildBookScene(page.core, page.random);
        for (std::size_t i = 4; i < page.core.objectCount(); ++i) {
            const engine::RigidShape& shape = page.core.object(i);
            // Rectangles and circles take turns, a rectangle first.
            test::expectEqual("a random shape's kind: rectangles and circles take turns, a rectangle first",
                              (i % 2 == 0 ? engine::ShapeType::Rectangle : engine::ShapeType::Circle), shape.type());
            test::expectAtLeast("a random shape's x, px: at least 0", 0, shape.center().x);
            test::expectBelow("a random shape's x, px: below 800", 800, shape.center().x);
            test::expectAtLeast("a random shape's y, px: at least 0", 0, shape.center().y);
            // the top half
            test::expectBelow("a random shape's y, px: in the top half, below 225", 225, shape.center().y);
            test::expectBelow("a random shape's mass: below 30", 30, shape.mass());
            test::expectBelow("a random shape's friction: below 1", 1, shape.friction());
            test::expectBelow("a random shape's restitution: below 1", 1, shape.restitution());
            test::expectAtMost("a random shape's |vx|, px/s: at most 30", 30, std::abs(shape.velocity().x));
            test::expectAtMost("a random shape's |vy|, px/s: at most 30", 30, std::abs(shape.velocity().y));
            largest_mass = std::max(largest_mass, shape.mass());
            if (const auto* box = dynamic_cast<const engine::Rectangle*>(&shape)) {
                for (double side : {box->width(), box->height()}) {
                    test::expectAtLeast("a random rectangle's side, px: at least 10", 10, side);
                    test::expectBelow("a random rectangle's side, px: below 60", 60, side);
                    smallest_side = std::min(smallest_side, side);
                    largest_side = std::max(largest_side, side);
                }
            } else {
                const auto& ball = dynamic_cast<const engine::Circle&>(shape);
                test::expectAtLeast("a random circle's radius, px: at least 10", 10, ball.radius());
                test::expectBelow("a random circle's radius, px: below 30", 30, ball.radius());
                smallest_radius = std::min(smallest_radius, ball.radius());
                largest_radius = std::max(largest_radius, ball.radius());
            }
        }
    }
    // 4,000 uniform draws each reach within half a percent of both ends of their range.
    test::expectBelow("the smallest random side over 200 seeds, px: near the range's 10", 10.5, smallest_side);
    test::expectAbove("the largest random side over 200 seeds, px: near the range's 60", 59.5, largest_side);
    test::expectBelow("the smallest random radius over 200 seeds, px: near 10", 10.5, smallest_radius);
    test::expectAbove("the largest random radius over 200 seeds, px: near 30", 29.5, largest_radius);
    test::expectAbove("the largest random mass over 200 seeds: near 30", 29.5, largest_mass);
}

TEST_CASE("s5_1: a shape leaving the canvas is gone in the step it leaves, and the shape after it keeps its step") {
    test::WorldFixture page(engine::kBookWorld);
    // Three balls far apart, falling; the middle one is about to cross the right edge
    // at 60 px/s (1 px a step). Symplectic Euler: one step from rest under g gives
    // vy = g dt and moves the ball down by g dt^2.
    engine::Circle& left = page.core.add(engine::Circle({100, 100}, 5));
    engine::Circle& leaving = page.core.add(engine::Circle({799.5, 100}, 5));
    page.core.add(engine::Circle({300, 100}, 5));
    leaving.setVelocity({60, 0});
    page.steps(1);  // it moves to x = 800.5, outside: removed at the end of this step
    test::requireEqual("objects after the step: the ball that crossed the right edge removed", 2,
                       page.core.objectCount());
    const double fallen = engine::kGravity.y * engine::kFrameTime * engine::kFrameTime;
    test::expectEqual("the first ball's y after the step, px: g dt^2 lower", 100 + fallen, left.center().y);
    // The ball after it (the book's loop would have skipped its update) fell as far.
    test::expectEqual("the third ball's x, px", 300, page.core.object(1).center().x);
    test::expectEqual("the third ball's y, px: it took its step too (the book's loop skips it)", 100 + fallen,
                      page.core.object(1).center().y);
}

TEST_CASE("s5_1: a shape moved off the canvas with movement off is removed at the next step") {
    // The book checks every shape in every update, moving or not.
    engine::WorldSettings still = engine::kBookWorld;
    still.movement = false;
    test::WorldFixture page(still);
    page.core.add(engine::Circle({100, 100}, 5));
    page.core.add(engine::Circle({10, 100}, 5));
    page.core.select(1);
    page.press(browser::Key::A, 2);  // 20 px to the left: its centre at x = -10
    test::requireEqual("objects before the step: both still there", 2, page.core.objectCount());
    page.steps(1);
    test::requireEqual("objects after the step: the one moved off the canvas removed", 1, page.core.objectCount());
    test::expectEqual("the remaining ball's centre, px", Vec2{100, 100}, page.core.object(0).center());
}

TEST_CASE("s5_1: when the selected shape is removed, object 0 is selected (the book's page stops)") {
    // The book leaves gObjectNum pointing past the end of the list: its echo panel then
    // throws on the missing object, and the page stops until a key selects a valid one.
    test::WorldFixture page(engine::kBookWorld);
    engine::Rectangle& ledge = page.core.add(engine::Rectangle({400, 300}, 100, 10, {.mass = 0}));
    engine::Circle& leaving = page.core.add(engine::Circle({799.5, 100}, 5));
    leaving.setVelocity({60, 0});
    page.core.select(1);
    page.steps(2);  // out of the canvas in the first step, removed in the second
    test::requireEqual("objects after two steps: the leaving ball removed", 1, page.core.objectCount());
    test::expectEqual("the selected index once the selected shape is gone: object 0", 0, page.core.selectedIndex());
    page.core.runGameLoop();  // the page goes on: the echo shows the ledge
    test::expectEqual("the echo's line \"Id: 0\"", true,
                      page.window.document.ui_echo.find("Id: 0\n") != std::string::npos);
    test::expectEqual("the echo's line \"Center: 400,300\": the ledge", true,
                      page.window.document.ui_echo.find("Center: 400,300\n") != std::string::npos);
    page.press(browser::Key::W);  // and the keys act on it
    test::expectEqual("the ledge's centre after W, px: the keys act on it", Vec2{400, 290}, ledge.center());
}

TEST_CASE("s5_1: the same seed gives the same run, another seed another") {
    const test::ScratchFolder folder("s5_1_repeat");
    auto run = [&](const std::string& name, std::uint64_t seed) {
        const std::string arguments = "--frames 90 --every 45 --no-gif --seed " + std::to_string(seed) + " --out " +
                                      test::quoted(folder.path / name) + " --dump " +
                                      test::quoted(folder.path / (name + ".csv"));
        const test::ProgramRun result = test::runStageProgram(folder, arguments);
        INFO(result.error_text);
        test::requireEqual("the program's exit status (0: the run succeeded)", 0, result.status);
        return test::readText(folder.path / (name + ".csv"));
    };
    const std::string first = run("first", 11), again = run("again", 11), other = run("other", 12);
    test::expectEqual("the state dumps of two runs with seed 11: the same", again, first);
    test::expectEqual("the state dumps of seeds 11 and 12: different", true, first != other);
    for (const char* picture : {"final.png", "frame_0045.png", "contact_sheet.png"}) {
        INFO(picture);
        const auto difference = browser::compare_images(browser::read_png(folder.path / "first" / picture),
                                                        browser::read_png(folder.path / "again" / picture), {});
        test::expectEqual("the two runs' pictures: the same size", true, difference.same_size);
        test::expectEqual("pixels that differ between the two runs' pictures", 0, difference.differing_pixels);
    }
}

TEST_CASE("s5_1: the default run writes an animated GIF of the whole page") {
    const test::ScratchFolder folder("s5_1_gif");
    const test::ProgramRun result =
        test::runStageProgram(folder, "--frames 20 --every 0 --out " + test::quoted(folder.path / "out"));
    test::requireEqual("the program's exit status (0: the run succeeded)", 0, result.status);
    const std::string gif = test::readText(folder.path / "out" / "animation.gif");
    REQUIRE(gif.size() > 10);
    test::expectEqual("the GIF's signature", "GIF89a", gif.substr(0, 6));
    // The logical screen: width and height, little-endian, right after the signature.
    const auto u16 = [&](std::size_t at) {
        return static_cast<unsigned char>(gif[at]) | static_cast<unsigned char>(gif[at + 1]) << 8;
    };
    test::expectEqual("the GIF's width, px: the canvas and the echo panel", 800 + browser::kPanelWidth, u16(6));
    // The canvas, 450 px, and under it the band of the page's note on the echo's mass
    // (main.cpp's echo_notes): a gap of 5, its two lines of 18 px, and 5 under them.
    test::expectEqual("the GIF's height, px: the canvas and the band of the note on the mass", 450 + 5 + 2 * 18 + 5,
                      u16(8));
}

TEST_CASE(
    "s5_1: the README's key script makes three boxes and three balls at once, and H at two seconds kicks every moving "
    "shape") {
    // README.md, "Play it live": --keys "f*3 g*3 h@120" --frames 240. Frame 0's clock
    // holds a hair less than one step (core.cpp's timer), so frame k runs step k: the
    // presses of frame 0 come before step 1, which has six more shapes than step 0
    // (three rectangles, then three circles), and H, before frame 120, gives every
    // moving shape a new velocity, uniform in the square [-250, 250)^2 px/s, in step 120.
    test::ScratchFolder folder("s5_1_readme_script");
    const std::filesystem::path dump = folder.path / "dump.csv";
    const test::ProgramRun run =
        test::runStageProgram(folder, "--keys \"f*3 g*3 h@120\" --frames 240 --every 0 --no-gif --out " +
                                          test::quoted(folder.path / "out") + " --dump " + test::quoted(dump));
    test::requireEqual("the program's exit status (0: the run succeeded)", 0, run.status);
    const std::vector<test::DumpRow> rows = test::readDump(dump);
    const auto at = [&](long step) {
        std::vector<test::DumpRow> found;
        std::copy_if(rows.begin(), rows.end(), std::back_inserter(found),
                     [&](const test::DumpRow& row) { return row.step == step; });
        return found;
    };
    const std::vector<test::DumpRow> start = at(0), first = at(1);
    test::requireEqual("dump rows at step 1: six more than at step 0 (F and G three times each)", start.size() + 6,
                       first.size());
    for (std::size_t k = 0; k < 6; ++k) CHECK(first[start.size() + k].shape == (k < 3 ? "rectangle" : "circle"));

    // H draws a new velocity u for each moving shape, whatever its velocity v was: u
    // misses v by less than 50 px/s only when it falls in a disc of radius 50 around v,
    // pi 50^2 / 500^2 = 3 % of the square. So in the step of H nine in ten moving shapes
    // or more change their velocity by over 50 px/s; in the step before, gravity adds
    // g dt = 1/3 px/s, and only a collision changes a velocity that much.
    const auto shareChanged = [](const std::vector<test::DumpRow>& from, const std::vector<test::DumpRow>& to) {
        REQUIRE(from.size() == to.size());
        int moving = 0, changed = 0;
        for (std::size_t k = 0; k < from.size(); ++k) {
            if (from[k].vx == 0.0 && from[k].vy == 0.0 && to[k].vx == 0.0 && to[k].vy == 0.0) continue;  // static
            ++moving;
            if (std::hypot(to[k].vx - from[k].vx, to[k].vy - from[k].vy) > 50) ++changed;
        }
        return moving > 0 ? static_cast<double>(changed) / moving : 0.0;
    };
    const double before = shareChanged(at(118), at(119)), kicked = shareChanged(at(119), at(120));
    INFO("share of moving shapes whose velocity changed by over 50 px/s: " << before << " before H, " << kicked
                                                                           << " in its step");
    test::expectAbove("the share of moving shapes whose velocity changed by over 50 px/s in the step of H", 0.9,
                      kicked);
    test::expectBelow("the same share in the step before H", 0.5, before);

    // The mean length of a velocity uniform in the square is 250 (sqrt 2 + ln(1 + sqrt 2)) / 3 = 191 px/s.
    double sum = 0.0;
    int moving = 0;
    for (const test::DumpRow& row : at(120)) {
        if (row.vx == 0.0 && row.vy == 0.0) continue;
        sum += std::hypot(row.vx, row.vy);
        ++moving;
    }
    REQUIRE(moving > 0);
    CHECK_THAT(sum / moving, test::near(250 * (std::sqrt(2.0) + std::log(1 + std::sqrt(2.0))) / 3, 60));
}

}  // namespace s5_1_test
