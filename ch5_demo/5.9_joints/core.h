#pragma once
// The engine core (the book's EngineCore/Core.js): the list of every rigid shape in the
// world, the selected one, and the engine loop that updates and shows them. The book
// keeps all this in a global, gEngine.Core; here it is one object that the page
// creates and passes to whoever needs it.

#include <concepts>
#include <cstddef>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "browser.h"
#include "continuous.h"
#include "mouse_joint.h"
#include "physics.h"
#include "rigid_shape.h"
#include "world_settings.h"

namespace engine {

class Core;

// 5.7: the game's own logic (the demo's is in my_game.h), which reads the step's events
// and may change the world: remove a shape, count, paint. The core calls it after each
// step, once the step is over, never inside it (contact_events.h says why).
class GameLogic {
public:
    virtual ~GameLogic() = default;
    // After every fixed step, with that step's events in core.events().
    virtual void afterStep(Core& core) = 0;
    // The colour the game wants `shape` drawn in, if any (the selected shape stays red,
    // a sleeping one gray).
    virtual std::optional<browser::Color> colourOf(const RigidShape& shape) const = 0;
    // What the game has to say on the page, a line or two for the band beyond the book.
    virtual std::string echo() const = 0;
};

// The timing half of the engine loop. Frames come when the browser is ready to draw,
// and their length varies; the world must still move in equal steps so it behaves the
// same on a fast machine and a slow one. So each frame adds the time that has passed
// to a lag, and one update is due for every whole step in the lag. What is left over
// waits for the next frame. When frames are slow several updates run per frame and
// only the last state is drawn: that is frame skipping.
class FixedStepTimer {
public:
    explicit FixedStepTimer(double start_ms, double step_ms = kMPF) : previous_ms_(start_ms), step_ms_(step_ms) {}

    // How many updates are due at time now_ms; they are taken out of the lag.
    int updatesDue(double now_ms);
    double lagMs() const { return lag_ms_; }

private:
    double previous_ms_;
    double step_ms_;
    double lag_ms_ = 0.0;
};

class Core {
public:
    // The settings' dt is both the step of the integration and the fixed step of the
    // loop, as the book derives both from one constant.
    explicit Core(browser::Window& window, const WorldSettings& settings = kBookWorld);

    double width() const;   // 800 px, the book's mWidth
    double height() const;  // 450 px, the book's mHeight

    // Takes a shape into the world (the book's shapes push themselves onto mAllObjects
    // when constructed), gives it the next id (rigid_shape.h), and returns it as it now
    // lives in the list.
    template <std::derived_from<RigidShape> Shape>
    Shape& add(Shape shape) {
        auto owned = std::make_unique<Shape>(std::move(shape));
        Shape& added = *owned;
        added.id_ = next_id_++;
        all_objects_.push_back(std::move(owned));
        return added;
    }
    std::size_t objectCount() const { return all_objects_.size(); }
    // Removes every object after the first `count` (the R key's reset).
    void keepFirstObjects(std::size_t count);
    // Removes the shape with id `id`, if it is still in the world: between two steps,
    // as the game's logic does (GameLogic). It wakes what it held up and ends every
    // pair it touched; the shapes after it move up the list. Returns whether it was there.
    bool remove(BodyId id);
    // 5.9: joins two shapes of the world with a joint (joints.h: pinAt, linkBetween make
    // one). The two wake: a joint is a change to both. A shape that leaves the world
    // takes its joints with it.
    void join(const JointDefinition& joint);
    const Joints& joints() const { return physics_.joints(); }
    RigidShape& object(std::size_t index) { return *all_objects_.at(index); }
    const RigidShape& object(std::size_t index) const { return *all_objects_.at(index); }

    // The selected object (the book's gObjectNum): drawn red, echoed in the panel, and
    // the one the keys act on.
    std::size_t selectedIndex() const { return selected_; }
    void select(std::size_t index);

    // The world's settings (the book keeps them in gEngine.Core: mGravity, mMovement,
    // mUpdateIntervalInSeconds; and in gEngine.Physics: mRelaxationCount,
    // mPosCorrectionRate, mPositionalCorrectionFlag): one value, read by the physics
    // and by every shape.
    const WorldSettings& settings() const { return settings_; }
    // A new world: gravity, a flag, a knob. Any change wakes every shape, since a
    // sleeping pile at rest under the old settings need not be at rest under the new.
    void changeSettings(const WorldSettings& settings);
    // The comma key: starts and stops every shape's motion.
    void toggleMovement() { toggleSetting(&WorldSettings::movement); }
    // The M key: turns positional correction on and off.
    void togglePositionalCorrection() { toggleSetting(&WorldSettings::positional_correction); }
    // The Y key: turns sleeping on and off.
    void toggleSleep() { toggleSetting(&WorldSettings::sleep); }
    // The P key: turns continuous collision on and off.
    void toggleContinuous() { toggleSetting(&WorldSettings::continuous); }

    // Sleeping (islands.h): the keys wake what they change. A shape's island wakes with
    // it; a static shape wakes everything.
    void wakeIslandOf(std::size_t index) { physics_.islands().wakeIslandOf(all_objects_, index); }
    void wakeAll() { physics_.islands().wakeAll(all_objects_); }
    std::size_t awakeCount() const { return Islands::awakeCount(all_objects_); }

    // One animation frame, in the book's order: the echo and the drawing of the world
    // as it stands, then every update that is due.
    void runGameLoop();
    // One fixed step of the world: the collision pass, then every awake shape's motion,
    // then, with continuous collision, the sweep of the fast shapes (continuous.h), then
    // the islands' sleep (islands.h); with
    // remove_out_of_bounds, every shape whose centre has left the canvas in this step
    // is then removed. With settings().substeps k > 1 all of that runs k times with
    // dt / k. Last, the step's collision events are told (contact_events.h). runGameLoop
    // runs it as often as the timer says; tests may run it directly.
    void update();
    // How many fixed steps have run (sub-steps not counted), and a function to call
    // after each one (the state dump of --dump listens here).
    long stepCount() const { return step_count_; }
    void onStep(std::function<void()> listener) { step_listener_ = std::move(listener); }

    const FixedStepTimer& timer() const { return timer_; }
    const Physics& physics() const { return physics_; }
    const ContinuousCollision& continuous() const { return continuous_; }

    // 5.7's collision events (contact_events.h): kept only while someone reads them (the
    // game logic, --events, the overlay). The events of the last step, read after it.
    void keepEvents(bool keep, EventReader reader = EventReader::program) { physics_.events().keep(reader, keep); }
    const ContactEvents& events() const { return physics_.events(); }
    // A key moved, turned or made static the shape at `index`: each pair it touched
    // ends (if it still touches, the next step begins it anew).
    void leaveContacts(std::size_t index);
    // The game's logic, called after every step (nullptr: none, as in the stages before).
    // It turns on the events it reads; the core does not own it.
    void setGame(GameLogic* game);

    // 5.9: the mouse (mouse_joint.h). A press at `point` grabs the shape there that
    // forces move, and wakes its island; the pointer's moves pull it there, and wake it;
    // the release lets it go. Returns whether a press grabbed something.
    bool grab(Vec2 point);
    void dragTo(Vec2 point);
    void letGo() { mouse_.release(); }
    const MouseJoint& mouse() const { return mouse_; }

private:
    void toggleSetting(bool WorldSettings::*flag);
    bool isOutOfBounds(const RigidShape& shape) const;
    void removeOutOfBounds();
    void updateUIEcho();
    void draw();

    browser::Window& window_;
    WorldSettings settings_;
    std::vector<std::unique_ptr<RigidShape>> all_objects_;  // the book's mAllObjects
    BodyId next_id_ = 1;  // the next shape's id: the counter only goes up, so no id is given twice
    std::size_t selected_ = 0;
    FixedStepTimer timer_;
    Physics physics_;  // the book's gEngine.Physics
    ContinuousCollision continuous_;
    MouseJoint mouse_;
    long step_count_ = 0;
    bool kinematic_named_ = false;  // the echo has named a kinematic body: it keeps the line
    std::function<void()> step_listener_;
    GameLogic* game_ = nullptr;
};

}  // namespace engine
