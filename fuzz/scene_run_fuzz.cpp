// Fuzz target: a scene read and run by the newest stage (5.8: sleeping, continuous
// collision, bullets, sensors and convex polygons as a scene file sets them, and its
// collision events kept). The input is the scene file's
// text, as --scene reads it; an accepted scene is built and stepped, as the program
// would run it, for as many steps as a small budget of pair tests allows (up to 20).
//
// Properties, besides "no crash, no sanitizer report, no exception but SceneError and
// NonFiniteState" (a state no double can hold ends a run with exit status 3):
//  - a refusal is one line;
//  - every sweep of a fast shape (continuous.h) stops it at a share of its step in
//    [0, 1], on the straight line from where its step began to where its motion took it;
//  - the same scene run twice gives the same state, bit for bit;
//  - with collision events (contact_events.h, from 5.7), per pair begins and ends
//    alternate, a hit follows its begin, and begins minus ends are the pairs touching.

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "browser.h"
#include "continuous.h"
#include "core.h"
#include "fuzz_check.h"
#include "keys.h"
#include "page_world.h"
#include "scene_file.h"
#include "scene_io.h"
#include "stage_main.h"
#include "state_dump.h"

namespace {

// The pair tests a fuzz input may cost, over all its steps (page_world.h counts a step's
// as the program's budget does): a few milliseconds.
constexpr double kPairTestBudget = 2e6;
constexpr int kMostSteps = 20;

struct BodyState {
    double cx, cy, angle, vx, vy, spin;
    bool operator==(const BodyState& other) const { return std::memcmp(this, &other, sizeof *this) == 0; }
};

void checkSweeps(const engine::Core& core) {
    for (const engine::Sweep& sweep : core.continuous().sweeps()) {
        if (sweep.index >= core.objectCount()) fuzz::property_failed("a sweep names a shape of the world");
        if (!sweep.impact) continue;
        const double t = *sweep.impact;
        fuzz::require(t >= 0.0 && t <= 1.0, "a sweep stops a shape within its step");
        const engine::Vec2 expected = sweep.from + (sweep.to - sweep.from) * t;
        const engine::Vec2 at = core.object(sweep.index).center();
        const double slack =
            1e-9 * (1.0 + std::abs(expected.x) + std::abs(expected.y) + (sweep.to - sweep.from).length());
        fuzz::require(std::abs(at.x - expected.x) <= slack && std::abs(at.y - expected.y) <= slack,
                      "a swept shape stops on the line of its step's motion");
    }
}

#if __has_include("contact_events.h")
// Per pair, 1 while it touches; and begins minus ends over the run.
struct EventTally {
    std::map<std::pair<engine::BodyId, engine::BodyId>, int> touching;
    long open = 0;
};

void checkEvents(const engine::Core& core, EventTally& tally) {
    const std::vector<engine::ContactEvent>& events = core.events().events();
    for (std::size_t i = 0; i < events.size(); ++i) {
        const engine::ContactEvent& event = events[i];
        fuzz::require(event.id_a < event.id_b, "an event names its pair smaller id first");
        int& state = tally.touching[{event.id_a, event.id_b}];
        switch (event.kind) {
            case engine::EventKind::begin:
                fuzz::require(state == 0, "a pair begins only when it was not touching");
                state = 1;
                ++tally.open;
                break;
            case engine::EventKind::end:
                fuzz::require(state == 1, "a pair ends only when it was touching");
                state = 0;
                --tally.open;
                break;
            case engine::EventKind::hit:
                fuzz::require(i > 0 && events[i - 1].kind == engine::EventKind::begin &&
                                  events[i - 1].id_a == event.id_a && events[i - 1].id_b == event.id_b,
                              "a hit follows its begin");
                break;
#if __has_include("joints.h")
            case engine::EventKind::limit:
                // A joint reaching its limit names the joint's two bodies: no contact,
                // so it neither opens nor closes a pair.
                break;
#endif
        }
    }
    fuzz::require(tally.open == static_cast<long>(core.events().touchingCount()),
                  "begins minus ends are the pairs touching");
}
#endif

// Runs the scene; the state after each step, every body in order.
std::vector<BodyState> run(const engine::Scene& scene) {
    browser::Window window(scene.world.dt * 1000.0);
    engine::Core core(window, scene.world);
#if __has_include("contact_events.h")
    core.keepEvents(true);  // they only watch: the second run, the same, keeps them too
    EventTally tally;
#endif
    engine::buildScene(core, scene.bodies);
    const browser::PageWorld world = engine::pageWorld(core);
    const browser::WorldCost cost = engine::worldCost(core, browser::KeyScript());
    const double per_step = std::max(1.0, cost.step_work);
    const int steps = std::clamp(static_cast<int>(kPairTestBudget / per_step), 1, kMostSteps);
    std::vector<BodyState> states;
    for (int step = 0; step < steps; ++step) {
        core.update();
        if (scene.world.substeps == 1) checkSweeps(core);  // a sub-step's sweeps are its own
#if __has_include("contact_events.h")
        checkEvents(core, tally);
#endif
        try {
            browser::check_finite(world);
        } catch (const browser::NonFiniteState&) {
            break;  // the program stops here, with exit status 3
        }
        for (std::size_t i = 0; i < core.objectCount(); ++i) {
            const engine::RigidShape& shape = core.object(i);
            states.push_back({shape.center().x, shape.center().y, shape.angle(), shape.velocity().x, shape.velocity().y,
                              shape.angularVelocity()});
        }
    }
    return states;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    engine::Scene scene;
    try {
        scene = engine::readScene(text, "fuzz.json");
    } catch (const browser::SceneError& refusal) {
        fuzz::require(fuzz::one_line(refusal.what()), "a refusal is one line:", refusal.what());
        return 0;
    }
    const std::vector<BodyState> first = run(scene);
    fuzz::require(run(scene) == first, "the same scene runs to the same state twice");
    return 0;
}
