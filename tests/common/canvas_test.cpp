// The canvas: where a 1 px anti-aliased stroke puts its ink. Every expected position is
// worked out here from the geometry (pixel (i, j) has its centre at (i + 0.5, j + 0.5)),
// never read back from the rasterizer.

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "canvas.h"
#include "contact_sheet.h"
#include "near.h"
#include "page.h"
#include "text.h"

using browser::Canvas;
using browser::Color;

namespace {

constexpr double kPi = std::numbers::pi;
constexpr int kWhite = 255;

// With a black pen on white, the red channel alone tells how much ink a pixel got:
// 255 untouched, 0 fully covered.
int grey(const Canvas& canvas, int i, int j) { return canvas.pixels().at(i, j).r; }

int grey_at_point(const Canvas& canvas, double x, double y) {
    return grey(canvas, static_cast<int>(std::floor(x)), static_cast<int>(std::floor(y)));
}

// Darkest pixel of the 3 x 3 block around the pixel holding (x, y), within the canvas.
int darkest_near(const Canvas& canvas, double x, double y) {
    const int i = static_cast<int>(std::floor(x)), j = static_cast<int>(std::floor(y));
    int darkest = kWhite;
    for (int dj = -1; dj <= 1; ++dj) {
        for (int di = -1; di <= 1; ++di) {
            if (canvas.pixels().contains(i + di, j + dj)) darkest = std::min(darkest, grey(canvas, i + di, j + dj));
        }
    }
    return darkest;
}

// Total ink of the picture in "fully covered pixels".
double ink(const Canvas& canvas) {
    double sum = 0;
    for (int j = 0; j < canvas.height(); ++j) {
        for (int i = 0; i < canvas.width(); ++i) sum += (kWhite - grey(canvas, i, j)) / 255.0;
    }
    return sum;
}

int largest_difference(const Canvas& a, const Canvas& b) {
    int largest = 0;
    for (std::size_t k = 0; k < a.pixels().rgba.size(); ++k) {
        largest = std::max(largest, std::abs(a.pixels().rgba[k] - b.pixels().rgba[k]));
    }
    return largest;
}

bool all_white(const Canvas& canvas) {
    return std::all_of(canvas.pixels().rgba.begin(), canvas.pixels().rgba.end(),
                       [](std::uint8_t v) { return v == kWhite; });
}

// Distance from the point (x, y) to the segment from a to b.
double distance_to_segment(double x, double y, double ax, double ay, double bx, double by) {
    const double dx = bx - ax, dy = by - ay;
    const double t = std::clamp(((x - ax) * dx + (y - ay) * dy) / (dx * dx + dy * dy), 0.0, 1.0);
    return std::hypot(x - ax - t * dx, y - ay - t * dy);
}

// How the ink of a 1 px line relates to the distance d of a pixel centre from the line:
// a centre on the line is (nearly) black, one within half a pixel at least half grey,
// any pixel it touches at all lies within one pixel of the line.
constexpr int kGreyWithinHalfPixel = 140;  // 255 * (1 - 0.5), plus rounding and chord error
constexpr int kGreyOfNearestPixel = 185;   // the pixel holding a line point: centre within 0.71 px
constexpr double kReach = 1.1;             // farther than this from the line: white

}  // namespace

TEST_CASE("canvas: a circle outline lights the whole circle and nothing else") {
    struct Case {
        double cx, cy, r;
    };
    for (const Case c : {Case{100.3, 80.7, 20.0}, Case{400.6, 220.2, 100.0}}) {
        CAPTURE(c.cx, c.cy, c.r);
        Canvas canvas;
        canvas.beginPath();
        canvas.arc(c.cx, c.cy, c.r, 0.0, 2.0 * kPi, true);  // as the book draws a circle
        canvas.closePath();
        canvas.stroke();

        for (int degree = 0; degree < 360; ++degree) {
            const double a = degree * kPi / 180.0;
            const double x = c.cx + c.r * std::cos(a), y = c.cy + c.r * std::sin(a);
            CAPTURE(degree, x, y);
            CHECK(grey_at_point(canvas, x, y) <= kGreyOfNearestPixel);
            CHECK(darkest_near(canvas, x, y) <= kGreyWithinHalfPixel);
        }
        int wrong = 0;
        for (int j = 0; j < canvas.height(); ++j) {
            for (int i = 0; i < canvas.width(); ++i) {
                const double off_circle = std::abs(std::hypot(i + 0.5 - c.cx, j + 0.5 - c.cy) - c.r);
                if (off_circle > kReach && grey(canvas, i, j) != kWhite) ++wrong;  // centre, far outside
                if (off_circle < 0.4 && grey(canvas, i, j) > kGreyWithinHalfPixel) ++wrong;
            }
        }
        CHECK(wrong == 0);
        // A 1 px pen lays down one pixel's worth of ink per pixel of length.
        CHECK(ink(canvas) == Approx(2.0 * kPi * c.r).epsilon(0.03));
    }
}

TEST_CASE("canvas: a rotated rectangle outline lights its four edges, not its inside") {
    // The book draws a rectangle by moving the origin to its first vertex and turning
    // the axes by the rectangle's angle, then stroking (0, 0, width, height).
    const double vx = 300.3, vy = 150.6, w = 120.0, h = 70.0, angle = 0.4;
    Canvas canvas;
    canvas.save();
    canvas.translate(vx, vy);
    canvas.rotate(angle);
    canvas.strokeRect(0, 0, w, h);
    canvas.restore();

    // Corners by hand: the width runs along (cos, sin), the height along (-sin, cos).
    const double ux = std::cos(angle), uy = std::sin(angle);
    const double corner_x[4] = {vx, vx + w * ux, vx + w * ux - h * uy, vx - h * uy};
    const double corner_y[4] = {vy, vy + w * uy, vy + w * uy + h * ux, vy + h * ux};
    for (int edge = 0; edge < 4; ++edge) {
        const int next = (edge + 1) % 4;
        for (int k = 1; k < 40; ++k) {
            const double s = k / 40.0;
            const double x = corner_x[edge] + s * (corner_x[next] - corner_x[edge]);
            const double y = corner_y[edge] + s * (corner_y[next] - corner_y[edge]);
            CAPTURE(edge, s, x, y);
            CHECK(grey_at_point(canvas, x, y) <= kGreyOfNearestPixel);
            CHECK(darkest_near(canvas, x, y) <= kGreyWithinHalfPixel);
        }
    }
    int wrong = 0;
    for (int j = 0; j < canvas.height(); ++j) {
        for (int i = 0; i < canvas.width(); ++i) {
            double nearest_edge = std::numeric_limits<double>::infinity();
            for (int edge = 0; edge < 4; ++edge) {
                const int next = (edge + 1) % 4;
                nearest_edge =
                    std::min(nearest_edge, distance_to_segment(i + 0.5, j + 0.5, corner_x[edge], corner_y[edge],
                                                               corner_x[next], corner_y[next]));
            }
            if (nearest_edge > kReach && grey(canvas, i, j) != kWhite) ++wrong;  // inside and outside
        }
    }
    CHECK(wrong == 0);
    // The rectangle's middle, in its own axes (w/2, h/2), is white.
    CHECK(grey_at_point(canvas, vx + w / 2 * ux - h / 2 * uy, vy + w / 2 * uy + h / 2 * ux) == kWhite);
}

TEST_CASE("canvas: strokeRect under translate and rotate equals the path through its corners") {
    const double vx = 200.5, vy = 100.25, w = 80.0, h = 40.0, angle = 0.3;
    Canvas by_rect;
    by_rect.translate(vx, vy);
    by_rect.rotate(angle);
    by_rect.strokeRect(0, 0, w, h);

    const double ux = std::cos(angle), uy = std::sin(angle);
    Canvas by_path;
    by_path.beginPath();
    by_path.moveTo(vx, vy);
    by_path.lineTo(vx + w * ux, vy + w * uy);
    by_path.lineTo(vx + w * ux - h * uy, vy + w * uy + h * ux);
    by_path.lineTo(vx - h * uy, vy + h * ux);
    by_path.closePath();
    by_path.stroke();

    CHECK(largest_difference(by_rect, by_path) <= 1);  // the same up to rounding
    CHECK(ink(by_rect) == Approx(2 * (w + h)).epsilon(0.03));
}

TEST_CASE("canvas: closePath joins back to the start, and drawing goes on from there") {
    Canvas canvas(200, 100);
    canvas.beginPath();
    canvas.moveTo(20.5, 20.5);
    canvas.lineTo(100.5, 20.5);
    canvas.lineTo(100.5, 60.5);
    canvas.closePath();         // the slanted side back to (20.5, 20.5)
    canvas.lineTo(20.5, 80.5);  // starts at (20.5, 20.5), not at (100.5, 60.5)
    canvas.stroke();
    CHECK(grey(canvas, 60, 40) == 0);       // the middle of the closing side
    CHECK(grey(canvas, 20, 50) == 0);       // on the line from the start downwards
    CHECK(grey(canvas, 60, 70) == kWhite);  // a line from (100.5, 60.5) would pass here
}

TEST_CASE("canvas: strokeRect leaves the current path alone") {
    Canvas canvas;
    canvas.beginPath();
    canvas.moveTo(10.5, 100.5);
    canvas.lineTo(300.5, 100.5);
    canvas.strokeRect(50.5, 20.5, 30, 30);
    CHECK(grey(canvas, 60, 20) == 0);         // the rectangle's top edge
    CHECK(grey(canvas, 200, 100) == kWhite);  // the path is not stroked yet...
    canvas.stroke();
    CHECK(grey(canvas, 200, 100) == 0);  // ...and still there afterwards
}

TEST_CASE("canvas: a translate after a rotate moves along the turned axes") {
    // Each call multiplies the current matrix on the right, so a point is first moved by
    // (20.5, -150.5), then turned by +90 degrees: (x, y) -> (-y, x) with +y down.
    Canvas canvas(200, 100);
    canvas.rotate(kPi / 2);
    canvas.translate(20.5, -150.5);
    canvas.beginPath();
    canvas.moveTo(0, 0);   // -> (150.5, 20.5)
    canvas.lineTo(40, 0);  // -> (150.5, 60.5)
    canvas.stroke();
    CHECK(grey(canvas, 150, 40) == 0);
    CHECK_THAT(ink(canvas), test::near(41.0, 1.5));  // anti-aliased ends: up to a pixel and a half
}

TEST_CASE("canvas: save and restore bring back the transform and the stroke style") {
    Canvas plain;
    plain.strokeRect(10.5, 10.5, 30, 20);

    Canvas restored;
    restored.save();
    restored.translate(50, 20);
    restored.rotate(1.0);
    restored.setStrokeStyle(browser::colors::kRed);
    restored.save();
    restored.translate(-7, 3);
    restored.restore();
    restored.restore();
    restored.restore();  // one more than saved: the browser ignores it, so do we
    CHECK(restored.strokeStyle() == browser::colors::kBlack);
    restored.strokeRect(10.5, 10.5, 30, 20);
    CHECK(restored.pixels().rgba == plain.pixels().rgba);
}

TEST_CASE("canvas: lines are anti-aliased, and move smoothly") {
    auto vertical_line = [](double x) {
        Canvas canvas(100, 60);
        canvas.beginPath();
        canvas.moveTo(x, 5);
        canvas.lineTo(x, 55);
        canvas.stroke();
        return canvas;
    };
    // On a pixel centre the line fills one column; on a pixel edge it half-fills two.
    const Canvas centred = vertical_line(50.5);
    CHECK(grey(centred, 50, 30) == 0);
    CHECK(grey(centred, 49, 30) == kWhite);
    CHECK(grey(centred, 51, 30) == kWhite);
    const Canvas on_edge = vertical_line(50.0);
    // 1 grey level: a share of ink rounds to a whole level of 255.
    CHECK_THAT(grey(on_edge, 49, 30), test::near(127.5, 1));
    CHECK_THAT(grey(on_edge, 50, 30), test::near(127.5, 1));

    // At x = 50.3, column 49 (centre 49.5) is 0.8 px away and column 50 is 0.2 px away:
    // they take 0.2 and 0.8 of the ink.
    const Canvas between = vertical_line(50.3);
    CHECK_THAT(grey(between, 49, 30), test::near(255 * 0.8, 1));
    CHECK_THAT(grey(between, 50, 30), test::near(255 * 0.2, 1));

    // Moving by 0.1 px moves at most a tenth of a pixel's ink in any pixel.
    const Canvas moved = vertical_line(50.4);
    CHECK(largest_difference(between, moved) <= 26 + 1);

    // The same for a slanted line, and its ink stays the same.
    auto slanted_line = [](double shift) {
        Canvas canvas(100, 60);
        canvas.beginPath();
        canvas.moveTo(10 + shift, 10);
        canvas.lineTo(90 + shift, 47);
        canvas.stroke();
        return canvas;
    };
    const Canvas a = slanted_line(0.0), b = slanted_line(0.1);
    CHECK(largest_difference(a, b) <= 26 + 1);
    int greys = 0;
    for (std::uint8_t v : a.pixels().rgba) greys += (v > 0 && v < kWhite) ? 1 : 0;
    CHECK(greys > 100);  // not just on and off
    CHECK(ink(a) == Approx(std::hypot(80.0, 37.0)).epsilon(0.05));
}

TEST_CASE("canvas: drawing off the canvas is clipped") {
    SECTION("a line with huge ends still draws its visible part exactly") {
        Canvas canvas(200, 100);
        canvas.beginPath();
        canvas.moveTo(-1e308, 50.5);  // the difference of the ends overflows a double
        canvas.lineTo(1e308, 50.5);
        canvas.moveTo(120.5, -1e9);
        canvas.lineTo(120.5, 1e9);
        canvas.stroke();
        int wrong = 0;
        for (int i = 0; i < 200; ++i) {
            if (grey(canvas, i, 50) != 0) ++wrong;
            if (i != 120 && (grey(canvas, i, 49) != kWhite || grey(canvas, i, 51) != kWhite)) ++wrong;
        }
        for (int j = 0; j < 100; ++j) {
            if (grey(canvas, 120, j) != 0) ++wrong;
        }
        CHECK(wrong == 0);
    }
    SECTION("shapes wholly outside draw nothing") {
        Canvas canvas(200, 100);
        canvas.beginPath();
        canvas.arc(1000, 1000, 50, 0, 2 * kPi);
        canvas.stroke();
        canvas.beginPath();
        canvas.arc(100, 50, 1e12, 0, 2 * kPi);  // everything is far outside
        canvas.stroke();
        canvas.translate(1e300, -1e300);
        canvas.strokeRect(0, 0, 10, 10);
        CHECK(all_white(canvas));
    }
    SECTION("a circle across the corner draws its inside quarter") {
        Canvas canvas(200, 100);
        canvas.beginPath();
        canvas.arc(0.0, 0.0, 30.0, 0, 2 * kPi);
        canvas.stroke();
        const double a = kPi / 4;  // the point of the circle halfway along the quarter inside
        CHECK(darkest_near(canvas, 30 * std::cos(a), 30 * std::sin(a)) <= kGreyWithinHalfPixel);
        CHECK(darkest_near(canvas, 0.5, 30.0) <= kGreyWithinHalfPixel);
        CHECK(grey(canvas, 10, 10) == kWhite);
    }
    SECTION("NaN and infinite points drop their segments, not the rest") {
        const double nan = std::numeric_limits<double>::quiet_NaN();
        const double inf = std::numeric_limits<double>::infinity();
        Canvas canvas(200, 100);
        canvas.beginPath();
        canvas.moveTo(nan, 10);
        canvas.lineTo(50, inf);
        canvas.lineTo(20.5, 20.5);
        canvas.lineTo(80.5, 20.5);  // the only finite segment
        canvas.arc(nan, 5, 5, 0, 1);
        canvas.stroke();
        canvas.translate(nan, 0);
        canvas.strokeRect(0, 0, 10, 10);
        CHECK(grey(canvas, 50, 20) == 0);
        CHECK_THAT(ink(canvas), test::near(60.0, 2.0));  // anti-aliased corners: up to 2 px
    }
}

TEST_CASE("canvas: arcs follow the canvas's angles and directions") {
    const double cx = 100.5, cy = 50.5, r = 30;
    auto point = [&](double a) { return std::pair{cx + r * std::cos(a), cy + r * std::sin(a)}; };
    auto inked = [&](const Canvas& canvas, double a) {
        const auto [x, y] = point(a);
        return darkest_near(canvas, x, y) <= kGreyWithinHalfPixel;
    };
    auto white = [&](const Canvas& canvas, double a) {
        const auto [x, y] = point(a);
        return darkest_near(canvas, x, y) == kWhite;
    };
    auto arc = [&](double a0, double a1, bool counterclockwise) {
        Canvas canvas(200, 100);
        canvas.beginPath();
        canvas.arc(cx, cy, r, a0, a1, counterclockwise);
        canvas.stroke();
        return canvas;
    };

    // +y points down, so the quarter from 0 to pi/2 clockwise is the lower right one.
    const Canvas clockwise = arc(0, kPi / 2, false);
    CHECK(inked(clockwise, kPi / 4));
    CHECK(white(clockwise, kPi));
    CHECK(white(clockwise, -kPi / 2));
    // The other way round, the same end angles give the other three quarters.
    const Canvas counterclockwise = arc(0, kPi / 2, true);
    CHECK(white(counterclockwise, kPi / 4));
    CHECK(inked(counterclockwise, kPi));
    CHECK(inked(counterclockwise, -kPi / 2));
    // An end angle behind the start is reached by going on round: 3/4 of the circle.
    const Canvas wrapped = arc(kPi / 2, 0, false);
    CHECK(inked(wrapped, kPi));
    CHECK(inked(wrapped, -kPi / 2));
    CHECK(white(wrapped, kPi / 4));
    // The book's full circle: from 0 to 2 pi, counterclockwise.
    const Canvas full = arc(0, 2 * kPi, true);
    for (int k = 0; k < 8; ++k) CHECK(inked(full, k * kPi / 4));

    // arc joins the current point to its start with a line; closePath joins its end
    // back to the first point.
    Canvas joined(200, 100);
    joined.beginPath();
    joined.moveTo(cx, cy);
    joined.arc(cx, cy, r, 0, kPi / 2);
    joined.closePath();
    joined.stroke();
    CHECK(grey(joined, static_cast<int>(cx + r / 2), static_cast<int>(cy)) == 0);  // centre to (r, 0)
    CHECK(grey(joined, static_cast<int>(cx), static_cast<int>(cy + r / 2)) == 0);  // (0, r) back to centre
}

TEST_CASE("canvas: clearRect erases to white, under the transform too") {
    Canvas canvas(100, 60);
    auto darken = [&] {
        canvas.beginPath();
        for (int j = 0; j < 60; ++j) {
            canvas.moveTo(0, j + 0.5);
            canvas.lineTo(100, j + 0.5);
        }
        canvas.stroke();
    };
    darken();
    CHECK(grey(canvas, 50, 30) == 0);
    canvas.clearRect(10, 20, 30, 15);  // pixels 10..39 x 20..34
    CHECK(grey(canvas, 10, 20) == kWhite);
    CHECK(grey(canvas, 39, 34) == kWhite);
    CHECK(grey(canvas, 9, 20) == 0);
    CHECK(grey(canvas, 40, 20) == 0);
    CHECK(grey(canvas, 10, 35) == 0);

    canvas.save();
    canvas.translate(70, 30);
    canvas.rotate(kPi / 4);
    canvas.clearRect(-10, -10, 20, 20);  // a diamond round (70, 30), 14.1 px from centre to tip
    canvas.restore();
    CHECK(grey(canvas, 70, 30) == kWhite);
    CHECK(grey(canvas, 70 + 12, 30) == kWhite);  // near the right tip
    CHECK(grey(canvas, 70 + 9, 30 + 9) == 0);    // beyond the lower right side
    CHECK(grey(canvas, 70 + 16, 30) == 0);       // beyond the tip

    canvas.clear();
    CHECK(all_white(canvas));
}

TEST_CASE("canvas: the same calls give the same pixels") {
    auto draw = [] {
        Canvas canvas;
        for (int k = 0; k < 10; ++k) {
            canvas.save();
            canvas.translate(40.0 + 70.3 * k, 100.0 + 17.1 * k);
            canvas.rotate(0.37 * k);
            canvas.strokeRect(0, 0, 30 + k, 20 + k);
            canvas.restore();
            canvas.beginPath();
            canvas.arc(50.0 + 71.7 * k, 300.0, 10.0 + 3.3 * k, 0, 2 * kPi, true);
            canvas.stroke();
        }
        return canvas.pixels().rgba;
    };
    CHECK(draw() == draw());
}

TEST_CASE("page: the canvas framed on the left, the echo text in a panel on the right") {
    browser::Document document{Canvas(200, 120), ""};
    document.canvas.beginPath();
    document.canvas.moveTo(20.5, 60.5);
    document.canvas.lineTo(180.5, 60.5);
    document.canvas.stroke();
    // One line far too long for the panel, with no place to break but its spaces.
    document.ui_echo = "Hello\n" + std::string(60, 'W') + " end\nlast";

    const browser::Image page = browser::render_page(document);
    REQUIRE(page.width == 200 + browser::kPanelWidth);
    REQUIRE(page.height == 120);
    CHECK(page.at(100, 60) == browser::colors::kBlack);  // the canvas's pixels
    CHECK(page.at(100, 30) == browser::colors::kWhite);
    CHECK(page.at(0, 0) == browser::colors::kGray);  // the frame on its edge pixels
    CHECK(page.at(199, 119) == browser::colors::kGray);

    // Which pixel rows of the panel have ink: every one of the text lines
    // ("Hello", the long line wrapped onto three, "end", "last") leaves some.
    int inked_rows = 0;
    int ink_right_of_text = 0;
    for (int y = 0; y < page.height; ++y) {
        bool inked = false;
        for (int x = 200; x < page.width; ++x) {
            if (page.at(x, y) == browser::colors::kBlack) {
                inked = true;
                if (x >= page.width - 5) ++ink_right_of_text;
            }
        }
        inked_rows += inked ? 1 : 0;
    }
    CHECK(inked_rows > 50);  // text all the way down the 120 px panel, not just one line
    CHECK(ink_right_of_text == 0);
}

TEST_CASE("canvas: at scale K a canvas pixel is K x K device pixels, and the canvas size stays") {
    Canvas canvas(40, 30, 3);
    CHECK(canvas.width() == 40);
    CHECK(canvas.height() == 30);
    CHECK(canvas.scale() == 3);
    CHECK(canvas.pixels().width == 120);
    CHECK(canvas.pixels().height == 90);
    CHECK(all_white(canvas));
    canvas.strokeRect(5, 5, 10, 10);
    canvas.setScale(2);  // blanks it
    CHECK(canvas.pixels().width == 80);
    CHECK(all_white(canvas));
    CHECK_THROWS_AS(canvas.setScale(0), std::invalid_argument);
    CHECK_THROWS_AS(Canvas(10, 10, Canvas::kMaxScale + 1), std::invalid_argument);
}

TEST_CASE("canvas: at scale 2 the pen is 2 device pixels wide, and lines land at twice their place") {
    // The line y = 10.5 from x = 10 to 30 is y = 21 on the device, from x = 20 to 60.
    // Pen reach 2: a row whose centre is d away gets 1 - d / 2 of the ink, so rows 20
    // and 21 (d = 0.5) get 0.75, rows 19 and 22 (d = 1.5) 0.25 and rows 18 and 23
    // (d = 2.5) none: black over white leaves 255 (1 - c), rounded: 64, 191, 255.
    Canvas canvas(40, 30, 2);
    canvas.beginPath();
    canvas.moveTo(10, 10.5);
    canvas.lineTo(30, 10.5);
    canvas.stroke();
    for (const int i : {24, 40, 55}) {
        INFO("device column " << i);
        CHECK(grey(canvas, i, 18) == 255);
        CHECK(grey(canvas, i, 19) == 191);
        CHECK(grey(canvas, i, 20) == 64);
        CHECK(grey(canvas, i, 21) == 64);
        CHECK(grey(canvas, i, 22) == 191);
        CHECK(grey(canvas, i, 23) == 255);
    }
    // Under a transform the scale comes last: translate(5, 0) moves the line 10 device px.
    Canvas moved(40, 30, 2);
    moved.translate(5, 0);
    moved.beginPath();
    moved.moveTo(10, 10.5);
    moved.lineTo(30, 10.5);
    moved.stroke();
    for (int j = 15; j < 26; ++j) CHECK(grey(moved, 50, j) == grey(canvas, 40, j));
}

TEST_CASE("canvas: at scale 2 a circle is drawn round at twice its radius") {
    // Radius 10 at (20, 15) is radius 20 at (40, 30) on the device. Near each point of
    // that circle some pixel centre lies within 0.71 device px of it, so it has at least
    // 1 - 0.71 / 2 of the ink: 255 * 0.355 = 91 at most.
    Canvas canvas(40, 30, 2);
    canvas.beginPath();
    canvas.arc(20, 15, 10, 0, 2 * kPi);
    canvas.stroke();
    for (int step = 0; step < 16; ++step) {
        const double angle = step * kPi / 8;
        INFO("angle " << angle);
        CHECK(darkest_near(canvas, 40 + 20 * std::cos(angle), 30 + 20 * std::sin(angle)) <= 91);
        // Halfway between centre and ring, and 4 device px outside it: no ink (reach 2).
        CHECK(grey_at_point(canvas, 40 + 10 * std::cos(angle), 30 + 10 * std::sin(angle)) == 255);
        CHECK(grey_at_point(canvas, 40 + 24 * std::cos(angle), 30 + 24 * std::sin(angle)) == 255);
    }
}

TEST_CASE("canvas: clearRect at scale 2 erases the rectangle's device pixels") {
    Canvas canvas(10, 10, 2);
    for (int row = 0; row < 20; ++row) {  // ink on every device row
        canvas.beginPath();
        canvas.moveTo(0, row * 0.5 + 0.25);
        canvas.lineTo(10, row * 0.5 + 0.25);
        canvas.stroke();
    }
    canvas.clearRect(2, 2, 3, 3);  // device pixels 4 to 9 in both directions
    for (int j = 0; j < 20; ++j) {
        for (int i = 0; i < 20; ++i) {
            const bool inside = i >= 4 && i < 10 && j >= 4 && j < 10;
            INFO("device pixel " << i << ", " << j);
            CHECK((grey(canvas, i, j) == 255) == inside);
        }
    }
}

TEST_CASE("page: at scale 2 the frame, the panel and its text are twice as large") {
    // Frame and text cover whole blocks of 2 x 2 device pixels, so the page at scale 2,
    // shrunk by 2 (each pixel the mean of a block), is the page at scale 1 exactly; and
    // the text wraps where it wraps at scale 1.
    const std::string echo = "Hello\n" + std::string(60, 'W') + " end\nlast";
    browser::Document small{Canvas(200, 120), echo};
    browser::Document large{Canvas(200, 120, 2), echo};
    const browser::Image page = browser::render_page(small);
    const browser::Image page2 = browser::render_page(large);
    REQUIRE(page2.width == 2 * page.width);
    REQUIRE(page2.height == 2 * page.height);
    CHECK(page2.at(1, 100) == browser::colors::kGray);  // the frame is 2 device pixels thick
    CHECK(page2.at(2, 100) == browser::colors::kWhite);
    const browser::Image shrunk = browser::shrink(page2, 2);
    CHECK(shrunk.rgba == page.rgba);
}

TEST_CASE("page: a stage's section beyond the book goes on a band under the page, the book's page unchanged") {
    for (const int scale : {1, 2}) {
        browser::Document document{Canvas(200, 120, scale), "Selected Object:\n  Id: 0"};
        document.canvas.beginPath();
        document.canvas.moveTo(20.5, 60.5);
        document.canvas.lineTo(180.5, 60.5);
        document.canvas.stroke();
        const browser::Image book = browser::render_page(document);
        // Three lines; the last one too long for the panel, so wrapped onto a fourth.
        document.beyond_echo = "Beyond the book:\n  Sleeping: true\n  " + std::string(40, 'W') + " end";
        const browser::Image page = browser::render_page(document);
        // The band: four lines and a half margin above and below them.
        REQUIRE(page.width == book.width);
        REQUIRE(page.height == book.height + (4 * browser::text_line_height() + 10) * scale);
        for (int y = 0; y < book.height; ++y) {
            for (int x = 0; x < book.width; ++x) REQUIRE(page.at(x, y) == book.at(x, y));
        }
        // Ink in the band under the panel, on each of its four lines; none under the canvas.
        int inked_lines = 0, ink_under_canvas = 0;
        for (int line = 0; line < 4; ++line) {
            bool inked = false;
            for (int y = book.height + (5 + line * browser::text_line_height()) * scale;
                 y < book.height + (5 + (line + 1) * browser::text_line_height()) * scale; ++y) {
                for (int x = 0; x < page.width; ++x) {
                    if (page.at(x, y) != browser::colors::kBlack) continue;
                    inked = inked || x >= 200 * scale;
                    ink_under_canvas += x < 200 * scale;
                }
            }
            inked_lines += inked;
        }
        CHECK(inked_lines == 4);
        CHECK(ink_under_canvas == 0);
    }
}

TEST_CASE("page: the live window's status line goes under the page, which stays as it is") {
    browser::Document document{Canvas(200, 120), "echo"};
    for (const int scale : {1, 3}) {
        document.canvas.setScale(scale);
        const browser::Image page = browser::render_page(document);
        const browser::Image picture = browser::with_status_line(page, "frame 12", scale);
        REQUIRE(picture.width == page.width);
        REQUIRE(picture.height == page.height + 24 * scale);
        for (int y = 0; y < page.height; y += 7) {
            for (int x = 0; x < page.width; x += 5) REQUIRE(picture.at(x, y) == page.at(x, y));
        }
        int ink_in_band = 0;
        for (int y = page.height; y < picture.height; ++y) {
            for (int x = 0; x < picture.width; ++x) ink_in_band += picture.at(x, y) == browser::colors::kBlack;
        }
        CHECK(ink_in_band > 20 * scale * scale);
        CHECK(picture.at(picture.width - 1, picture.height - 1) == Color{224, 224, 224, 255});
    }
}
