// Stage 5.7: collision events (contact_events.h). A ball dropped on a floor begins
// touching it at the step the closed form of symplectic Euler predicts, and hits it at
// sqrt(2 g h) within one step's error; the issue trackers' failures (an end lost when a
// shape is removed, made static or moved by a key; ends sent by a pile falling asleep,
// begins by its waking); and the invariants over the book's scene, kicked, on both
// solvers, sleep and continuous collision on and off: per pair begins and ends
// alternate, and begins minus ends are the pairs touching now. Events change nothing:
// with them kept, every shipped scene still moves to the bit as 5.1 moved it (the
// identity feature test keeps them). 5.6's own tests run on this stage too
// (s5_7.s5_6_stage).
#include <catch2/catch.hpp>

#include <cmath>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "circle.h"
#include "contact_events.h"
#include "my_game.h"
#include "narrow_phase.h"
#include "rectangle.h"
#include "stage_program.h"
#include "world_fixture.h"

namespace s5_7_test {

using engine::ContactEvent;
using engine::EventKind;
using engine::Vec2;

namespace {

constexpr engine::SolverKind kBothSolvers[] = {engine::SolverKind::book, engine::SolverKind::sequential_impulse};
constexpr engine::PhysicalAttributes kStatic{.mass = 0.0};

engine::WorldSettings eventWorld(engine::SolverKind solver, bool sleep = false) {
    engine::WorldSettings world = test::world(true);
    world.solver = solver;
    world.sleep = sleep;
    return world;
}

std::vector<ContactEvent> ofKind(const std::vector<ContactEvent>& events, EventKind kind) {
    std::vector<ContactEvent> chosen;
    for (const ContactEvent& event : events) {
        if (event.kind == kind) chosen.push_back(event);
    }
    return chosen;
}

// Steps until the first event of `kind`, at most `limit` steps; the events of that step.
std::vector<ContactEvent> stepUntil(test::WorldFixture& page, EventKind kind, int limit) {
    for (int step = 0; step < limit; ++step) {
        page.core.update();
        if (!ofKind(page.core.events().events(), kind).empty()) return page.core.events().events();
    }
    return {};
}

// A static floor, its top at y = 300, and a ball of radius 10 at rest above it.
struct Drop {
    Drop(test::WorldFixture& page, double gap)
        : floor(page.core.add(engine::Rectangle({400, 320}, 700, 40, kStatic))),
          ball(page.core.add(engine::Circle({400, 300 - kRadius - gap}, kRadius))) {}
    static constexpr double kRadius = 10.0;
    engine::Rectangle& floor;
    engine::Circle& ball;
};

}  // namespace

TEST_CASE("s5_7: a ball dropped from h begins at the step the closed form says, and hits at sqrt(2 g h)") {
    for (const engine::SolverKind solver : kBothSolvers) {
        for (const double gap : {10.0, 190.0, 250.0}) {
            INFO("solver " << static_cast<int>(solver) << ", dropped " << gap << " px");
            test::WorldFixture page(eventWorld(solver));
            page.core.keepEvents(true);
            Drop drop(page, gap);
            // Symplectic Euler from rest: after n updates v = n g dt and the ball has
            // fallen g dt^2 n (n + 1) / 2. The collision pass of step k looks at the ball
            // after k - 1 updates: the first step that finds it overlapping the floor is
            // the first n with that fall > gap, plus one.
            const double g = engine::kGravity.y;
            const double dt = engine::kBookWorld.dt;
            long n = 0;
            while (g * dt * dt * static_cast<double>(n * (n + 1)) / 2 <= gap) ++n;
            const std::vector<ContactEvent> events = stepUntil(page, EventKind::begin, 2000);
            INFO("the ball's first begin, at step " << page.core.stepCount() << "; the closed form's: " << n + 1);
            REQUIRE(page.core.stepCount() == n + 1);
            const std::vector<ContactEvent> hits = ofKind(events, EventKind::hit);
            INFO("hit events in the begin's step: " << hits.size() << ", one expected");
            REQUIRE(hits.size() == 1);
            CHECK(hits[0].step == n + 1);
            CHECK(hits[0].id_a == drop.floor.id());
            CHECK(hits[0].id_b == drop.ball.id());
            // The ball met the floor at n g dt, which is sqrt(2 g h) to within a step's
            // gain, g dt (the last step's fall overshoots the gap by less than a step).
            CHECK(hits[0].speed == Approx(static_cast<double>(n) * g * dt).margin(1e-9));
            CHECK(std::abs(hits[0].speed - std::sqrt(2 * g * gap)) < g * dt);
            // Where: on the floor's top under the ball; the normal from floor to ball, up.
            CHECK(hits[0].point.x == Approx(400.0));
            CHECK(std::abs(hits[0].point.y - 300.0) < 1.0);
            CHECK(hits[0].normal.y == Approx(-1.0));
        }
    }
}

TEST_CASE("s5_7: a gentle touch begins but is no hit; a pair that parts ends, once") {
    for (const engine::SolverKind solver : kBothSolvers) {
        test::WorldFixture page(eventWorld(solver));
        page.core.keepEvents(true);
        Drop drop(page, 1.0);  // 1 px: it meets the floor at about sqrt(2 g) = 6.3 px/s
        const std::vector<ContactEvent> events = stepUntil(page, EventKind::begin, 100);
        INFO("a 1 px drop: begins " << ofKind(events, EventKind::begin).size() << " (1 expected), hits "
                                    << ofKind(events, EventKind::hit).size() << " (none: 6.3 px/s < kHitSpeed)");
        REQUIRE(ofKind(events, EventKind::begin).size() == 1);
        CHECK(ofKind(events, EventKind::hit).empty());
        // Its small bounces over, at rest on the floor it touches, step after step, with
        // no event.
        page.steps(120);
        INFO("pairs touching with the ball at rest on the floor: " << page.core.events().touchingCount());
        REQUIRE(page.core.events().touchingCount() == 1);
        for (int i = 0; i < 60; ++i) {
            page.core.update();
            INFO("events of a resting pair at step " << page.core.stepCount() << ": "
                                                     << page.core.events().events().size() << ", none expected");
            REQUIRE(page.core.events().events().empty());
        }
        // Thrown up hard, it leaves the floor: one end.
        // The step that throws it still finds it touching the floor; the next kMissedSteps
        // do not, and the last of them ends the pair.
        drop.ball.setVelocity({0, -300});
        page.steps(engine::kMissedSteps);
        INFO("events before the pair has been missed kMissedSteps times: " << page.core.events().events().size());
        REQUIRE(page.core.events().events().empty());
        page.core.update();
        const std::vector<ContactEvent> ends = ofKind(page.core.events().events(), EventKind::end);
        INFO("end events once the thrown ball is gone kMissedSteps steps: " << ends.size() << ", one expected");
        REQUIRE(ends.size() == 1);
        CHECK(ends[0].id_b == drop.ball.id());
        CHECK(page.core.events().touchingCount() == 0);
    }
}

namespace {

// A ball resting on the floor, touching: the first steps until its begin.
struct Resting {
    explicit Resting(test::WorldFixture& page) : drop(page, 0.5) {
        page.core.keepEvents(true);
        REQUIRE_FALSE(stepUntil(page, EventKind::begin, 100).empty());
        page.steps(120);  // 2 s: its small bounces are over, it rests on the floor
        INFO("pairs touching with the ball at rest on the floor: " << page.core.events().touchingCount());
        REQUIRE(page.core.events().touchingCount() == 1);
    }
    Drop drop;
};

// The one end event of the floor and the ball (by their ids: the ball may be gone).
void requireOneEnd(const std::vector<ContactEvent>& events, engine::BodyId floor, engine::BodyId ball) {
    const std::vector<ContactEvent> ends = ofKind(events, EventKind::end);
    INFO("end events of the floor (id " << floor << ") and the ball (id " << ball << "): " << ends.size()
                                        << ", one expected");
    REQUIRE(ends.size() == 1);
    CHECK(ends[0].id_a == floor);
    CHECK(ends[0].id_b == ball);
}

}  // namespace

TEST_CASE("s5_7: a shape removed by the reset key ends each pair it touched (FXGL #566, qml-box2d #99)") {
    for (const engine::SolverKind solver : kBothSolvers) {
        test::WorldFixture page(eventWorld(solver));
        // Seven shapes far apart keep their places on reset; the ball is the eighth.
        for (int i = 0; i < 6; ++i) page.core.add(engine::Circle({60.0 + 40 * i, 40}, 5, kStatic));
        Resting resting(page);
        const engine::BodyId floor = resting.drop.floor.id();
        const engine::BodyId ball = resting.drop.ball.id();
        const long step = page.core.stepCount();
        page.press(browser::Key::R);
        REQUIRE(page.core.objectCount() == 7);
        page.core.update();
        requireOneEnd(page.core.events().events(), floor, ball);
        CHECK(ofKind(page.core.events().events(), EventKind::end)[0].step == step);
        CHECK(page.core.events().touchingCount() == 0);
        // And nothing ever names the removed ball again.
        for (int i = 0; i < 30; ++i) {
            page.core.update();
            CHECK(page.core.events().events().empty());
        }
    }
}

TEST_CASE("s5_7: a shape leaving the canvas ends its pairs in the step it goes (matter.js #230)") {
    for (const engine::SolverKind solver : kBothSolvers) {
        test::WorldFixture page(eventWorld(solver));
        Resting resting(page);
        const engine::BodyId floor = resting.drop.floor.id();
        const engine::BodyId ball = resting.drop.ball.id();
        resting.drop.ball.move({340, 0});  // x = 740: on the floor's right end, 60 px from the canvas's edge
        page.core.update();
        REQUIRE(page.core.events().touchingCount() == 1);  // moved by hand, not by a key: still touching
        resting.drop.ball.setVelocity({4200, 0});          // 70 px a step: past the edge in one
        page.core.update();
        REQUIRE(page.core.objectCount() == 1);
        requireOneEnd(page.core.events().events(), floor, ball);
        CHECK(page.core.events().touchingCount() == 0);
    }
}

TEST_CASE("s5_7: made static by the mass key, or moved by W, a shape ends its pairs (Box2D #828)") {
    for (const engine::SolverKind solver : kBothSolvers) {
        SECTION("mass key") {
            test::WorldFixture page(eventWorld(solver));
            Resting resting(page);
            const engine::BodyId floor = resting.drop.floor.id();
            const engine::BodyId ball = resting.drop.ball.id();
            page.core.select(1);
            page.press(browser::Key::Z);  // mass 1 - 1 = 0: static
            REQUIRE(resting.drop.ball.isStatic());
            page.core.update();
            requireOneEnd(page.core.events().events(), floor, ball);
            // Two static shapes: no pass tests them, and nothing begins again.
            for (int i = 0; i < 10; ++i) {
                page.core.update();
                CHECK(page.core.events().events().empty());
            }
        }
        SECTION("W") {
            test::WorldFixture page(eventWorld(solver));
            Resting resting(page);
            const engine::BodyId floor = resting.drop.floor.id();
            const engine::BodyId ball = resting.drop.ball.id();
            page.core.select(1);
            page.press(browser::Key::W);  // 10 px up: apart
            page.core.update();
            requireOneEnd(page.core.events().events(), floor, ball);
            // It falls back: a new begin, some steps later.
            CHECK_FALSE(stepUntil(page, EventKind::begin, 120).empty());
        }
    }
}

TEST_CASE("s5_7: a pile that falls asleep touching sends no end, and its waking no begin (matter.js #1232)") {
    for (const engine::SolverKind solver : kBothSolvers) {
        test::WorldFixture page(eventWorld(solver, true));
        page.core.keepEvents(true);
        page.core.add(engine::Rectangle({400, 320}, 700, 40, kStatic));
        for (int i = 0; i < 3; ++i) page.core.add(engine::Rectangle({300.0 + 100 * i, 289.5}, 40, 20));
        int begins = 0;
        int ends = 0;
        const auto count = [&] {
            begins += static_cast<int>(ofKind(page.core.events().events(), EventKind::begin).size());
            ends += static_cast<int>(ofKind(page.core.events().events(), EventKind::end).size());
        };
        int step = 0;
        for (; step < 1200 && page.core.awakeCount() > 0; ++step) {
            page.core.update();
            count();
        }
        INFO("solver " << static_cast<int>(solver) << ", awake " << page.core.awakeCount() << " after " << step
                       << " steps");
        REQUIRE(page.core.awakeCount() == 0);
        REQUIRE(page.core.events().touchingCount() == 3);
        REQUIRE(begins - ends == 3);
        const int begins_asleep = begins;
        const int ends_asleep = ends;
        for (int i = 0; i < 120; ++i) {
            page.core.update();
            count();
        }
        INFO("end events while the boxes sleep: " << ends - ends_asleep << ", none expected");
        CHECK(ends == ends_asleep);
        page.core.wakeAll();
        for (int i = 0; i < 10; ++i) {
            page.core.update();
            count();
        }
        REQUIRE(page.core.awakeCount() > 0);
        INFO("after waking: begins " << begins - begins_asleep << ", ends " << ends - ends_asleep << ", none expected");
        CHECK(begins == begins_asleep);
        CHECK(ends == ends_asleep);
        CHECK(page.core.events().touchingCount() == 3);
    }
}

namespace {

// A static sensor rectangle (rigid_shape.h: it feels, it takes no part).
engine::Rectangle& addSensor(test::WorldFixture& page, Vec2 center, double width, double height) {
    engine::Rectangle& sensor = page.core.add(engine::Rectangle(center, width, height, kStatic));
    sensor.setSensor(true);
    return sensor;
}

}  // namespace

TEST_CASE("s5_7: a sensor feels a falling ball enter and leave, and leaves its fall untouched to the bit") {
    for (const engine::SolverKind solver : kBothSolvers) {
        INFO("solver " << static_cast<int>(solver));
        // The same fall twice: through a sensor zone (y 180 to 220), and with no zone.
        test::WorldFixture zoned(eventWorld(solver));
        test::WorldFixture open(eventWorld(solver));
        zoned.core.keepEvents(true);
        const engine::Rectangle& zone = addSensor(zoned, {400, 200}, 100, 40);
        open.core.add(engine::Rectangle({40, 40}, 10, 10, kStatic));  // the ball's id alike in both
        engine::Circle& ball = zoned.core.add(engine::Circle({400, 100}, 10));
        engine::Circle& twin = open.core.add(engine::Circle({400, 100}, 10));
        // The ball's centre before each step (index k: after k updates).
        std::vector<double> y_before{ball.center().y};
        std::vector<ContactEvent> told;
        // 5 s: it falls 250 px, to y = 350, still on the canvas (no floor: nothing else touches it).
        for (int step = 1; step <= 300; ++step) {
            zoned.core.update();
            open.core.update();
            REQUIRE(ball.center().x == twin.center().x);  // not a bit of difference: no response
            REQUIRE(ball.center().y == twin.center().y);
            REQUIRE(ball.velocity().y == twin.velocity().y);
            y_before.push_back(ball.center().y);
            for (const ContactEvent& event : zoned.core.events().events()) told.push_back(event);
        }
        // The collision pass of step s looks at the ball after s - 1 updates: it overlaps
        // the zone when its bottom is below 180 and its top above 220.
        const auto inZone = [&](long s) {
            const double y = y_before[static_cast<std::size_t>(s - 1)];
            return y + 10 > 180 && y - 10 < 220;
        };
        long first_in = 0, last_in = 0;
        for (long s = 1; s <= 300; ++s) {
            if (inZone(s) && first_in == 0) first_in = s;
            if (inZone(s)) last_in = s;
        }
        REQUIRE(first_in > 0);
        REQUIRE(last_in < 300 - engine::kMissedSteps);  // it left the zone in the run
        INFO("the ball is in the zone from step " << first_in << " to " << last_in << "; events told: " << told.size());
        REQUIRE(told.size() == 2);  // a begin, an end, and no hit: nothing strikes a zone
        CHECK(told[0].kind == EventKind::begin);
        CHECK(told[0].step == first_in);
        CHECK(told[0].id_a == zone.id());
        CHECK(told[0].id_b == ball.id());
        CHECK(told[1].kind == EventKind::end);
        CHECK(told[1].step == last_in + engine::kMissedSteps);
    }
}

TEST_CASE(
    "s5_7: a sensor feels a box that falls asleep inside it to the end: no end, and no begin on waking (Jolt #277)") {
    for (const engine::SolverKind solver : kBothSolvers) {
        INFO("solver " << static_cast<int>(solver));
        test::WorldFixture page(eventWorld(solver, true));
        page.core.keepEvents(true);
        page.core.add(engine::Rectangle({400, 320}, 700, 40, kStatic));
        addSensor(page, {400, 270}, 200, 60);  // over the floor's middle, from y 240 to 300
        engine::Rectangle& box = page.core.add(engine::Rectangle({400, 289.5}, 40, 20));
        long begins = 0, ends = 0;
        const auto count = [&] {
            begins += static_cast<long>(ofKind(page.core.events().events(), EventKind::begin).size());
            ends += static_cast<long>(ofKind(page.core.events().events(), EventKind::end).size());
        };
        for (int step = 0; step < 1200 && page.core.awakeCount() > 0; ++step) {
            page.core.update();
            count();
        }
        REQUIRE(box.sleep().asleep);
        INFO("pairs touching with the box asleep on the floor in the zone: " << page.core.events().touchingCount());
        REQUIRE(page.core.events().touchingCount() == 2);  // the floor, and the zone
        const long begins_asleep = begins;
        const long ends_asleep = ends;
        for (int i = 0; i < 300; ++i) {
            page.core.update();
            count();
        }
        INFO("end events in 5 s of sleep inside the zone: " << ends - ends_asleep << ", none expected");
        CHECK(ends == ends_asleep);
        page.core.wakeAll();
        for (int i = 0; i < 10; ++i) {
            page.core.update();
            count();
        }
        INFO("after waking: begins " << begins - begins_asleep << ", ends " << ends - ends_asleep << ", none expected");
        CHECK(begins == begins_asleep);
        CHECK(ends == ends_asleep);
        CHECK(page.core.events().touchingCount() == 2);
    }
}

TEST_CASE("s5_7: a thin sensor crossed by a fast shape within one step: one begin and one end (Box2D's sensor test)") {
    for (const engine::SolverKind solver : kBothSolvers) {
        for (const bool continuous : {true, false}) {
            INFO("solver " << static_cast<int>(solver) << ", continuous " << continuous);
            engine::WorldSettings world = eventWorld(solver);
            world.gravity = {0, 0};
            world.continuous = continuous;
            test::WorldFixture page(world);
            page.core.keepEvents(true);
            // A 2 px gate at x 399 to 401, and a 2 px ball at 3000 px/s: 50 px a step, its
            // centre at 125 + 50 k, so no step ever ends with it in the gate.
            const engine::Rectangle& gate = addSensor(page, {400, 200}, 2, 200);
            engine::Circle& ball = page.core.add(engine::Circle({125, 200}, 2));
            ball.setVelocity({3000, 0});
            std::vector<ContactEvent> told;
            for (int step = 0; step < 10; ++step) {
                page.core.update();
                for (const ContactEvent& event : page.core.events().events()) told.push_back(event);
            }
            CHECK(ball.center().x > 500);  // through: a sensor stops nothing, swept or not
            if (!continuous) {
                INFO("events with continuous collision off: " << told.size() << " (the ball tunnels, unseen)");
                CHECK(told.empty());
                continue;
            }
            INFO("events with continuous collision on: " << told.size() << ", a begin and an end expected");
            REQUIRE(told.size() == 2);
            CHECK(told[0].kind == EventKind::begin);
            CHECK(told[1].kind == EventKind::end);
            CHECK(told[1].step == told[0].step + engine::kMissedSteps);
            CHECK(told[0].id_a == gate.id());
            CHECK(told[0].id_b == ball.id());
            // Where: the ball's centre as its outline was kImpactDepth (0.5 px) into the
            // gate's near face, x = 399 - 2 + 0.5, to within the sweep's quarter depth.
            CHECK(std::abs(told[0].point.x - 397.5) <= 0.125 + 1e-9);
            CHECK(told[0].normal.x == Approx(-1.0));  // from the gate to the ball, against its motion
        }
    }
}

TEST_CASE("s5_7: sensors do not feel each other; a moving sensor falls through a static one untold") {
    for (const engine::SolverKind solver : kBothSolvers) {
        test::WorldFixture page(eventWorld(solver));
        page.core.keepEvents(true);
        addSensor(page, {400, 200}, 300, 100);
        engine::Circle& falling = page.core.add(engine::Circle({400, 120}, 20));
        falling.setSensor(true);
        page.steps(240);
        INFO("events between two sensors: " << page.core.events().touchingCount() << " touching");
        CHECK(page.core.events().touchingCount() == 0);
        CHECK(falling.center().y > 200);  // it fell on, into and through the other
    }
}

TEST_CASE("s5_7: per pair begins and ends alternate, and begins minus ends touch now: the book's scene, kicked") {
    for (const engine::SolverKind solver : kBothSolvers) {
        for (const bool sleep : {false, true}) {
            for (const bool continuous : {false, true}) {
                INFO("solver " << static_cast<int>(solver) << ", sleep " << sleep << ", continuous " << continuous);
                engine::WorldSettings world = eventWorld(solver, sleep);
                world.continuous = continuous;
                test::WorldFixture page(world, 7);
                page.core.keepEvents(true);
                engine::buildScene(page.core, page.random);
                addSensor(page, {400, 300}, 300, 200);                          // a zone (the reset key removes it)
                std::map<std::pair<engine::BodyId, engine::BodyId>, int> open;  // 1 while a pair touches
                long begins = 0;
                long ends = 0;
                for (int step = 1; step <= 600; ++step) {
                    if (step % 150 == 0) page.press(browser::Key::H);
                    if (step % 200 == 0) page.press(browser::Key::G);
                    if (step == 450) page.press(browser::Key::R);
                    page.core.update();
                    for (const ContactEvent& event : page.core.events().events()) {
                        int& state = open[{event.id_a, event.id_b}];
                        INFO("step " << step << ": " << engine::kindName(event.kind) << " of the pair " << event.id_a
                                     << "-" << event.id_b << " (touching before: " << state << "), speed "
                                     << event.speed);
                        REQUIRE(event.id_a < event.id_b);
                        if (event.kind == EventKind::begin) {
                            REQUIRE(state == 0);
                            state = 1;
                            ++begins;
                        } else if (event.kind == EventKind::end) {
                            REQUIRE(state == 1);
                            state = 0;
                            ++ends;
                        } else {
                            REQUIRE(state == 1);  // a hit comes right after its begin
                            REQUIRE(event.speed > engine::kHitSpeed);
                        }
                    }
                    INFO("step " << step << ": begins " << begins << " - ends " << ends << " against "
                                 << page.core.events().touchingCount() << " pairs touching");
                    REQUIRE(begins - ends == static_cast<long>(page.core.events().touchingCount()));
                }
                CHECK(begins > 20);  // the scene does touch: the test can fail
                CHECK(ends > 0);
            }
        }
    }
}

namespace {

// One line of --events FILE: step,kind,id_a,id_b,x,y,nx,ny,speed.
struct EventRow {
    long step = 0;
    std::string kind;
    engine::BodyId id_a = 0, id_b = 0;
    double x = 0, y = 0, nx = 0, ny = 0, speed = 0;
};

std::vector<EventRow> readEvents(const std::filesystem::path& file) {
    std::istringstream text(test::readText(file));
    std::string line;
    std::getline(text, line);
    REQUIRE(line == "step,kind,id_a,id_b,x,y,nx,ny,speed");
    std::vector<EventRow> rows;
    while (std::getline(text, line)) {
        std::vector<std::string> field;
        std::istringstream cells(line);
        for (std::string cell; std::getline(cells, cell, ',');) field.push_back(cell);
        INFO(line);
        REQUIRE(field.size() == 9);
        const auto number = [](const std::string& cell) {
            std::size_t used = 0;
            const double value = std::stod(cell, &used);
            REQUIRE(used == cell.size());
            return value;
        };
        rows.push_back({std::stol(field[0]), field[1], std::stoull(field[2]), std::stoull(field[3]), number(field[4]),
                        number(field[5]), number(field[6]), number(field[7]), number(field[8])});
    }
    return rows;
}

}  // namespace

TEST_CASE("s5_7: --events FILE writes every event of the run; the shapes move as without it") {
    const test::ScratchFolder folder("s5_7-events");
    const std::string run_of = " --frames 420 --every 0 --no-gif --out ";
    const test::ProgramRun quiet = test::runStageProgram(
        folder, run_of + test::quoted(folder.path / "quiet") + " --dump " + test::quoted(folder.path / "quiet.csv"));
    REQUIRE(quiet.status == 0);
    const test::ProgramRun told = test::runStageProgram(
        folder, run_of + test::quoted(folder.path / "told") + " --dump " + test::quoted(folder.path / "told.csv") +
                    " --events " + test::quoted(folder.path / "events.csv") + " --overlay");
    REQUIRE(told.status == 0);
    // Reading the events changes nothing in the world: the dumps agree to the bit.
    CHECK(test::readText(folder.path / "quiet.csv") == test::readText(folder.path / "told.csv"));

    // Every event names two shapes of the world as its step began or ended (the dump of
    // the step before, or of its own: a shape added by a key between the two, or one
    // the demo's goal removed after the step, is in one only), smaller id first, with a
    // unit normal; a hit follows its begin, faster than kHitSpeed; per pair begins and
    // ends alternate.
    std::map<long, std::set<std::uint64_t>> ids_at;
    for (const test::DumpRow& row : test::readDump(folder.path / "told.csv")) ids_at[row.step].insert(*row.id);
    std::map<std::pair<engine::BodyId, engine::BodyId>, int> open;
    std::map<std::string, int> count;
    const std::vector<EventRow> events = readEvents(folder.path / "events.csv");
    for (std::size_t i = 0; i < events.size(); ++i) {
        const EventRow& event = events[i];
        INFO("line " << i + 2 << ": step " << event.step << " " << event.kind << " " << event.id_a << "-"
                     << event.id_b);
        ++count[event.kind];
        REQUIRE(event.id_a < event.id_b);
        for (const engine::BodyId id : {event.id_a, event.id_b}) {
            INFO("shape " << id);
            CHECK(ids_at[event.step - 1].count(id) + ids_at[event.step].count(id) >= 1);
        }
        CHECK_THAT(std::hypot(event.nx, event.ny), test::near(1.0, 1e-12));
        int& state = open[{event.id_a, event.id_b}];
        if (event.kind == "begin") {
            REQUIRE(state == 0);
            state = 1;
        } else if (event.kind == "end") {
            REQUIRE(state == 1);
            state = 0;
        } else {
            REQUIRE(event.kind == "hit");
            REQUIRE(i > 0);
            CHECK(events[i - 1].kind == "begin");
            CHECK(events[i - 1].id_a == event.id_a);
            CHECK(events[i - 1].id_b == event.id_b);
            CHECK(event.speed > engine::kHitSpeed);
        }
    }
    // The demo's shapes do meet, part and strike: the test can fail.
    CHECK(count["begin"] > 10);
    CHECK(count["end"] > 5);
    CHECK(count["hit"] > 5);
}

TEST_CASE("s5_7: --events refuses a file another output of the run writes, and writes nothing") {
    const test::ScratchFolder folder("s5_7-events-refused");
    const std::string out = " --frames 3 --no-gif --out " + test::quoted(folder.path / "out");
    test::checkRefused(folder,
                       "--events " + test::quoted(folder.path / "same.csv") + " --dump " +
                           test::quoted(folder.path / "same.csv") + out,
                       "it is also the state dump");
    test::checkRefused(folder, "--events " + test::quoted(folder.path / "out" / "final.png") + out,
                       "cannot write event list");
    test::checkRefused(folder, "--events " + test::quoted(folder.path) + out, "cannot write event list");
}

TEST_CASE("s5_7: the demo's goal removes what enters it after the step; no later event names it (matter.js #206)") {
    test::WorldFixture page(engine::kBookWorld);
    engine::DemoGame game(page.core, page.random);
    page.core.setGame(&game);
    REQUIRE(page.core.object(4).id() == game.zone());  // after the book's four platforms
    REQUIRE(page.core.object(5).id() == game.goal());
    std::map<engine::BodyId, long> scored_at;  // a shape's id, the step the goal took it
    std::map<std::pair<engine::BodyId, engine::BodyId>, int> open;
    for (int step = 1; step <= 900; ++step) {
        if (step % 300 == 0) page.press(browser::Key::H);  // kicks: more shapes reach the goal
        page.core.update();
        for (const ContactEvent& event : page.core.events().events()) {
            for (const engine::BodyId id : {event.id_a, event.id_b}) {
                const auto taken = scored_at.find(id);
                if (taken == scored_at.end()) continue;
                // After its removal a shape is named once more, by the ends of its pairs,
                // in the next step's list (dated the step it was removed in); never again.
                INFO("step " << step << ": " << engine::kindName(event.kind) << " names shape " << id
                             << ", removed by the goal after step " << taken->second);
                CHECK(event.kind == EventKind::end);
                CHECK(step == taken->second + 1);
                CHECK(event.step == taken->second);
            }
            int& state = open[{event.id_a, event.id_b}];
            if (event.kind == EventKind::begin) state = 1;
            if (event.kind == EventKind::end) state = 0;
            if (event.kind == EventKind::begin && (event.id_a == game.goal() || event.id_b == game.goal())) {
                scored_at[event.id_a == game.goal() ? event.id_b : event.id_a] = step;
            }
        }
        // Each one taken is gone from the world by the end of the step that told it.
        for (const auto& [id, at] : scored_at) {
            for (std::size_t i = 0; i < page.core.objectCount(); ++i) REQUIRE(page.core.object(i).id() != id);
        }
    }
    INFO("shapes the goal took: " << scored_at.size());
    CHECK(game.scored() == static_cast<int>(scored_at.size()));
    CHECK(game.scored() >= 1);  // the demo does score: the test can fail
    // No pair of a removed shape is left open.
    for (const auto& [pair, state] : open) {
        if (scored_at.count(pair.first) || scored_at.count(pair.second)) CHECK(state == 0);
    }
}

TEST_CASE("s5_7: the demo's zone counts what lies in it, and a shape turns orange at its first contact") {
    // On the sequential impulse solver, which looks at each pair once a step, where the
    // step begins: "touching" (contact_events.h) is then exactly "overlapping where one
    // of the last kMissedSteps steps began", which the test works out from the geometry.
    engine::WorldSettings world = engine::kBookWorld;
    world.solver = engine::SolverKind::sequential_impulse;
    test::WorldFixture page(world);
    engine::DemoGame game(page.core, page.random);
    page.core.setGame(&game);
    // Before any step nothing has met anything: no shape is painted.
    for (std::size_t i = 0; i < page.core.objectCount(); ++i) CHECK_FALSE(game.colourOf(page.core.object(i)));
    const auto zone = [&]() -> const engine::RigidShape& {
        for (std::size_t i = 0; i < page.core.objectCount(); ++i) {
            if (page.core.object(i).id() == game.zone()) return page.core.object(i);
        }
        FAIL("the zone is gone");
        throw;
    };
    std::vector<std::set<engine::BodyId>> overlapping_at;  // the moving shapes in the zone as each step began
    std::size_t most_inside = 0;
    for (int step = 1; step <= 1200; ++step) {
        std::set<engine::BodyId> in_zone;
        for (std::size_t i = 0; i < page.core.objectCount(); ++i) {
            const engine::RigidShape& shape = page.core.object(i);
            if (!shape.isStatic() && engine::narrowPhase(zone(), shape)) in_zone.insert(shape.id());
        }
        overlapping_at.push_back(in_zone);
        page.core.update();
        // In the zone now: found at the start of this step or of one of the kMissedSteps - 1 before,
        // and still in the world.
        std::set<engine::BodyId> expected;
        for (std::size_t back = 0;
             back < static_cast<std::size_t>(engine::kMissedSteps) && back < overlapping_at.size(); ++back) {
            for (const engine::BodyId id : overlapping_at[overlapping_at.size() - 1 - back]) {
                for (std::size_t i = 0; i < page.core.objectCount(); ++i) {
                    if (page.core.object(i).id() == id) expected.insert(id);
                }
            }
        }
        INFO("step " << step << ": the game counts " << game.insideZone() << " in the zone, the geometry "
                     << expected.size());
        REQUIRE(game.insideZone() == expected.size());
        most_inside = std::max(most_inside, expected.size());
    }
    CHECK(most_inside >= 2);  // shapes do settle in it: the test can fail
    // Every shape still on the canvas has landed on something, so has met another, and
    // is orange; the platforms and the sensors keep their colours.
    for (std::size_t i = 0; i < page.core.objectCount(); ++i) {
        const engine::RigidShape& shape = page.core.object(i);
        INFO("shape " << shape.id() << (shape.isStatic() ? ", static" : ", moving"));
        if (shape.isStatic()) {
            CHECK_FALSE(game.colourOf(shape));
        } else {
            CHECK(game.colourOf(shape) == browser::colors::kOrange);
        }
    }
}

}  // namespace s5_7_test
