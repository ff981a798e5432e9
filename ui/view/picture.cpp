// A teaching view's drawing as data: placing its labels.
#include "ui/view/picture.hpp"

namespace isoparm::ui {

LabelPlacement place(const Picture& p, const MeasureText& measure) {
    return place_labels(p.labels, p.frame, measure, p.style, p.keep_clear);
}

} // namespace isoparm::ui
