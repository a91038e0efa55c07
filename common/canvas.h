#pragma once
// The HTML5 canvas 2D context, as far as the book uses it: a current path made of
// moveTo / lineTo / arc, stroked with a 1 px anti-aliased line in the current
// strokeStyle; strokeRect; clearRect; and a transform stack (save, restore,
// translate, rotate) that applies to every point of a path when it is added.
// Beyond the book, for the overlays that label what the engine computed: fillText and
// fillRect in the current fillStyle.
//
// Coordinates are the canvas's: origin at the top-left corner, +x right, +y down,
// one unit a pixel, pixel (i, j) covering [i, i+1) x [j, j+1) so its centre is at
// (i + 0.5, j + 0.5). Anything outside the canvas is clipped, never an error.
//
// A canvas may have more device pixels than canvas pixels, as a browser's canvas on a
// high-density screen does: with scale K each canvas unit covers K x K device pixels,
// the pen is K device pixels wide and arcs get as many chords as their size on the
// device needs. Drawing is then the same drawing at K times the detail, not a
// magnified copy: a circle stays round where a copy would show its steps K times as
// large. At scale 1 every computation is the one without a scale (a product with 1.0
// is exact), so pictures do not change by a bit.

#include <string_view>
#include <vector>

#include "image.h"

namespace browser {

class Canvas {
public:
    static constexpr int kDefaultWidth = 800;   // the book's mWidth
    static constexpr int kDefaultHeight = 450;  // the book's mHeight

    static constexpr int kMaxScale = 4;  // a page 4 times larger is 4720 x 1800 pixels already

    explicit Canvas(int width = kDefaultWidth, int height = kDefaultHeight, int scale = 1);

    // The size in canvas pixels, what the page's scripts draw in.
    int width() const { return width_; }
    int height() const { return height_; }
    int scale() const { return scale_; }
    // The device pixels: width() * scale() by height() * scale().
    const Image& pixels() const { return pixels_; }
    // A blank canvas of the same size with `scale` (1 to kMaxScale) device pixels a unit.
    void setScale(int scale);

    // Erases to the page background (white, like a canvas on a blank page).
    void clearRect(double x, double y, double w, double h);
    void clear() { clearRect(0, 0, width(), height()); }

    void setStrokeStyle(Color c) { stroke_color_ = c; }
    Color strokeStyle() const { return stroke_color_; }
    void setFillStyle(Color c) { fill_color_ = c; }
    Color fillStyle() const { return fill_color_; }

    // Path building. Points pass through the current transform when added.
    void beginPath();
    void moveTo(double x, double y);
    void lineTo(double x, double y);
    // Circular arc of radius r around (cx, cy) from angle a0 to a1 (radians, +y down so
    // growing angles turn clockwise on screen); joins the current point with a line
    // first, as the canvas does. counterclockwise picks the direction of travel.
    void arc(double cx, double cy, double r, double a0, double a1, bool counterclockwise = false);
    void closePath();
    void stroke();  // draws the current path; the path stays until beginPath()

    // Outline of the axis-aligned rectangle (x, y, w, h) in current coordinates.
    void strokeRect(double x, double y, double w, double h);
    // The axis-aligned rectangle (x, y, w, h), filled. Its corners pass through the
    // current transform's translation only (an overlay's boxes stay upright).
    void fillRect(double x, double y, double w, double h);
    // One line of text in the page's font (text.h's draw_text: letters about 14 units
    // tall), its top-left corner at (x, y) after the current transform's translation.
    void fillText(std::string_view text, double x, double y);

    void save();     // pushes the transform and the stroke and fill styles
    void restore();  // pops them again; does nothing when nothing was saved
    void translate(double dx, double dy);
    void rotate(double radians);

private:
    struct Point {
        double x, y;
    };
    struct Transform {  // x' = a x + c y + e ; y' = b x + d y + f  (canvas's setTransform order)
        double a = 1, b = 0, c = 0, d = 1, e = 0, f = 0;
    };
    struct State {  // what save() keeps: the transform and, as in the browser, the style
        Transform transform;
        Color stroke_color;
        Color fill_color;
    };
    Point apply(double x, double y) const;  // canvas coordinates to device pixels

    int width_, height_, scale_;
    Image pixels_;
    Color stroke_color_ = colors::kBlack;
    Color fill_color_ = colors::kBlack;
    Transform transform_;
    std::vector<State> saved_;
    std::vector<std::vector<Point>> subpaths_;
    std::vector<bool> closed_;
};

}  // namespace browser
