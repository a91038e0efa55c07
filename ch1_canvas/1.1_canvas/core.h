#pragma once
// The engine core of chapter 1 (the book's EngineCore/Core.js): the one place that
// knows the drawing surface. The book keeps it in a global, gEngine.Core; here it is
// an object that the page creates and hands to whoever needs to draw.

#include "canvas.h"

namespace engine {

class Core {
public:
    explicit Core(browser::Canvas& context);

    double width() const;   // 800 px, the book's mWidth
    double height() const;  // 450 px, the book's mHeight
    browser::Canvas& context() { return context_; }

private:
    browser::Canvas& context_;  // the canvas's 2D drawing context, the book's mContext
};

}  // namespace engine
