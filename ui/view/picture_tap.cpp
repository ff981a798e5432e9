#include "ui/view/picture_tap.hpp"

namespace isoparm::ui {

namespace {
thread_local PictureTap* open_tap = nullptr;
} // namespace

PictureTap::PictureTap() : outer_(open_tap) {
    open_tap = this;
}

PictureTap::~PictureTap() {
    open_tap = outer_;
}

const Picture* PictureTap::find(const std::string& view) const {
    const auto it = pictures_.find(view);
    return it == pictures_.end() ? nullptr : &it->second;
}

void offer_picture(const Picture& p) {
    if (open_tap) open_tap->pictures_[p.view] = p;
}

const char* picture_view_name(int figure_view) {
    static constexpr const char* names[] = {"tracing", "basis_u",     "curve",
                                            "deboor",  "homogeneous", "blossom"};
    return figure_view >= 0 && figure_view < 6 ? names[figure_view] : "";
}

} // namespace isoparm::ui
