// The echo panel (every stage from 4.1 on): the selected object's motion and
// attributes, the flags and the keys, within what the page's text panel shows:
// about 24 lines of at most 37 letters (common/page.cpp).
#include <catch2/catch.hpp>

#include <source_location>
#include <sstream>
#include <string>

#include "book_scene.h"
#include "checked_at.h"
#include "circle.h"
#include "expect.h"
#include "my_game.h"
#include "rectangle.h"
#include "stage_fixture.h"

namespace ui_echo_test {

using browser::Key;

namespace {

constexpr std::size_t kPanelLines = 24;
constexpr std::size_t kPanelLetters = 37;

// Checks that the echo has the line `line`, reported at the test's line with what the
// echo holds instead.
void shows(const std::string& echo, const std::string& line,
           std::source_location where = std::source_location::current()) {
    const bool found = echo.find(line) != std::string::npos;
    std::string text = "the echo's line \"" + line.substr(0, line.size() - 1) + "\": ";
    text += found ? "found" : "not found in the echo:\n" + echo;
    test::checkedAt(where, "a line of the echo panel, as the book's updateUIEcho prints it", found, text);
}

}  // namespace

TEST_CASE("ui echo: the selected object's velocities, mass, friction and restitution, and the flags") {
    test::StageFixture page;
    page.core.add(
        engine::Rectangle({100, 100}, 20, 20, {.mass = 0}));  // a static shape first, so the ball is not object 0
    const std::size_t id = page.core.objectCount();
    const engine::PhysicalAttributes attributes{.mass = 2.5, .friction = 0.25, .restitution = 0.75};
    engine::Circle& ball = page.core.add(engine::Circle({700, 430}, 10, attributes));
    ball.setVelocity({12.5, -3});
    ball.setAngularVelocity(0.25);
    page.core.select(id);
    if (page.core.settings().movement) page.core.toggleMovement();  // so the frame shows these numbers
    page.frame();
    const std::string& echo = page.window.document.ui_echo;
    shows(echo, "Id: " + std::to_string(id) + "\n");
    shows(echo, "Center: 700,430\n");
    shows(echo, "Velocity: 12.5,-3.00\n");
    shows(echo, "Angular Velocity: 0.250\n");
    shows(echo, "Mass: 2.5\n");  // 1 / 0.400
    shows(echo, "Friction: 0.250\n");
    shows(echo, "Restitution: 0.750\n");
    shows(echo, "Movement: false\n");
    page.press(Key::Comma);
    page.press(Key::Digit0);  // the cursor: static
    page.frame();
    shows(page.window.document.ui_echo, "Movement: true\n");
    shows(page.window.document.ui_echo, "Mass: Infinity\n");  // 1 / 0.00
}

TEST_CASE("ui echo: the mass is 1 over the inverse mass rounded to 3 digits, as the book prints it") {
    // The book's `1 / invMass.toPrecision(3)` divides 1 by the rounded text, and prints
    // the quotient with JavaScript's default digits (docs/errata.md).
    test::StageFixture page;
    page.core.add(engine::Rectangle({100, 100}, 20, 20, {.mass = 0}));
    const struct {
        double mass;
        const char* shown;
    } cases[] = {
        {7, "6.993006993006993"},    // 1 / 0.143
        {5, "5"},                    // 1 / 0.200
        {3, "3.003003003003003"},    // 1 / 0.333
        {30, "30.030030030030026"},  // 1 / 0.0333
        {0.5, "0.5"},                // 1 / 2.00
    };
    for (const auto& example : cases) {
        page.core.add(engine::Circle({300, 300}, 10, {.mass = example.mass}));
        page.core.select(page.core.objectCount() - 1);
        page.frame();
        shows(page.window.document.ui_echo, std::string("Mass: ") + example.shown + "\n");
    }
}

TEST_CASE("ui echo: the book's lines, each whole and in the book's order, after a blank line") {
    // The key help every stage from 4.1 shows; a stage beyond the book puts its own
    // settings and keys in a section of their own (Document::beyond_echo), never
    // folded into the book's lines.
    test::StageFixture page;
    page.frame();
    const std::string& echo = page.window.document.ui_echo;
    std::size_t from = echo.find("\n\nControl: of selected object\n");
    REQUIRE(from != std::string::npos);
    for (const char* line :
         {"  Num or Up/Down Arrow: Select Object\n", "  WASD + QE: Position [Move + Rotate]\n",
          "  IJKL + UO: Velocity [lin + ang]\n", "  ZX: Mass [Decrease/Increase]\n",
          "  CV: Friction [Decrease/Increase]\n", "  BN: Restitution [Decrease/Increase]\n", "  ,: Movement [On/Off]\n",
          "  H: Excite all objects\n", "  F/G: New [Rect/Circle] at selected\n", "  R: Reset System\n"}) {
        const std::size_t at = echo.find(line, from);
        INFO(line << "in\n" << echo);
        CHECK(at != std::string::npos);
        if (at != std::string::npos) from = at;
    }
}

TEST_CASE("ui echo: fits the panel, even with the longest numbers") {
    test::StageFixture page;
    test::buildBookScene(page.core, page.random);
    engine::Circle& ball = page.core.add(engine::Circle({-1234.5, -6789.25}, 10, {.mass = 0.001234}));
    ball.setVelocity({-12345.6, -0.00123456});
    ball.setAngularVelocity(-98765.4);
    ball.rotate(-1234.5);
    page.core.select(page.core.objectCount() - 1);
    page.frame();
    std::istringstream echo(page.window.document.ui_echo);
    std::size_t lines = 0;
    for (std::string line; std::getline(echo, line); ++lines) {
        INFO("line " << lines << ": \"" << line << "\"");
        test::expectAtMost("letters of an echo line: at most 37, what the page's panel shows", kPanelLetters,
                           line.size());
    }
    test::expectAtMost("lines of the echo: at most 24, what the page's panel shows", kPanelLines, lines);
    // A stage's own section (beyond the book, under the page) is as narrow.
    std::istringstream beyond(page.window.document.beyond_echo);
    for (std::string line; std::getline(beyond, line);) {
        INFO("beyond the book: \"" << line << "\"");
        test::expectAtMost("letters of a line beyond the book: at most 37, as the panel's", kPanelLetters, line.size());
    }
}

}  // namespace ui_echo_test
