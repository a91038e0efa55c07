#include "core.h"

#include <string>

#include "number_format.h"

namespace engine {

// As in the book, the lag is compared with the step exactly. 1000/60 ms has no exact
// binary form: the step is a hair above 50/3, so three of them add up to a hair more
// than 50 ms, and a 50 ms frame runs two updates and carries almost a whole step.
int FixedStepTimer::updatesDue(double now_ms) {
    lag_ms_ += now_ms - previous_ms_;
    previous_ms_ = now_ms;
    int updates = 0;
    while (lag_ms_ >= kMPF) {
        lag_ms_ -= kMPF;
        ++updates;
    }
    return updates;
}

Core::Core(browser::Window& window) : window_(window), timer_(window.clock.nowMs()) {}

double Core::width() const { return window_.document.canvas.width(); }
double Core::height() const { return window_.document.canvas.height(); }

void Core::select(std::size_t index) {
    if (index < all_objects_.size()) selected_ = index;
}

void Core::keepFirstObjects(std::size_t count) {
    if (count < all_objects_.size()) all_objects_.resize(count);
    if (selected_ >= all_objects_.size()) selected_ = 0;
}

void Core::runGameLoop() {
    for (int due = timer_.updatesDue(window_.clock.nowMs()); due > 0; --due) update();
    updateUIEcho();
    draw();
}

void Core::update() {
    for (const auto& shape : all_objects_) shape->update(height());
}

void Core::updateUIEcho() {
    using browser::to_precision;
    std::string echo = "Selected Object:\n";
    if (selected_ < all_objects_.size()) {
        const RigidShape& shape = *all_objects_[selected_];
        echo += "  Id: " + std::to_string(selected_) + "\n";
        echo += "  Center: " + to_precision(shape.center().x, 3) + "," + to_precision(shape.center().y, 3) + "\n";
        echo += "  Angle: " + to_precision(shape.angle(), 3) + "\n";
    } else {
        echo += "  Id: none\n";
    }
    echo +=
        "\n"
        "Control: of selected object\n"
        "  Num or Up/Down Arrow: Select Object\n"
        "  WASD + QE: Position [Move + Rotate]\n"
        "  F/G: Spawn [Rectangle/Circle] at selected object\n"
        "  H: Fix object\n"
        "  R: Reset System\n";
    window_.document.ui_echo = echo;
}

void Core::draw() {
    browser::Canvas& context = window_.document.canvas;
    context.clear();
    for (std::size_t i = 0; i < all_objects_.size(); ++i) {
        context.setStrokeStyle(i == selected_ ? browser::colors::kRed : browser::colors::kBlue);
        all_objects_[i]->draw(context);
    }
}

}  // namespace engine
