#include "core.h"

#include <string>

#include "number_format.h"
#include "overlay.h"

namespace engine {

namespace {
constexpr double kMsPerSecond = 1000.0;

// The book's echo prints numbers with toPrecision(3).
constexpr int kEchoDigits = 3;
std::string echoNumber(double value) { return browser::to_precision(value, kEchoDigits); }
std::string echoVector(Vec2 v) {
    std::string text = echoNumber(v.x);
    return text.append(",").append(echoNumber(v.y));
}
// JavaScript prints a flag as true or false.
std::string echoFlag(bool on) { return on ? "true" : "false"; }
// The book prints `1 / invMass.toPrecision(3)`. toPrecision binds first and gives back
// text, which the division reads as a number again: so the echo shows 1 over the
// inverse mass *rounded to 3 digits*, printed with all the digits JavaScript prints by
// default. Mass 7 shows as 1 / 0.143 = 6.993006993006993, mass 5 as 5, and a static
// shape as 1 / 0 = Infinity (docs/errata.md).
std::string echoMass(const RigidShape& shape) {
    const double shown_inverse_mass = std::stod(echoNumber(shape.invMass()));
    return browser::to_js_string(1.0 / shown_inverse_mass);
}
}  // namespace

// As in the book, the lag is compared with the step exactly. 1000/60 ms has no exact
// binary form: the step is a hair above 50/3, so three of them add up to a hair more
// than 50 ms, and a 50 ms frame runs two updates and carries almost a whole step.
int FixedStepTimer::updatesDue(double now_ms) {
    lag_ms_ += now_ms - previous_ms_;
    previous_ms_ = now_ms;
    int updates = 0;
    while (lag_ms_ >= step_ms_) {
        lag_ms_ -= step_ms_;
        ++updates;
    }
    return updates;
}

Core::Core(browser::Window& window, const WorldSettings& settings)
    : window_(window), settings_(settings), timer_(window.clock.nowMs(), settings.dt * kMsPerSecond) {}

double Core::width() const { return window_.document.canvas.width(); }
double Core::height() const { return window_.document.canvas.height(); }

void Core::select(std::size_t index) {
    if (index < all_objects_.size()) selected_ = index;
}

void Core::keepFirstObjects(std::size_t count) {
    if (count < all_objects_.size()) all_objects_.resize(count);
    if (selected_ >= all_objects_.size()) selected_ = 0;
}

// The book's order (3.1 on): the frame shows the world as it stands, then runs the
// updates that are due, so each picture shows the state from before that frame's
// updates. From 4.3 on the book's pass no longer draws the collisions it finds. Last,
// over everything, the overlay: it shows the world after the updates, a step (or a
// frame's steps) ahead of the shapes drawn, a pixel or two at the book's speeds.
void Core::runGameLoop() {
    updateUIEcho();
    draw();
    // What the steps do to each pair is recorded only for the overlay to draw (physics.h).
    physics_.keepResponses(window_.overlay);
    for (int due = timer_.updatesDue(window_.clock.nowMs()); due > 0; --due) update();
    drawOverlay(window_, *this);
}

// One fixed step: find the collisions first, then let every shape take its step.
void Core::update() {
    physics_.collision(all_objects_, settings_);
    for (const auto& shape : all_objects_) shape->update(settings_);
    ++step_count_;
    if (step_listener_) step_listener_();
}

// The echo panel holds about 24 lines of 37 letters (common/page.cpp), so the key help
// is kept short.
void Core::updateUIEcho() {
    std::string echo = "Selected Object:\n";
    if (selected_ < all_objects_.size()) {
        const RigidShape& shape = *all_objects_[selected_];
        echo.append("  Id: ").append(std::to_string(selected_)).append("\n");
        echo.append("  Center: ").append(echoVector(shape.center())).append("\n");
        echo.append("  Angle: ").append(echoNumber(shape.angle())).append("\n");
        echo.append("  Velocity: ").append(echoVector(shape.velocity())).append("\n");
        echo.append("  Angular Velocity: ").append(echoNumber(shape.angularVelocity())).append("\n");
        echo.append("  Mass: ").append(echoMass(shape)).append("\n");
        echo.append("  Friction: ").append(echoNumber(shape.friction())).append("\n");
        echo.append("  Restitution: ").append(echoNumber(shape.restitution())).append("\n");
    } else {
        echo += "  Id: none\n";
    }
    echo.append("  Positional Correction: ").append(echoFlag(settings_.positional_correction)).append("\n");
    echo.append("  Movement: ").append(echoFlag(settings_.movement)).append("\n");
    echo +=
        "\n"
        "Control: of selected object\n"
        "  Num or Up/Down Arrow: Select Object\n"
        "  WASD + QE: Position [Move + Rotate]\n"
        "  IJKL + UO: Velocity [lin + ang]\n"
        "  ZX: Mass [Decrease/Increase]\n"
        "  CV: Friction [Decrease/Increase]\n"
        "  BN: Restitution [Decrease/Increase]\n"
        "  M: Positional Correction [On/Off]\n"
        "  ,: Movement [On/Off]\n"
        "  H: Excite all objects\n"
        "  F/G: New [Rect/Circle] at selected\n"
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
