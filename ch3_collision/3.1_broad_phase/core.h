#pragma once
// The engine core (the book's EngineCore/Core.js): the list of every rigid shape in the
// world, the selected one, and the engine loop that updates and shows them. The book
// keeps all this in a global, gEngine.Core; here it is one object that the page
// creates and passes to whoever needs it.

#include <concepts>
#include <cstddef>
#include <memory>
#include <utility>
#include <vector>

#include "browser.h"
#include "physics.h"
#include "rigid_shape.h"

namespace engine {

// The world advances in fixed steps of 1/60 s, whatever the frame rate.
inline constexpr double kFPS = 60.0;
inline constexpr double kFrameTime = 1.0 / kFPS;  // seconds per update
inline constexpr double kMPF = 1000.0 / kFPS;     // milliseconds per update

// The timing half of the engine loop. Frames come when the browser is ready to draw,
// and their length varies; the world must still move in equal steps so it behaves the
// same on a fast machine and a slow one. So each frame adds the time that has passed
// to a lag, and one update is due for every whole step in the lag. What is left over
// waits for the next frame. When frames are slow several updates run per frame and
// only the last state is drawn: that is frame skipping.
class FixedStepTimer {
public:
    explicit FixedStepTimer(double start_ms) : previous_ms_(start_ms) {}

    // How many updates are due at time now_ms; they are taken out of the lag.
    int updatesDue(double now_ms);
    double lagMs() const { return lag_ms_; }

private:
    double previous_ms_;
    double lag_ms_ = 0.0;
};

class Core {
public:
    explicit Core(browser::Window& window);

    double width() const;   // 800 px, the book's mWidth
    double height() const;  // 450 px, the book's mHeight

    // Takes a shape into the world (the book's shapes push themselves onto mAllObjects
    // when constructed) and returns it as it now lives in the list.
    template <std::derived_from<RigidShape> Shape>
    Shape& add(Shape shape) {
        auto owned = std::make_unique<Shape>(std::move(shape));
        Shape& added = *owned;
        all_objects_.push_back(std::move(owned));
        return added;
    }
    std::size_t objectCount() const { return all_objects_.size(); }
    // Removes every object after the first `count` (the R key's reset).
    void keepFirstObjects(std::size_t count);
    RigidShape& object(std::size_t index) { return *all_objects_.at(index); }
    const RigidShape& object(std::size_t index) const { return *all_objects_.at(index); }

    // The selected object (the book's gObjectNum): drawn red, echoed in the panel, and
    // the one the keys act on.
    std::size_t selectedIndex() const { return selected_; }
    void select(std::size_t index);

    // One animation frame, in the book's order: the echo and the drawing of the world
    // as it stands, then every update that is due, then what the last collision pass
    // found.
    void runGameLoop();
    const FixedStepTimer& timer() const { return timer_; }
    const Physics& physics() const { return physics_; }

private:
    void update();
    void updateUIEcho();
    void draw();

    browser::Window& window_;
    std::vector<std::unique_ptr<RigidShape>> all_objects_;  // the book's mAllObjects
    std::size_t selected_ = 0;
    FixedStepTimer timer_;
    Physics physics_;  // the book's gEngine.Physics
};

}  // namespace engine
