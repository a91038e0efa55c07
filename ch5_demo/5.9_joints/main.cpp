// The stage's index.html: the canvas and the echo panel, the engine core with its
// scene (the book's, or one from --scene FILE), and the user control script that every
// key press goes to. The stage program (common/stage_main.h) does the rest: the
// options, --scene and --dump, the run's budget and its exit statuses.

#include <optional>

#include "core.h"
#include "my_game.h"
#include "page_world.h"
#include "scene_io.h"
#include "stage_main.h"
#include "user_control.h"

namespace {

// The book's demo with every knob at its default, the book's engine, continuous
// collision on, five random convex polygons (5.8) after the book's shapes, and the
// demo's game (my_game.h), which reads the events after every step: a zone on the left
// floor counts the shapes in it, a shape turns orange at its first contact, and a goal
// at the bottom right removes what falls into it. A scene file turns the knobs
// (docs/scene_format.md) and has no game. Two seconds in, a box and a ball are thrown
// from the long slide; at five seconds H kicks every shape.
// A table, an option or a key a line, which the layout would re-wrap:
// clang-format off
const browser::StageDefaults kStage{
    .id = "s5_9",
    .title = "5.9 Joints: the demo, with shapes of up to eight corners",
    .keys = "f@120 g h@300",
    .frames = 480,
    .every = 60,
    .gif = true,
    .extra_options = {{std::string(engine::kEventsOption), "FILE",
                       "write every collision event (begin, end, hit) and joint limit reached (limit) to this CSV file: step,kind,id_a,id_b,x,y,nx,ny,speed", ""}},
    // Every key user_control.cpp reacts to, as the README lists them.
    .key_help = {
        {"0-9 up down", "select an object: by its number, the one before, the one after"},
        {"w a s d", "move the selected object 10 px up, left, down, right"},
        {"q e", "turn it -0.1 / +0.1 rad"},
        {"i k", "its velocity -1 / +1 px/s along y"},
        {"j l", "its velocity -1 / +1 px/s along x"},
        {"u o", "its angular velocity -0.1 / +0.1 rad/s"},
        {"z x", "its mass -1 / +1 (0 makes it static)"},
        {"c v", "its friction -0.01 / +0.01"},
        {"b n", "its restitution -0.01 / +0.01"},
        {"comma", "movement on / off"},
        {"m", "positional correction on / off"},
        {"y", "sleeping on / off (every change of the world, and every key that changes a shape, wakes what it touches)"},
        {"p", "continuous collision on / off"},
        {"h", "excite: a random velocity for every moving shape"},
        {"f g", "a new rectangle / circle at the selected object"},
        {"slash", "a new random convex polygon, 3 to 8 corners, at the selected object (also /)"},
        {"r", "reset: keep only the first seven objects"},
    },
    .overlay = "the joints: anchors, links from the centres, limits (a revolute's arc, a slider's range, a rope's lengths) and each joint's error past 1 px, ringed, the four largest in px (--overlay-all: GJK's panels, the events, the sweeps, the grid, the islands, chapter 3's and 4's layers, the contacts too)",
    // The page notes the book's quirk beside the echo's mass (docs/errata.md): the echo
    // keeps the book's number.
    .echo_notes = {{"Mass:", "*", "the book's quirk: 1 / (1/mass rounded to 3 digits); docs/errata.md"}},
};
// clang-format on

class Page final : public browser::StagePage {
public:
    Page(browser::Window& window, browser::Random& random, const engine::Scene* scene)
        : core_(window, scene ? scene->world : engine::kBookWorld), control_(core_, random) {
        if (scene) {
            engine::buildScene(core_, *scene);
        } else {
            // The book's demo, with the game that reads its events (my_game.h).
            game_.emplace(core_, random);
            core_.setGame(&*game_);
        }
    }
    void onKeyDown(browser::Key key) override { control_.onKeyDown(key); }
    void onAnimationFrame() override { core_.runGameLoop(); }
    // 5.9: the mouse grabs, drags and lets go of a shape (mouse_joint.h).
    void onPointer(const browser::PointerEvent& event) override {
        const engine::Vec2 point{static_cast<double>(event.point.x), static_cast<double>(event.point.y)};
        switch (event.kind) {
            case browser::PointerEvent::Kind::press: core_.grab(point); break;
            case browser::PointerEvent::Kind::move: core_.dragTo(point); break;
            case browser::PointerEvent::Kind::release: core_.letGo(); break;
        }
    }
    browser::PageWorld world() override { return engine::pageWorld(core_); }

private:
    engine::Core core_;
    engine::UserControl control_;
    std::optional<engine::DemoGame> game_;  // the demo's only: a scene file has none
};

}  // namespace

int main(int argc, char** argv) { return browser::run_stage<Page>(argc, argv, kStage, engine::kSceneFiles); }
