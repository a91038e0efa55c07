#include "contact_sheet.h"

#include <algorithm>
#include <cstdint>
#include <stdexcept>

#include "text.h"  // draw_text

namespace browser {
namespace {

int divide_rounding_up(int a, int b) { return (a + b - 1) / b; }

// stb_easy_font letters at the page's text size are about 14 pixels tall: centred in
// the band.
constexpr int kLabelTop = 3;

}  // namespace

std::vector<int> contact_sheet_frames(int frames, int every) {
    if (frames < 1 || every < 1) throw std::invalid_argument("contact_sheet_frames: frames and every must be >= 1");
    const int last = frames - 1;
    const int saved = last / every + 1;  // frames 0, every, 2 every, ... up to last
    const bool last_is_saved = last % every == 0;
    const int wanted = saved + (last_is_saved ? 0 : 1);
    // One place stays free for the last frame, which always ends the sheet.
    const int stride = wanted <= kMostThumbnails ? 1 : divide_rounding_up(saved, kMostThumbnails - 1);

    std::vector<int> shown;
    for (int i = 0; i < saved; i += stride) shown.push_back(i * every);
    if (shown.back() != last) shown.push_back(last);
    return shown;
}

Image shrink(const Image& picture, int factor) {
    if (factor < 1) throw std::invalid_argument("shrink: the factor must be >= 1");
    Image small(divide_rounding_up(picture.width, factor), divide_rounding_up(picture.height, factor));
    for (int y = 0; y < small.height; ++y) {
        for (int x = 0; x < small.width; ++x) {
            const int x0 = x * factor, y0 = y * factor;
            const int x1 = std::min(x0 + factor, picture.width), y1 = std::min(y0 + factor, picture.height);
            int sum[4] = {0, 0, 0, 0};
            for (int j = y0; j < y1; ++j) {
                for (int i = x0; i < x1; ++i) {
                    const Color c = picture.at(i, j);
                    sum[0] += c.r;
                    sum[1] += c.g;
                    sum[2] += c.b;
                    sum[3] += c.a;
                }
            }
            const int count = (x1 - x0) * (y1 - y0);
            const auto mean = [&](int total) { return static_cast<std::uint8_t>((total + count / 2) / count); };
            small.set(x, y, {mean(sum[0]), mean(sum[1]), mean(sum[2]), mean(sum[3])});
        }
    }
    return small;
}

ContactSheet::ContactSheet(int pictures, int page_scale) : pictures_(pictures), page_scale_(page_scale) {
    if (pictures < 1) throw std::invalid_argument("ContactSheet: needs at least one picture");
}

void ContactSheet::add(const Image& page, std::string_view label) {
    if (added_ == pictures_) throw std::logic_error("ContactSheet: more pictures than promised");
    if (added_ == 0) {
        page_width_ = page.width;
        page_height_ = page.height;
    } else if (page.width != page_width_ || page.height != page_height_) {
        throw std::invalid_argument("ContactSheet: every page must have the size of the first");
    }

    const Image thumbnail = shrink(page, kThumbnailScale * page_scale_);
    const int cell_width = thumbnail.width + kSheetMargin;
    const int cell_height = kLabelHeight + thumbnail.height + kSheetMargin;
    if (added_ == 0) {
        const int columns = std::min(kSheetColumns, pictures_);
        const int rows = divide_rounding_up(pictures_, columns);
        sheet_ = Image(kSheetMargin + columns * cell_width, kSheetMargin + rows * cell_height, kSheetBackground);
    }

    const int left = kSheetMargin + (added_ % kSheetColumns) * cell_width;
    const int top = kSheetMargin + (added_ / kSheetColumns) * cell_height;
    draw_text(sheet_, label, left, top + kLabelTop, colors::kBlack);
    sheet_.paste(thumbnail, left, top + kLabelHeight);
    ++added_;
}

}  // namespace browser
