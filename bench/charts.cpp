#include "charts.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <initializer_list>
#include <iterator>
#include <numbers>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "canvas.h"
#include "contact_sheet.h"  // shrink
#include "image.h"
#include "page.h"  // draw_text
#include "png_io.h"

namespace bench {

namespace {

using browser::Canvas;
using browser::Color;
using browser::Image;

// ---------------------------------------------------------------- the look

constexpr Color kTextInk{25, 25, 25, 255};
constexpr Color kNoteInk{80, 80, 80, 255};
constexpr Color kAxisColor{60, 60, 60, 255};
constexpr Color kGridColor{220, 220, 220, 255};
constexpr Color kMinorGridColor{240, 240, 240, 255};
constexpr Color kBoxColor{170, 170, 170, 255};  // the picture's frame and the legend's box
constexpr Color kParetoColor{20, 20, 20, 255};

// Ten colours that stay apart from one another and from the grey of the grid.
constexpr Color kPalette[] = {
    {31, 119, 180, 255}, {255, 127, 14, 255}, {44, 160, 44, 255},  {214, 39, 40, 255},  {148, 103, 189, 255},
    {140, 86, 75, 255},  {227, 119, 194, 255}, {127, 127, 127, 255}, {188, 189, 34, 255}, {23, 190, 207, 255},
};
constexpr int kColourCount = static_cast<int>(std::size(kPalette));

// Markers are told apart by shape as well as colour, so the chart reads in grey too.
enum class Marker { circle, square, triangle_up, diamond, triangle_down, cross, plus, star };
constexpr int kMarkerCount = 8;
constexpr double kMarkerRadius = 5.0;
constexpr double kParetoRadius = 9.0;

constexpr int kMargin = 14;       // between the picture's edge and anything on it
constexpr int kTickLength = 5;
constexpr int kLabelGap = 6;      // between a tick and its label
constexpr int kLegendGap = 18;  // between the plot and the legend
constexpr int kLegendPadding = 8;
constexpr int kLegendSample = 34;  // room for a marker with a bit of line either side
constexpr int kLegendMostText = 210;

// draw_text's letters: capitals 14 px tall from the line's top, descenders down to 18 px.
constexpr int kCapHeight = 14;
constexpr int kInkHeight = 18;
constexpr int kLineStep = 20;
constexpr int kWidestLetter = 20;  // more than any letter's advance in that font (16 for @)

// Linear axes stop at 1e300 so that spans and paddings of the values stay finite.
constexpr double kLargestLinear = 1e300;

// ---------------------------------------------------------------- text

// A line of text as ink: black letters on white, exactly as wide as the letters reach.
Image ink_of(std::string_view text) {
    const auto tabs = std::count(text.begin(), text.end(), '\t');  // a tab is four spaces
    const int room = kWidestLetter * static_cast<int>(text.size() + 3 * static_cast<std::size_t>(tabs) + 1);
    Image scratch(room, kInkHeight, browser::colors::kWhite);
    browser::draw_text(scratch, text, 0, 0, browser::colors::kBlack);
    int width = 1;
    for (int x = 0; x < scratch.width; ++x) {
        for (int y = 0; y < scratch.height; ++y) {
            if (scratch.at(x, y).r != 255) width = x + 1;
        }
    }
    Image trimmed(width, kInkHeight, browser::colors::kWhite);
    trimmed.paste(scratch, 0, 0);
    return trimmed;
}

int text_width(std::string_view text) { return ink_of(text).width; }

// The font has a single size; halving its ink gives letters 7 px tall, with grey edges
// where a letter's stroke fell on half a pixel.
Image small_ink_of(std::string_view text) { return browser::shrink(ink_of(text), 2); }

// The ink turned a quarter turn anticlockwise, so the line reads from bottom to top.
Image turned_up(const Image& ink) {
    Image turned(ink.height, ink.width);
    for (int y = 0; y < ink.height; ++y) {
        for (int x = 0; x < ink.width; ++x) turned.set(y, ink.width - 1 - x, ink.at(x, y));
    }
    return turned;
}

// Lays the ink on the picture with its top-left corner at (x, y): the darker an ink pixel,
// the more `color` covers the pixel beneath, as an anti-aliased stroke would.
void stamp(Image& picture, const Image& ink, int x, int y, Color color) {
    const auto mix = [](std::uint8_t under, std::uint8_t over, double cover) {
        return static_cast<std::uint8_t>(under + (over - under) * cover + 0.5);
    };
    for (int j = 0; j < ink.height; ++j) {
        for (int i = 0; i < ink.width; ++i) {
            const double cover = 1.0 - ink.at(i, j).r / 255.0;
            if (cover <= 0.0 || !picture.contains(x + i, y + j)) continue;
            const Color under = picture.at(x + i, y + j);
            picture.set(x + i, y + j, {mix(under.r, color.r, cover), mix(under.g, color.g, cover),
                                       mix(under.b, color.b, cover), 255});
        }
    }
}

// The text in lines at most max_width pixels wide, broken at spaces where it can be,
// inside a word too long for a line of its own where it cannot.
std::vector<std::string> wrapped(std::string_view text, int max_width) {
    std::vector<std::string> lines;
    std::string line;
    const auto fits = [&](const std::string& candidate) { return text_width(candidate) <= max_width; };
    std::size_t start = 0;
    while (start <= text.size()) {
        const std::size_t end = std::min(text.find(' ', start), text.size());
        std::string word(text.substr(start, end - start));
        start = end + 1;
        if (word.empty()) continue;
        if (!line.empty() && fits(line + " " + word)) {
            line += " " + word;
            continue;
        }
        if (!line.empty()) lines.push_back(line);
        line.clear();
        while (!fits(word)) {  // a word wider than a line: as many letters as fit, at least one
            std::size_t keep = 1;
            while (keep + 1 < word.size() && fits(word.substr(0, keep + 1))) ++keep;
            lines.push_back(word.substr(0, keep));
            word.erase(0, keep);
        }
        line = word;
    }
    if (!line.empty() || lines.empty()) lines.push_back(line);
    return lines;
}

// A pixel position as a whole pixel, kept well inside int even if the layout went wild.
int whole(double pixel) { return static_cast<int>(std::lround(std::clamp(pixel, -1e6, 1e6))); }

// ---------------------------------------------------------------- axes

// One axis maps data values to pixels. On a logarithmic axis positions follow log10 of the
// value, so equal ratios take equal lengths; "units" below are the values on a linear
// axis and their logarithms on a logarithmic one.
struct Axis {
    bool log = false;
    double low = 0.0, high = 1.0;              // the ends, in units
    double pixel_low = 0.0, pixel_high = 1.0;  // where they lie on the picture

    double units(double value) const { return log ? std::log10(value) : value; }
    double pixel_of_units(double u) const { return pixel_low + (u - low) / (high - low) * (pixel_high - pixel_low); }
    double pixel(double value) const { return pixel_of_units(units(value)); }
    double length() const { return std::abs(pixel_high - pixel_low); }
};

bool on_scale(double value, bool log) {
    if (!std::isfinite(value)) return false;
    return log ? value > 0.0 : std::abs(value) <= kLargestLinear;
}

bool on_scale(const ChartPoint& point, const Chart& chart) {
    return on_scale(point.x, chart.log_x) && on_scale(point.y, chart.log_y);
}

// The ends of an axis showing the given units: the data's span with a twentieth of it to
// spare at each end, so no marker sits on the frame. A single value gets room around it
// (half a decade either side on a logarithmic axis); no values at all, a unit span.
std::pair<double, double> axis_ends(const std::vector<double>& units, bool log) {
    if (units.empty()) return {0.0, 1.0};
    const auto [least, most] = std::minmax_element(units.begin(), units.end());
    double low = *least, high = *most;
    if (low == high) {
        const double room = log ? 0.5 : (low == 0.0 ? 1.0 : 0.1 * std::abs(low));
        return {low - room, high + room};
    }
    const double spare = 0.05 * (high - low);
    return {low - spare, high + spare};
}

struct Tick {
    double units;
    std::string label;
    int priority;  // labels of priority 0 are placed first, then 1, ...
    double place;  // a whole number counting the ticks of priority 0 from a round value (0 or 1)
};

struct AxisMarks {
    std::vector<Tick> ticks;           // with a grid line and a label (if it fits)
    std::vector<double> minor_units;   // a faint grid line only
};

// A step of 1, 2 or 5 times a power of ten, the smallest such at least `rough`: ticks
// then fall on round numbers.
double round_step(double rough) {
    const double power = std::pow(10.0, std::floor(std::log10(rough)));
    for (double multiple : {1.0, 2.0, 5.0}) {
        if (multiple * power >= rough * (1.0 - 1e-9)) return multiple * power;
    }
    return 10.0 * power;
}

// "0.25", "1500"; for very large or very fine numbers "2.5e6", "3e-5", "1e7".
std::string linear_label(double value, double step) {
    char text[64];
    const int step_digit = static_cast<int>(std::floor(std::log10(step) + 1e-9));
    const bool scientific = std::abs(value) >= 1e6 || step < 1e-4;
    if (std::abs(value) < 1e-6 * step) value = 0.0;  // what rounding left of a zero; also keeps "-0" away
    if (scientific && value == 0.0) return "0";
    if (!scientific) {
        std::snprintf(text, sizeof text, "%.*f", std::max(0, -step_digit), value);
        return text;
    }
    const int exponent = static_cast<int>(std::floor(std::log10(std::abs(value)) + 1e-9));
    const int decimals = std::clamp(exponent - step_digit, 0, 6);
    std::snprintf(text, sizeof text, "%.*f", decimals, value / std::pow(10.0, exponent));
    std::string mantissa = text;
    if (mantissa.find('.') != std::string::npos) {  // "2.50" -> "2.5", "1.0" -> "1": each label as short as it can be
        mantissa.erase(mantissa.find_last_not_of('0') + 1);
        if (mantissa.back() == '.') mantissa.pop_back();
    }
    return mantissa + "e" + std::to_string(exponent);
}

// Round numbers a step apart, the step chosen for about one tick per `spacing` pixels.
// `to_units` places a value on the axis (the identity on a linear axis).
template <typename ToUnits>
std::vector<Tick> linear_ticks(double low_value, double high_value, double length, double spacing, ToUnits to_units) {
    const double step = round_step((high_value - low_value) / std::max(2.0, length / spacing));
    std::vector<Tick> ticks;
    constexpr int kMostTicks = 50;  // a span below the values' precision repeats values
    const double first = std::ceil(low_value / step);
    for (int k = 0; k < kMostTicks && (first + k) * step <= high_value; ++k) {
        const double value = (first + k) * step;
        ticks.push_back({to_units(value), linear_label(value, step), 0, first + k});
    }
    return ticks;
}

// Decades as "0.01" ... "1000", wider ones as "1e4", "1e-3"; with a leading multiple ("2e5")
// for the ticks between decades.
std::string log_label(int multiple, int decade) {
    char text[64];
    if (decade >= -2 && decade <= 3) {
        std::snprintf(text, sizeof text, "%.*f", std::max(0, -decade), multiple * std::pow(10.0, decade));
    } else {
        std::snprintf(text, sizeof text, "%de%d", multiple, decade);
    }
    return text;
}

// Ticks at whole decades. A short axis also gets 2 and 5 times them (and, if that is still
// too few to read a scale from, every multiple); a long one with room to spare gets faint
// lines at 2 ... 9 times each decade, which show the axis is logarithmic at a glance.
AxisMarks log_marks(const Axis& axis) {
    AxisMarks marks;
    const double decade_pixels = axis.length() / (axis.high - axis.low);
    int stride = 1;  // decades apart, so that ticks stay at least 24 px apart
    for (int next : {2, 5, 10, 20, 50, 100}) {
        if (stride * decade_pixels >= 24.0) break;
        stride = next;
    }
    const int first = static_cast<int>(std::ceil(axis.low)), last = static_cast<int>(std::floor(axis.high));
    const auto inside = [&](double u) { return u >= axis.low && u <= axis.high; };
    for (int decade = first; decade <= last; ++decade) {
        if (decade % stride == 0) {
            marks.ticks.push_back({static_cast<double>(decade), log_label(1, decade), 0, static_cast<double>(decade / stride)});
        }
    }
    const auto add_multiples = [&](std::initializer_list<int> multiples, int priority) {
        for (int decade = first - 1; decade <= last; ++decade) {
            for (int multiple : multiples) {
                const double u = decade + std::log10(multiple);
                if (inside(u)) marks.ticks.push_back({u, log_label(multiple, decade), priority, 0.0});
            }
        }
    };
    if (marks.ticks.size() < 3) add_multiples({2, 5}, 1);
    if (marks.ticks.size() < 2) add_multiples({3, 4, 6, 7, 8, 9}, 2);
    if (marks.ticks.size() < 2) {  // less than a factor of two: round values, placed by their logarithm
        marks.ticks = linear_ticks(std::pow(10.0, axis.low), std::pow(10.0, axis.high), axis.length(), 60.0,
                                   [](double value) { return std::log10(value); });
    }
    if (stride == 1 && decade_pixels >= 60.0 && marks.ticks.size() >= 2) {
        for (int decade = first - 1; decade <= last; ++decade) {
            for (int multiple = 2; multiple <= 9; ++multiple) {
                const double u = decade + std::log10(multiple);
                if (inside(u)) marks.minor_units.push_back(u);
            }
        }
    }
    return marks;
}

// `spacing`: the pixels wanted between ticks of a linear axis.
AxisMarks axis_marks(const Axis& axis, double spacing) {
    if (axis.log) return log_marks(axis);
    return {linear_ticks(axis.low, axis.high, axis.length(), spacing, [](double value) { return value; }), {}};
}

// Which tick labels to print, so that none comes within `gap` pixels of another
// (`extent`: a label's size along the axis). The main ticks are labelled every n-th,
// n as small as leaves room, counted from a round value so the labels stay regular;
// then each tick of priority 1, then 2, that finds room among those placed.
std::vector<bool> labels_that_fit(const std::vector<Tick>& ticks, const Axis& axis,
                                  const std::vector<int>& extent, double gap) {
    const auto clear_of_shown = [&](const std::vector<bool>& shown, std::size_t i) {
        for (std::size_t j = 0; j < ticks.size(); ++j) {
            if (j == i || !shown[j]) continue;
            const double apart = std::abs(axis.pixel_of_units(ticks[i].units) - axis.pixel_of_units(ticks[j].units));
            if (apart < 0.5 * (extent[i] + extent[j]) + gap) return false;
        }
        return true;
    };
    std::vector<bool> shown(ticks.size(), false);
    for (std::size_t every = 1; every <= ticks.size(); ++every) {
        for (std::size_t i = 0; i < ticks.size(); ++i) {
            shown[i] = ticks[i].priority == 0 && std::fmod(ticks[i].place, static_cast<double>(every)) == 0.0;
        }
        bool any = false, clear = true;
        for (std::size_t i = 0; i < ticks.size(); ++i) {
            if (!shown[i]) continue;
            any = true;
            clear = clear && clear_of_shown(shown, i);
        }
        if (any && clear) break;
        std::fill(shown.begin(), shown.end(), false);
    }
    for (int priority = 1; priority <= 2; ++priority) {
        for (std::size_t i = 0; i < ticks.size(); ++i) {
            if (ticks[i].priority == priority) shown[i] = clear_of_shown(shown, i);
        }
    }
    return shown;
}

// ---------------------------------------------------------------- strokes

struct Pixel {
    double x, y;
};

// Data lines a little over 1.5 px wide: the 1 px pen drawn three times, nudged half a pixel
// across and down.
void stroke_thick(Canvas& canvas, const std::vector<Pixel>& line, Color color) {
    for (const Pixel nudge : {Pixel{0.0, 0.0}, Pixel{0.5, 0.0}, Pixel{0.0, 0.5}}) {
        canvas.save();
        canvas.setStrokeStyle(color);
        canvas.translate(nudge.x, nudge.y);
        canvas.beginPath();
        for (const Pixel& p : line) canvas.lineTo(p.x, p.y);
        canvas.stroke();
        canvas.restore();
    }
}

// A dashed line through the pixels: dashes and gaps measured along the whole line, so the
// pattern runs on round its corners.
void stroke_dashed(Canvas& canvas, const std::vector<Pixel>& line, Color color) {
    constexpr double kDash = 7.0, kGap = 5.0;
    std::vector<std::vector<Pixel>> dashes;
    double along = 0.0;  // position in the current dash-and-gap period
    bool drawing = false;
    for (std::size_t k = 1; k < line.size(); ++k) {
        const Pixel a = line[k - 1], b = line[k];
        const double length = std::hypot(b.x - a.x, b.y - a.y);
        double done = 0.0;
        while (done < length) {
            const bool in_dash = along < kDash;
            const double piece = std::min(length - done, in_dash ? kDash - along : kDash + kGap - along);
            const Pixel from{a.x + (b.x - a.x) * done / length, a.y + (b.y - a.y) * done / length};
            done += piece;
            const Pixel to{a.x + (b.x - a.x) * done / length, a.y + (b.y - a.y) * done / length};
            if (in_dash) {
                if (!drawing) dashes.push_back({from});
                dashes.back().push_back(to);
            }
            drawing = in_dash && along + piece < kDash;
            along = std::fmod(along + piece, kDash + kGap);
        }
    }
    for (const auto& dash : dashes) stroke_thick(canvas, dash, color);
}

// The outline of a marker of size r round (cx, cy), as the current path.
void marker_path(Canvas& canvas, Marker marker, double cx, double cy, double r) {
    canvas.beginPath();
    const auto polygon = [&](std::initializer_list<Pixel> corners) {
        for (const Pixel& c : corners) canvas.lineTo(cx + c.x, cy + c.y);
        canvas.closePath();
    };
    const auto bar = [&](double dx, double dy) {
        canvas.moveTo(cx - dx, cy - dy);
        canvas.lineTo(cx + dx, cy + dy);
    };
    // Sizes balanced by eye: a square as wide as a circle looks heavier, a triangle lighter.
    const double s = 0.85 * r, t = 1.25 * r, d = 1.2 * r;
    switch (marker) {
        case Marker::circle: canvas.arc(cx, cy, r, 0.0, 2.0 * std::numbers::pi); break;
        case Marker::square: polygon({{-s, -s}, {s, -s}, {s, s}, {-s, s}}); break;
        case Marker::triangle_up: polygon({{0, -t}, {0.866 * t, 0.5 * t}, {-0.866 * t, 0.5 * t}}); break;
        case Marker::diamond: polygon({{0, -d}, {d, 0}, {0, d}, {-d, 0}}); break;
        case Marker::triangle_down: polygon({{0, t}, {-0.866 * t, -0.5 * t}, {0.866 * t, -0.5 * t}}); break;
        case Marker::cross: bar(s, s); bar(s, -s); break;
        case Marker::plus: bar(r, 0); bar(0, r); break;
        case Marker::star: bar(r, 0); bar(0.5 * r, 0.866 * r); bar(0.5 * r, -0.866 * r); break;
    }
}

bool has_inside(Marker marker) { return marker != Marker::cross && marker != Marker::plus && marker != Marker::star; }

// A hollow marker with a white face, so lines under it do not show through; its rim is
// two outlines a pixel apart, to stand out from the 1 px grid.
void draw_marker(Canvas& canvas, Marker marker, double cx, double cy, Color color) {
    canvas.save();
    if (has_inside(marker)) {
        canvas.setStrokeStyle(browser::colors::kWhite);
        for (double r = kMarkerRadius - 1.0; r > 0.0; r -= 0.6) {
            marker_path(canvas, marker, cx, cy, r);
            canvas.stroke();
        }
    }
    canvas.setStrokeStyle(color);
    marker_path(canvas, marker, cx, cy, kMarkerRadius);
    canvas.stroke();
    if (has_inside(marker)) {
        marker_path(canvas, marker, cx, cy, kMarkerRadius - 0.8);
    } else {  // bars: thickened across instead of nested
        canvas.translate(0.5, 0.5);
        marker_path(canvas, marker, cx, cy, kMarkerRadius);
    }
    canvas.stroke();
    canvas.restore();
}

void draw_pareto_ring(Canvas& canvas, double cx, double cy) {
    canvas.save();
    canvas.setStrokeStyle(kParetoColor);
    for (double r : {kParetoRadius, kParetoRadius - 0.7}) {
        canvas.beginPath();
        canvas.arc(cx, cy, r, 0.0, 2.0 * std::numbers::pi);
        canvas.stroke();
    }
    canvas.restore();
}

// A horizontal or vertical 1 px line lands on one row or column of pixels when it runs
// through pixel centres.
double centred(double pixel) { return std::floor(pixel) + 0.5; }

void draw_line(Canvas& canvas, double x0, double y0, double x1, double y1, Color color) {
    canvas.save();
    canvas.setStrokeStyle(color);
    canvas.beginPath();
    canvas.moveTo(x0, y0);
    canvas.lineTo(x1, y1);
    canvas.stroke();
    canvas.restore();
}

// ---------------------------------------------------------------- the chart

Color colour_of(std::size_t series) { return kPalette[series % kColourCount]; }
Marker marker_of(std::size_t series) { return static_cast<Marker>(series % kMarkerCount); }

struct LegendEntry {
    std::vector<std::string> lines;
    Color colour;
    Marker marker;
    bool joined;
    bool pareto;  // the Pareto front's entry: ring and dashes
    int top = 0;  // of its first line
};

// The box right of the plot, its top level with the plot's: for each entry a sample (marker,
// line) and the name beside it.
struct Legend {
    std::vector<LegendEntry> entries;
    int left = 0, top = 0, width = 0, height = 0;
    int sample_left() const { return left + kLegendPadding; }
    int text_left() const { return sample_left() + kLegendSample + 8; }
};

// Entries for the named series and for the Pareto front, stacked; the box is placed later,
// once the plot's right edge is known.
Legend list_legend(const Chart& chart, bool has_front) {
    Legend legend;
    for (std::size_t s = 0; s < chart.series.size(); ++s) {
        const Series& series = chart.series[s];
        if (series.name.empty()) continue;
        legend.entries.push_back({wrapped(series.name, kLegendMostText), colour_of(s), marker_of(s), series.joined, false});
    }
    if (has_front) legend.entries.push_back({{"Pareto front"}, kParetoColor, Marker::circle, true, true});
    if (legend.entries.empty()) return legend;
    int text_width_most = 0, y = kLegendPadding;
    for (LegendEntry& entry : legend.entries) {
        for (const std::string& text : entry.lines) text_width_most = std::max(text_width_most, text_width(text));
        entry.top = y;
        y += static_cast<int>(entry.lines.size()) * kLineStep + 4;
    }
    legend.width = 2 * kLegendPadding + kLegendSample + 8 + text_width_most;
    legend.height = y - 4 + kLegendPadding;
    return legend;
}

void place_legend(Legend& legend, int left, int top) {
    legend.left = left;
    legend.top = top;
    for (LegendEntry& entry : legend.entries) entry.top += top;
}

// Everything drawn, worked out before drawing: the plot's box, the axes, the texts.
struct Layout {
    std::vector<std::string> title_lines, note_lines;
    double plot_left = 0, plot_top = 0, plot_right = 0, plot_bottom = 0;
    Axis x, y;
    AxisMarks x_marks, y_marks;
    std::vector<Image> x_label_inks, y_label_inks;
    std::vector<bool> x_shown, y_shown;
    Legend legend;
};

std::vector<Image> label_inks(const std::vector<Tick>& ticks) {
    std::vector<Image> inks;
    for (const Tick& tick : ticks) inks.push_back(ink_of(tick.label));
    return inks;
}

Layout lay_out(const Chart& chart, const std::vector<std::string>& notes, const std::vector<ChartPoint>& placed,
               bool has_front) {
    Layout layout;
    const int text_room = kChartWidth - 2 * kMargin;
    layout.title_lines = wrapped(chart.title, text_room);
    if (chart.title.empty()) layout.title_lines.clear();
    for (const std::string& note : notes) {
        for (std::string& piece : wrapped(note, text_room)) layout.note_lines.push_back(std::move(piece));
    }
    const auto header_lines = static_cast<int>(layout.title_lines.size() + layout.note_lines.size());

    // Top to bottom: header, plot, x tick labels, x axis label.
    layout.plot_top = kMargin + header_lines * kLineStep + 12;  // the top y label reaches 7 px above
    layout.plot_bottom = kChartHeight - kMargin - (chart.x_label.empty() ? 0 : kLineStep + 4) - kInkHeight -
                         kLabelGap - kTickLength;

    std::vector<double> xs, ys;
    for (const ChartPoint& p : placed) {
        xs.push_back(chart.log_x ? std::log10(p.x) : p.x);
        ys.push_back(chart.log_y ? std::log10(p.y) : p.y);
    }
    const auto [y_low, y_high] = axis_ends(ys, chart.log_y);
    layout.y = {chart.log_y, y_low, y_high, centred(layout.plot_bottom), centred(layout.plot_top)};
    layout.y_marks = axis_marks(layout.y, 55.0);
    layout.y_label_inks = label_inks(layout.y_marks.ticks);
    layout.y_shown = labels_that_fit(layout.y_marks.ticks, layout.y, std::vector<int>(layout.y_marks.ticks.size(), kCapHeight), 6.0);
    int widest_y_label = 0;
    for (std::size_t i = 0; i < layout.y_label_inks.size(); ++i) {
        if (layout.y_shown[i]) widest_y_label = std::max(widest_y_label, layout.y_label_inks[i].width);
    }

    // Left to right: y axis label (turned), y tick labels, plot, legend.
    layout.plot_left = kMargin + (chart.y_label.empty() ? 0 : kInkHeight + 12) + widest_y_label + kLabelGap + kTickLength;
    layout.legend = list_legend(chart, has_front);
    const bool has_legend = !layout.legend.entries.empty();
    layout.plot_right = kChartWidth - kMargin - (has_legend ? layout.legend.width + kLegendGap : 16);
    place_legend(layout.legend, static_cast<int>(layout.plot_right) + kLegendGap, static_cast<int>(layout.plot_top));

    const auto [x_low, x_high] = axis_ends(xs, chart.log_x);
    layout.x = {chart.log_x, x_low, x_high, centred(layout.plot_left), centred(layout.plot_right)};
    layout.x_marks = axis_marks(layout.x, 90.0);
    layout.x_label_inks = label_inks(layout.x_marks.ticks);
    std::vector<int> widths;
    for (const Image& ink : layout.x_label_inks) widths.push_back(ink.width);
    layout.x_shown = labels_that_fit(layout.x_marks.ticks, layout.x, widths, 12.0);
    return layout;
}

void draw_grid_and_axes(Canvas& canvas, const Layout& layout) {
    const double left = centred(layout.plot_left), right = centred(layout.plot_right);
    const double top = centred(layout.plot_top), bottom = centred(layout.plot_bottom);
    for (double u : layout.x_marks.minor_units) {
        const double x = centred(layout.x.pixel_of_units(u));
        draw_line(canvas, x, top, x, bottom, kMinorGridColor);
    }
    for (double u : layout.y_marks.minor_units) {
        const double y = centred(layout.y.pixel_of_units(u));
        draw_line(canvas, left, y, right, y, kMinorGridColor);
    }
    for (const Tick& tick : layout.x_marks.ticks) {
        const double x = centred(layout.x.pixel_of_units(tick.units));
        draw_line(canvas, x, top, x, bottom, kGridColor);
        draw_line(canvas, x, bottom, x, bottom + kTickLength, kAxisColor);
    }
    for (const Tick& tick : layout.y_marks.ticks) {
        const double y = centred(layout.y.pixel_of_units(tick.units));
        draw_line(canvas, left, y, right, y, kGridColor);
        draw_line(canvas, left - kTickLength, y, left, y, kAxisColor);
    }
    canvas.save();
    canvas.setStrokeStyle(kAxisColor);
    canvas.strokeRect(left, top, right - left, bottom - top);
    canvas.restore();
}

Pixel pixel_of(const ChartPoint& point, const Layout& layout) {
    return {layout.x.pixel(point.x), layout.y.pixel(point.y)};
}

// Dashes from ring to ring, which leave the markers on the front clear.
void draw_front_line(Canvas& canvas, const std::vector<Pixel>& front) {
    for (std::size_t k = 1; k < front.size(); ++k) {
        const Pixel a = front[k - 1], b = front[k];
        const double length = std::hypot(b.x - a.x, b.y - a.y);
        if (length <= 2.0 * kParetoRadius) continue;  // rings touching: no room for a line
        const double ux = (b.x - a.x) / length * kParetoRadius, uy = (b.y - a.y) / length * kParetoRadius;
        stroke_dashed(canvas, {{a.x + ux, a.y + uy}, {b.x - ux, b.y - uy}}, kParetoColor);
    }
}

// The lines of the joined series first, then all markers, so no line crosses a marker.
void draw_series(Canvas& canvas, const Chart& chart, const Layout& layout) {
    for (std::size_t s = 0; s < chart.series.size(); ++s) {
        if (!chart.series[s].joined) continue;
        std::vector<Pixel> run;  // a point off the scale breaks the line: nothing is known there
        const auto end_run = [&] {
            stroke_thick(canvas, run, colour_of(s));
            run.clear();
        };
        for (const ChartPoint& point : chart.series[s].points) {
            if (on_scale(point, chart)) run.push_back(pixel_of(point, layout));
            else end_run();
        }
        end_run();
    }
    for (std::size_t s = 0; s < chart.series.size(); ++s) {
        for (const ChartPoint& point : chart.series[s].points) {
            if (!on_scale(point, chart)) continue;
            const Pixel p = pixel_of(point, layout);
            draw_marker(canvas, marker_of(s), p.x, p.y, colour_of(s));
        }
    }
}

void draw_legend_box(Canvas& canvas, const Legend& legend) {
    if (legend.entries.empty()) return;
    for (const LegendEntry& entry : legend.entries) {
        const double mid_y = entry.top + kCapHeight / 2.0;
        const double sample_left = legend.sample_left(), sample_right = sample_left + kLegendSample;
        const double mid_x = 0.5 * (sample_left + sample_right);
        const std::vector<Pixel> sample{{sample_left, mid_y}, {sample_right, mid_y}};
        if (entry.pareto) {
            stroke_dashed(canvas, sample, entry.colour);
            draw_pareto_ring(canvas, mid_x, mid_y);
        } else {
            if (entry.joined) stroke_thick(canvas, sample, entry.colour);
            draw_marker(canvas, entry.marker, mid_x, mid_y, entry.colour);
        }
    }
    canvas.save();
    canvas.setStrokeStyle(kBoxColor);
    canvas.strokeRect(legend.left + 0.5, legend.top + 0.5, legend.width, legend.height);
    canvas.restore();
}

void draw_texts(Image& picture, const Chart& chart, const Layout& layout) {
    int y = kMargin;
    for (const std::string& text : layout.title_lines) {  // bold: the letters twice, a pixel apart
        const Image ink = ink_of(text);
        stamp(picture, ink, kMargin, y, kTextInk);
        stamp(picture, ink, kMargin + 1, y, kTextInk);
        y += kLineStep;
    }
    for (const std::string& text : layout.note_lines) {
        stamp(picture, ink_of(text), kMargin, y, kNoteInk);
        y += kLineStep;
    }

    const int below_ticks = whole(layout.plot_bottom) + kTickLength + kLabelGap;
    for (std::size_t i = 0; i < layout.x_marks.ticks.size(); ++i) {
        if (!layout.x_shown[i]) continue;
        const Image& ink = layout.x_label_inks[i];
        const int centre = whole(layout.x.pixel_of_units(layout.x_marks.ticks[i].units));
        stamp(picture, ink, centre - ink.width / 2, below_ticks, kTextInk);
    }
    for (std::size_t i = 0; i < layout.y_marks.ticks.size(); ++i) {
        if (!layout.y_shown[i]) continue;
        const Image& ink = layout.y_label_inks[i];
        const int centre = whole(layout.y.pixel_of_units(layout.y_marks.ticks[i].units));
        stamp(picture, ink, whole(layout.plot_left) - kTickLength - kLabelGap - ink.width, centre - kCapHeight / 2,
              kTextInk);
    }

    const int plot_middle_x = whole(0.5 * (layout.plot_left + layout.plot_right));
    const int plot_middle_y = whole(0.5 * (layout.plot_top + layout.plot_bottom));
    if (!chart.x_label.empty()) {
        const Image ink = ink_of(chart.x_label);
        const int x = std::clamp(plot_middle_x - ink.width / 2, kMargin, std::max(kMargin, kChartWidth - kMargin - ink.width));
        stamp(picture, ink, x, below_ticks + kLineStep + 4, kTextInk);
    }
    if (!chart.y_label.empty()) {
        const Image ink = turned_up(ink_of(chart.y_label));
        const int top = std::max(whole(layout.plot_top) - 8, plot_middle_y - ink.height / 2);
        stamp(picture, ink, kMargin, top, kTextInk);
    }

    for (const LegendEntry& entry : layout.legend.entries) {
        int line_y = entry.top;
        for (const std::string& text : entry.lines) {
            stamp(picture, ink_of(text), layout.legend.text_left(), line_y, kTextInk);
            line_y += kLineStep;
        }
    }
}

// Point labels in the small font, in a darker shade of the series' colour (light colours
// make faint letters), right of the marker, or left of it near the right edge, and clear
// of the ring round a point on the Pareto front.
void draw_point_labels(Image& picture, const Chart& chart, const Layout& layout, const std::vector<ChartPoint>& front) {
    const auto darker = [](std::uint8_t channel) { return static_cast<std::uint8_t>(channel * 7 / 10); };
    for (std::size_t s = 0; s < chart.series.size(); ++s) {
        const Color colour = colour_of(s);
        const Color ink_colour{darker(colour.r), darker(colour.g), darker(colour.b), 255};
        for (const ChartPoint& point : chart.series[s].points) {
            if (point.label.empty() || !on_scale(point, chart)) continue;
            const bool ringed = std::any_of(front.begin(), front.end(),
                                            [&](const ChartPoint& f) { return f.x == point.x && f.y == point.y; });
            const Image ink = small_ink_of(point.label);
            const int x = whole(layout.x.pixel(point.x)), y = whole(layout.y.pixel(point.y));
            const int room = static_cast<int>(ringed ? kParetoRadius : kMarkerRadius) + 4;
            const int left = x + room + ink.width <= whole(layout.plot_right) - 2 ? x + room : x - room - ink.width;
            stamp(picture, ink, left, y - kCapHeight / 4, ink_colour);
        }
    }
}

}  // namespace

std::vector<ChartPoint> pareto_front(const std::vector<ChartPoint>& points) {
    // b beats a when it is no worse on either axis and better on one.
    const auto beats = [](const ChartPoint& b, const ChartPoint& a) {
        return b.x <= a.x && b.y <= a.y && (b.x < a.x || b.y < a.y);
    };
    std::vector<ChartPoint> front;
    for (const ChartPoint& a : points) {
        if (std::isnan(a.x) || std::isnan(a.y)) continue;
        const bool beaten = std::any_of(points.begin(), points.end(), [&](const ChartPoint& b) { return beats(b, a); });
        if (!beaten) front.push_back(a);
    }
    std::stable_sort(front.begin(), front.end(), [](const ChartPoint& a, const ChartPoint& b) {
        return a.x < b.x || (a.x == b.x && a.y < b.y);
    });
    return front;
}

double fitted_exponent(const std::vector<ChartPoint>& points, double x_min, double x_max) {
    // With u = log x and v = log y the power law is the line v = log a + b u, and the
    // least-squares slope is b = sum (u - mean u)(v - mean v) / sum (u - mean u)^2.
    std::vector<std::pair<double, double>> logs;
    for (const ChartPoint& p : points) {
        const bool usable = p.x >= x_min && p.x <= x_max && p.x > 0.0 && p.y > 0.0 && std::isfinite(p.x) &&
                            std::isfinite(p.y);
        if (usable) logs.emplace_back(std::log(p.x), std::log(p.y));
    }
    if (logs.empty()) return std::nan("");
    double mean_u = 0.0, mean_v = 0.0;
    for (const auto& [u, v] : logs) {
        mean_u += u;
        mean_v += v;
    }
    mean_u /= static_cast<double>(logs.size());
    mean_v /= static_cast<double>(logs.size());
    double spread_uv = 0.0, spread_uu = 0.0;
    for (const auto& [u, v] : logs) {
        spread_uv += (u - mean_u) * (v - mean_v);
        spread_uu += (u - mean_u) * (u - mean_u);
    }
    if (spread_uu == 0.0) return std::nan("");  // one x only: every slope fits as well
    return spread_uv / spread_uu;
}

void write_chart(const Chart& chart, const std::filesystem::path& png) {
    std::vector<ChartPoint> placed;
    int off_scale = 0;
    for (const Series& series : chart.series) {
        for (const ChartPoint& point : series.points) {
            if (on_scale(point, chart)) placed.push_back(point);
            else ++off_scale;
        }
    }
    std::vector<std::string> notes = chart.notes;
    if (off_scale > 0) notes.push_back(std::to_string(off_scale) + (off_scale == 1 ? " point" : " points") + " off the scale");
    const std::vector<ChartPoint> front = chart.mark_pareto ? pareto_front(placed) : std::vector<ChartPoint>{};
    const Layout layout = lay_out(chart, notes, placed, !front.empty());

    Canvas canvas(kChartWidth, kChartHeight);
    draw_grid_and_axes(canvas, layout);
    std::vector<Pixel> front_pixels;
    for (const ChartPoint& p : front) front_pixels.push_back(pixel_of(p, layout));
    draw_front_line(canvas, front_pixels);
    draw_series(canvas, chart, layout);
    for (const Pixel& p : front_pixels) draw_pareto_ring(canvas, p.x, p.y);
    draw_legend_box(canvas, layout.legend);
    canvas.save();
    canvas.setStrokeStyle(kBoxColor);
    canvas.strokeRect(0.5, 0.5, kChartWidth - 1.0, kChartHeight - 1.0);
    canvas.restore();

    Image picture = canvas.pixels();
    draw_texts(picture, chart, layout);
    draw_point_labels(picture, chart, layout, front);
    browser::write_png(png, picture);
}

}  // namespace bench
