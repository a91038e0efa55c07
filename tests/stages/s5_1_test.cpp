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
    REQUIRE(page.core.objectCount() == 4 + 20);

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
        CHECK(box.isStatic());
        CHECK(box.center() == platforms[i].center);
        CHECK(box.width() == platforms[i].width);
        CHECK(box.height() == platforms[i].height);
        CHECK_THAT(turnOf(box), test::near(platforms[i].angle, 1e-12));  // atan2 of a turned normal: rounding
        CHECK(box.friction() == platforms[i].friction);
        CHECK(box.restitution() == platforms[i].restitution);
    }
    CHECK(page.core.settings().gravity == Vec2{0, 20});
    CHECK(page.core.settings().movement);
    CHECK(page.core.settings().remove_out_of_bounds);
    CHECK(engine::UserControl::kKeptOnReset == 7);
    CHECK(engine::UserControl::kExciteSpeed == 250);
}

TEST_CASE("s5_1: the twenty random shapes are the book's, drawn in its order") {
    for (const std::uint64_t seed : {std::uint64_t{1}, browser::Random::kDefaultSeed}) {
        INFO("seed " << seed);
        test::WorldFixture page(engine::kBookWorld, seed);
        test::buildBookScene(page.core, page.random);
        browser::Random book(seed);  // the same Math.random, drawn by hand
        const std::vector<test::DemoShape> shapes = test::demoShapesAsTheBookDraws(book);
        REQUIRE(page.core.objectCount() == 4 + shapes.size());
        for (std::size_t k = 0; k < shapes.size(); ++k) {
            INFO("random shape " << k);
            const test::DemoShape& expected = shapes[k];
            const engine::RigidShape& shape = page.core.object(4 + k);
            CHECK(shape.center() == expected.center);
            if (expected.is_box) {
                const auto* box = dynamic_cast<const engine::Rectangle*>(&shape);
                REQUIRE(box != nullptr);
                CHECK(box->width() == expected.width);
                CHECK(box->height() == expected.height);
            } else {
                const auto* ball = dynamic_cast<const engine::Circle*>(&shape);
                REQUIRE(ball != nullptr);
                CHECK(ball->radius() == expected.radius);
            }
            // The shape keeps 1/m: m comes back to within a rounding or two of 30 (1e-13).
            CHECK_THAT(shape.mass(), test::near(expected.mass, 1e-13));
            CHECK(shape.friction() == expected.friction);
            CHECK(shape.restitution() == expected.restitution);
            CHECK(shape.velocity() == expected.velocity);
            CHECK(shape.angularVelocity() == 0);
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
            CHECK(shape.type() == (i % 2 == 0 ? engine::ShapeType::Rectangle : engine::ShapeType::Circle));
            CHECK(shape.center().x >= 0);
            CHECK(shape.center().x < 800);
            CHECK(shape.center().y >= 0);
            CHECK(shape.center().y < 225);  // the top half
            CHECK(shape.mass() < 30);
            CHECK(shape.friction() < 1);
            CHECK(shape.restitution() < 1);
            CHECK(std::abs(shape.velocity().x) <= 30);
            CHECK(std::abs(shape.velocity().y) <= 30);
            largest_mass = std::max(largest_mass, shape.mass());
            if (const auto* box = dynamic_cast<const engine::Rectangle*>(&shape)) {
                for (double side : {box->width(), box->height()}) {
                    CHECK(side >= 10);
                    CHECK(side < 60);
                    smallest_side = std::min(smallest_side, side);
                    largest_side = std::max(largest_side, side);
                }
            } else {
                const auto& ball = dynamic_cast<const engine::Circle&>(shape);
                CHECK(ball.radius() >= 10);
                CHECK(ball.radius() < 30);
                smallest_radius = std::min(smallest_radius, ball.radius());
                largest_radius = std::max(largest_radius, ball.radius());
            }
        }
    }
    // 4,000 uniform draws each reach within half a percent of both ends of their range.
    CHECK(smallest_side < 10.5);
    CHECK(largest_side > 59.5);
    CHECK(smallest_radius < 10.5);
    CHECK(largest_radius > 29.5);
    CHECK(largest_mass > 29.5);
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
    REQUIRE(page.core.objectCount() == 2);
    const double fallen = engine::kGravity.y * engine::kFrameTime * engine::kFrameTime;
    CHECK(left.center().y == 100 + fallen);
    // The ball after it (the book's loop would have skipped its update) fell as far.
    CHECK(page.core.object(1).center().x == 300);
    CHECK(page.core.object(1).center().y == 100 + fallen);
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
    REQUIRE(page.core.objectCount() == 2);
    page.steps(1);
    REQUIRE(page.core.objectCount() == 1);
    CHECK(page.core.object(0).center() == Vec2{100, 100});
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
    REQUIRE(page.core.objectCount() == 1);
    CHECK(page.core.selectedIndex() == 0);
    page.core.runGameLoop();  // the page goes on: the echo shows the ledge
    CHECK(page.window.document.ui_echo.find("Id: 0\n") != std::string::npos);
    CHECK(page.window.document.ui_echo.find("Center: 400,300\n") != std::string::npos);
    page.press(browser::Key::W);  // and the keys act on it
    CHECK(ledge.center() == Vec2{400, 290});
}

TEST_CASE("s5_1: the same seed gives the same run, another seed another") {
    const test::ScratchFolder folder("s5_1_repeat");
    auto run = [&](const std::string& name, std::uint64_t seed) {
        const std::string arguments = "--frames 90 --every 45 --no-gif --seed " + std::to_string(seed) + " --out " +
                                      test::quoted(folder.path / name) + " --dump " +
                                      test::quoted(folder.path / (name + ".csv"));
        const test::ProgramRun result = test::runStageProgram(folder, arguments);
        INFO(result.error_text);
        REQUIRE(result.status == 0);
        return test::readText(folder.path / (name + ".csv"));
    };
    const std::string first = run("first", 11), again = run("again", 11), other = run("other", 12);
    CHECK(first == again);
    CHECK(first != other);
    for (const char* picture : {"final.png", "frame_0045.png", "contact_sheet.png"}) {
        INFO(picture);
        const auto difference = browser::compare_images(browser::read_png(folder.path / "first" / picture),
                                                        browser::read_png(folder.path / "again" / picture), {});
        CHECK(difference.same_size);
        CHECK(difference.differing_pixels == 0);
    }
}

TEST_CASE("s5_1: the default run writes an animated GIF of the whole page") {
    const test::ScratchFolder folder("s5_1_gif");
    const test::ProgramRun result =
        test::runStageProgram(folder, "--frames 20 --every 0 --out " + test::quoted(folder.path / "out"));
    REQUIRE(result.status == 0);
    const std::string gif = test::readText(folder.path / "out" / "animation.gif");
    REQUIRE(gif.size() > 10);
    CHECK(gif.substr(0, 6) == "GIF89a");
    // The logical screen: width and height, little-endian, right after the signature.
    const auto u16 = [&](std::size_t at) {
        return static_cast<unsigned char>(gif[at]) | static_cast<unsigned char>(gif[at + 1]) << 8;
    };
    CHECK(u16(6) == 800 + browser::kPanelWidth);
    CHECK(u16(8) == 450);
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
    REQUIRE(run.status == 0);
    const std::vector<test::DumpRow> rows = test::readDump(dump);
    const auto at = [&](long step) {
        std::vector<test::DumpRow> found;
        std::copy_if(rows.begin(), rows.end(), std::back_inserter(found),
                     [&](const test::DumpRow& row) { return row.step == step; });
        return found;
    };
    const std::vector<test::DumpRow> start = at(0), first = at(1);
    REQUIRE(first.size() == start.size() + 6);
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
    CHECK(kicked > 0.9);
    CHECK(before < 0.5);

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
