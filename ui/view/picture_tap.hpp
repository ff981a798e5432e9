// The panels' own Pictures for the vector figures: while a PictureTap is open, every Picture a
// backend draws (ui/panels/picture_draw: one call to offer_picture) is kept, the last of each
// view name. `isoparm figure` and File > Export figure open one around a headless frame of the
// workstation and draw the view's Picture with the vector writers (drawing_of), so a figure is
// the panel's one drawing code; a view whose panel offers no Picture yet is built by
// figures.hpp instead.
#pragma once

#include <map>
#include <string>

#include "ui/view/picture.hpp"

namespace isoparm::ui {

class PictureTap {
public:
    PictureTap();  // opens (taps nest: the innermost takes the pictures)
    ~PictureTap(); // closes
    PictureTap(const PictureTap&) = delete;
    PictureTap& operator=(const PictureTap&) = delete;
    // The last Picture offered with this view name ("tracing", "basis_u", "curve"...).
    const Picture* find(const std::string& view) const;
    std::size_t size() const { return pictures_.size(); }

private:
    friend void offer_picture(const Picture& p);
    std::map<std::string, Picture> pictures_;
    PictureTap* outer_ = nullptr;
};

// A backend drawing `p` offers it to the open tap (nothing happens when none is open). One
// thread: the frame's.
void offer_picture(const Picture& p);

// The panel Picture that shows a figure view: "tracing", "basis_u", "curve", "deboor",
// "homogeneous", "blossom" for FigureView's order.
const char* picture_view_name(int figure_view);

} // namespace isoparm::ui
