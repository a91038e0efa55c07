#pragma once
// The contact sheet: small copies of the saved pages in a grid on one picture, each
// with its frame number above it, so a whole run can be seen at a glance (and compared
// with a stage's expected/ sheet) without opening a dozen files.

#include <string_view>
#include <vector>

#include "image.h"

namespace browser {

inline constexpr int kThumbnailScale = 3;                     // a thumbnail is the page shrunk 3 times
inline constexpr int kSheetColumns = 4;                       // thumbnails a row
inline constexpr int kSheetMargin = 10;                       // pixels round and between the cells
inline constexpr int kLabelHeight = 20;                       // the band above a thumbnail for its label
inline constexpr int kMostThumbnails = 100;                   // keeps a sheet of a long run a sensible size
inline constexpr Color kSheetBackground{224, 224, 224, 255};  // light gray, so white pages stand out

// The frames a run of `frames` animation frames that saves every `every`-th (> 0) shows
// on its sheet: the saved ones (0, every, 2 every, ...), then the last frame (the one
// final.png shows) when it is not one of them. When that would make more than
// kMostThumbnails, only every s-th saved frame is shown, s as small as fits.
std::vector<int> contact_sheet_frames(int frames, int every);

// `picture` shrunk `factor` (>= 1) times by a box filter: each pixel of the result is
// the rounded mean of a factor x factor block. Blocks cut by the right or bottom edge
// average the pixels they have, so the result is ceil(width / factor) wide.
Image shrink(const Image& picture, int factor);

// A grid of kSheetColumns thumbnails a row (fewer when there are fewer pictures), filled
// left to right, top to bottom. Each cell is a kLabelHeight band with the label, then
// the thumbnail; kSheetMargin pixels separate the cells and surround the grid. The
// number of pictures is fixed at the start so the sheet is made once, at its final
// size, when the first page shows how big a page is.
class ContactSheet {
public:
    // `page_scale`: the pages are drawn that many times larger (--scale), and shrunk
    // that many times more, so the sheet looks the same at every scale.
    explicit ContactSheet(int pictures, int page_scale = 1);

    // Adds `page` shrunk by kThumbnailScale (times the page scale) in the next cell. Every page must have the
    // size of the first; adding more than the promised number is an error.
    void add(const Image& page, std::string_view label);

    int pictures() const { return pictures_; }
    int added() const { return added_; }
    const Image& picture() const { return sheet_; }  // empty until the first add()

private:
    int pictures_;
    int page_scale_;
    int added_ = 0;
    int page_width_ = 0, page_height_ = 0;
    Image sheet_;
};

}  // namespace browser
