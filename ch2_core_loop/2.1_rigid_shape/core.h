#pragma once
// The engine core (the book's EngineCore/Core.js): the list of every rigid shape in the
// world, the selected one, and the loop that shows them each animation frame. The book
// keeps all this in a global, gEngine.Core; here it is one object that the page
// creates and passes to whoever needs it.

#include <concepts>
#include <cstddef>
#include <memory>
#include <utility>
#include <vector>

#include "browser.h"
#include "rigid_shape.h"

namespace engine {

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
    RigidShape& object(std::size_t index) { return *all_objects_.at(index); }
    const RigidShape& object(std::size_t index) const { return *all_objects_.at(index); }

    // The selected object (the book's gObjectNum): drawn red, echoed in the panel, and
    // the one the keys act on.
    std::size_t selectedIndex() const { return selected_; }
    void select(std::size_t index);

    // One animation frame: echo the selected object's state, then draw every shape.
    void runGameLoop();

private:
    void updateUIEcho();
    void draw();

    browser::Window& window_;
    std::vector<std::unique_ptr<RigidShape>> all_objects_;  // the book's mAllObjects
    std::size_t selected_ = 0;
};

}  // namespace engine
