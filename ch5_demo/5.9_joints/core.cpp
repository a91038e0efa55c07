#include "core.h"

#include <algorithm>
#include <string>

#include "kinematic_drawing.h"
#include "number_format.h"
#include "overlay.h"
#include "overlay_draw.h"

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
// The shapes that can move: the panel counts how many of them are awake.
std::size_t movingCount(ShapeList shapes) {
    return static_cast<std::size_t>(
        std::count_if(shapes.begin(), shapes.end(), [](const auto& shape) { return !shape->isStatic(); }));
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

void Core::changeSettings(const WorldSettings& settings) {
    if (settings == settings_) return;
    settings_ = settings;
    wakeAll();
}

// A flag flipped is a change of the world like any other (changeSettings): it wakes
// every shape.
void Core::toggleSetting(bool WorldSettings::*flag) {
    WorldSettings changed = settings_;
    changed.*flag = !(changed.*flag);
    changeSettings(changed);
}

// The shapes removed wake whatever they held up (islands.h), and end every pair they
// touched (contact_events.h).
void Core::keepFirstObjects(std::size_t count) {
    for (std::size_t i = count; i < all_objects_.size(); ++i) {
        wakeIslandOf(i);
        leaveContacts(i);
        physics_.joints().forgetBody(all_objects_[i]->id());
    }
    if (count < all_objects_.size()) all_objects_.resize(count);
    if (selected_ >= all_objects_.size()) selected_ = 0;
}

bool Core::remove(BodyId id) {
    const auto found =
        std::find_if(all_objects_.begin(), all_objects_.end(), [id](const auto& shape) { return shape->id() == id; });
    if (found == all_objects_.end()) return false;
    const auto index = static_cast<std::size_t>(found - all_objects_.begin());
    wakeIslandOf(index);
    leaveContacts(index);
    physics_.joints().forgetBody(id);
    all_objects_.erase(found);
    // The physics' record and the sweeps name shapes by their places, which moved up.
    physics_.forgetResponses();
    continuous_.forgetSweeps();
    if (selected_ > index) --selected_;  // the same shape stays selected
    if (selected_ >= all_objects_.size()) selected_ = 0;
    return true;
}

void Core::join(const JointDefinition& joint) {
    for (std::size_t i = 0; i < all_objects_.size(); ++i) {
        const BodyId id = all_objects_[i]->id();
        if ((id == joint.body_a || id == joint.body_b) && !all_objects_[i]->isStatic()) wakeIslandOf(i);
    }
    physics_.joints().add({.definition = joint, .impulses = {}});
}

void Core::setGame(GameLogic* game) {
    if (game_) keepEvents(false, EventReader::game);
    game_ = game;
    if (game_) keepEvents(true, EventReader::game);
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
    // And the events, for the overlay's layer of them (events_overlay.h).
    keepEvents(window_.overlay, EventReader::overlay);
    for (int due = timer_.updatesDue(window_.clock.nowMs()); due > 0; --due) update();
    drawOverlay(window_, *this);
}

// One fixed step: find the collisions first, then let every shape take its step. With
// substeps k, that is done k times with dt / k: the world is the same, only the steps
// are shorter, so shapes overlap less before they are found and a fast one moves less
// between two looks. The loop's timer still counts whole steps of dt.
void Core::update() {
    physics_.events().startStep(step_count_ + 1);
    WorldSettings sub_step = settings_;
    sub_step.dt = settings_.dt / settings_.substeps;
    for (int k = 0; k < settings_.substeps; ++k) {
        // 5.9: the mouse's pull (nothing while no shape is held): before the book's passes,
        // inside the sequential impulses' iterations.
        if (sub_step.solver == SolverKind::book) mouse_.apply(all_objects_, sub_step);
        physics_.collision(all_objects_, sub_step, &mouse_);
        if (settings_.continuous) continuous_.startStep(all_objects_);
        for (const auto& shape : all_objects_) {
            if (!shape->sleep().asleep) shape->update(sub_step);
        }
        // 5.9: the joints' positional passes, once every shape has moved (joints.h).
        if (settings_.solver == SolverKind::sequential_impulse && !physics_.joints().empty()) {
            physics_.joints().correctPositions(all_objects_, sub_step);
        }
        if (settings_.continuous) {
            continuous_.sweep(all_objects_, &physics_.joints());
            for (const Crossing& crossing : continuous_.crossings()) {
                physics_.events().crossed(*all_objects_[crossing.mover], *all_objects_[crossing.sensor], crossing.point,
                                          crossing.direction);
            }
        } else {
            continuous_.forgetSweeps();  // the overlay shows no sweep from before P turned it off
        }
        physics_.islands().endStep(all_objects_, sub_step);
        if (settings_.remove_out_of_bounds) removeOutOfBounds();
    }
    // Compared once a step, not once a sub-step: a pair found in any sub-step touches in
    // this step, and kMissedSteps counts whole steps whatever the sub-steps.
    physics_.events().endStep(all_objects_, kHitSpeed);
    ++step_count_;
    // The step is over: now the game may read what happened and change the world.
    if (game_) game_->afterStep(*this);
    if (step_listener_) step_listener_();
}

bool Core::grab(Vec2 point) {
    const std::optional<std::size_t> grabbed = mouse_.grab(all_objects_, point);
    if (grabbed) wakeIslandOf(*grabbed);
    return grabbed.has_value();
}

void Core::dragTo(Vec2 point) {
    if (!mouse_.holding()) return;
    mouse_.moveTo(point);
    for (std::size_t i = 0; i < all_objects_.size(); ++i) {
        if (all_objects_[i]->id() == mouse_.body() && all_objects_[i]->sleep().asleep) wakeIslandOf(i);
    }
}

void Core::leaveContacts(std::size_t index) {
    if (index < all_objects_.size()) physics_.events().shapeLeaves(all_objects_[index]->id());
}

bool Core::isOutOfBounds(const RigidShape& shape) const {
    const Vec2 c = shape.center();
    return c.x < 0 || c.x > width() || c.y < 0 || c.y > height();
}

// The book removes a shape from inside its own update, while the core's loop walks the
// list, so the shape after it slides into its place and misses its step. Removing once
// every shape has taken its step removes the same shapes in the same step, and skips
// no one (docs/errata.md). The selection is an index, as the book's gObjectNum is; one
// past the end of the list goes back to object 0. The shapes after a removed one move
// up the list, so the physics' record of what the step did to each pair, kept by their
// places in the list, would name other shapes: it is dropped. Each shape leaving first
// wakes its island: what it held up, or lay on (islands.h).
void Core::removeOutOfBounds() {
    for (std::size_t i = 0; i < all_objects_.size(); ++i) {
        if (!isOutOfBounds(*all_objects_[i])) continue;
        wakeIslandOf(i);
        physics_.joints().forgetBody(all_objects_[i]->id());
    }
    if (std::erase_if(all_objects_, [this](const auto& shape) { return isOutOfBounds(*shape); }) > 0) {
        physics_.forgetResponses();
        continuous_.forgetSweeps();
    }
    if (selected_ >= all_objects_.size()) selected_ = 0;
}

// The echo panel holds about 24 lines of 37 letters (common/page.cpp), so the key help
// is kept short. The book's lines fill it: the settings beyond the book, with their
// keys, get a section of their own, on a band under the page (Document::beyond_echo).
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
    std::string beyond = "Beyond the book:\n";
    beyond.append("  Sleeping: ").append(echoFlag(settings_.sleep)).append(", awake ");
    beyond.append(std::to_string(awakeCount()))
        .append("/")
        .append(std::to_string(movingCount(all_objects_)))
        .append("\n");
    beyond.append("  Continuous: ").append(echoFlag(settings_.continuous)).append("\n");
    // 5.9: the kinematic bodies, named with their colour, once the world has had one
    // (and from then on, so that the page keeps its height when a reset removes them).
    const auto kinematic = static_cast<std::size_t>(std::count_if(
        all_objects_.begin(), all_objects_.end(), [](const auto& shape) { return shape->isKinematic(); }));
    kinematic_named_ = kinematic_named_ || kinematic > 0;
    if (kinematic_named_)
        beyond.append("  Kinematic (purple): ")
            .append(std::to_string(kinematic))
            .append(", arrows ")
            .append(browser::overlay::fixed(kKinematicMotionShown, 0))
            .append(" s\n");
    beyond +=
        "  Y: Sleeping [On/Off]\n"
        "  P: Continuous [On/Off]\n";
    if (game_) beyond.append(game_->echo());
    window_.document.beyond_echo = beyond;
}

void Core::draw() {
    browser::Canvas& context = window_.document.canvas;
    context.clear();
    // A sleeping shape is drawn gray: a reader sees at a glance what the step leaves out.
    // A sensor is green: it is there, but nothing rests on it. A kinematic body (5.9) is
    // purple, with arrows for how it moves (kinematic_drawing.h). The game may paint the rest.
    for (std::size_t i = 0; i < all_objects_.size(); ++i) {
        const RigidShape& shape = *all_objects_[i];
        const std::optional<browser::Color> painted = game_ ? game_->colourOf(shape) : std::nullopt;
        context.setStrokeStyle(i == selected_         ? browser::colors::kRed
                               : shape.sleep().asleep ? browser::colors::kGray
                               : shape.isSensor()     ? browser::colors::kGreen
                               : shape.isKinematic()  ? kKinematicColor
                               : painted              ? *painted
                                                      : browser::colors::kBlue);
        shape.draw(context);
        if (shape.isKinematic()) drawKinematicMotion(context, shape);
    }
    mouse_.draw(context, all_objects_);  // 5.9: the pull, while a shape is held
}

}  // namespace engine
