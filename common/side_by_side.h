#pragma once
// Two runs of one scene, shown as one picture: the left run's canvas beside the right
// one's, each under a band naming its setting (build/compare_runs). Only the canvases
// are shown: the two echo panels would only say twice what the labels say.

#include <string_view>

#include "image.h"

namespace browser {

// The left `page.width - kPanelWidth * scale` columns of a page (page.h), down to the
// bottom of the frame: its canvas with the frame round it, without the band a stage
// beyond the book adds under the page.
Image canvas_of(const Image& page, int scale);

// The part of `picture` at (x, y), width x height pixels; what lies outside
// `picture` is white.
Image cropped(const Image& picture, int x, int y, int width, int height);

// `picture` with `start` drawn faintly where `picture` is blank paper: whatever moved
// since `start` shows twice, the start a light tint of its colour. The two must be
// the same size (pictures of one run).
Image with_start_ghost(const Image& picture, const Image& start);

// `picture` with `trail`'s pixels where `picture` is blank paper. With the trail made
// of earlier pictures by with_start_ghost (each ghosted onto the trail in turn, from a
// blank one), this gives what ghosting each of them onto `picture` in turn gives, with
// one picture in memory instead of all of them.
Image with_trail(const Image& picture, const Image& trail);

// The two pictures side by side, kGapWidth apart, each under a band with its label in
// the page's font at its normal size (a label need not grow with --scale, and a zoomed
// crop has room for a long one). The taller sets the height; the other is padded white.
Image side_by_side(const Image& left, std::string_view left_label, const Image& right, std::string_view right_label);

inline constexpr int kGapWidth = 12;         // px between the two halves
inline constexpr int kHalfLabelHeight = 24;  // px of the band above each half

}  // namespace browser
