#pragma once
// The user control script (UserControl.js): what a key press does. In chapter 1 it
// tests the canvas: F strokes a rectangle outline, G a circle outline, each at a
// random place with a random size. Nothing is remembered, so the shapes pile up on
// the canvas exactly as they do in the browser, where nothing clears it.

#include "core.h"
#include "keys.h"
#include "random.h"

namespace engine {

class UserControl {
public:
    UserControl(Core& core, browser::Random& random) : core_(core), random_(random) {}
    void onKeyDown(browser::Key key);

private:
    void drawRandomRectangle();
    void drawRandomCircle();

    Core& core_;
    browser::Random& random_;  // stands in for Math.random()
};

}  // namespace engine
