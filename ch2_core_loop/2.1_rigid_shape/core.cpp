#include "core.h"

#include <string>

#include "number_format.h"

namespace engine {

Core::Core(browser::Window& window) : window_(window) {}

double Core::width() const { return window_.document.canvas.width(); }
double Core::height() const { return window_.document.canvas.height(); }

void Core::select(std::size_t index) {
    if (index < all_objects_.size()) selected_ = index;
}

void Core::runGameLoop() {
    updateUIEcho();
    draw();
}

void Core::updateUIEcho() {
    using browser::to_precision;
    std::string echo = "Selected Object:\n";
    if (selected_ < all_objects_.size()) {
        const RigidShape& shape = *all_objects_[selected_];
        echo += "  Id: " + std::to_string(selected_) + "\n";
        echo += "  Center: " + to_precision(shape.center().x, 3) + "," + to_precision(shape.center().y, 3) + "\n";
    } else {
        echo += "  Id: none\n";
    }
    echo +=
        "\n"
        "Control: of selected object\n"
        "  Num or Up/Down Arrow: Select Object\n"
        "  F/G: Spawn [Rectangle/Circle] at random location\n";
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
