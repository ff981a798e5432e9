// The analysis display's range and colours: automatic ranges from the visible surfaces'
// exact curvature (symmetric for K and H), fixed ranges as given, a flat grid's zero range
// widened, and the colour bar's map equal at its ends and middle to the shader's stops.
#include <gtest/gtest.h>

#include <cmath>

#include "core/doc/document.hpp"
#include "ui/view/analysis.hpp"

using namespace isoparm;
using namespace isoparm::ui;

namespace {

doc::Document with_analysis(doc::AnalysisMode mode) {
    doc::Document d = doc::default_document();
    d.view.display.analysis = mode;
    return d;
}

TEST(AnalysisView, AutomaticRangesAreSymmetricForGaussianAndMean) {
    for (auto mode : {doc::AnalysisMode::gaussian, doc::AnalysisMode::mean}) {
        const AnalysisView v = analysis_view(with_analysis(mode));
        EXPECT_TRUE(v.diverging);
        EXPECT_EQ(v.lo, -v.hi);
        EXPECT_GT(v.hi, 0);
    }
    const AnalysisView k = analysis_view(with_analysis(doc::AnalysisMode::kmax));
    EXPECT_FALSE(k.diverging);
    EXPECT_LT(k.lo, k.hi);
}

TEST(AnalysisView, AFixedRangeIsUsedAsGivenAndHiddenSurfacesDoNotCount) {
    doc::Document d = with_analysis(doc::AnalysisMode::kmin);
    d.view.display.analysis_fixed = true;
    d.view.display.analysis_lo = -0.5;
    d.view.display.analysis_hi = 2;
    const AnalysisView v = analysis_view(d);
    EXPECT_EQ(v.lo, -0.5f);
    EXPECT_EQ(v.hi, 2.0f);
    doc::Document hidden = with_analysis(doc::AnalysisMode::gaussian);
    for (doc::Object& o : hidden.objects) o.visible = false;
    const AnalysisView none = analysis_view(hidden);
    EXPECT_NEAR(none.hi, 1e-12, 1e-15); // nothing to measure: the zero range, widened
}

TEST(AnalysisView, ColoursMatchTheShadersStops) {
    AnalysisView v;
    v.kind = AnalysisKind::gaussian;
    v.lo = -2;
    v.hi = 2;
    const glm::vec3 mid = analysis_colour(v, 0), cool = analysis_colour(v, -2),
                    warm = analysis_colour(v, 5); // beyond the range: saturated
    EXPECT_FLOAT_EQ(mid.r, 0.87f);
    EXPECT_FLOAT_EQ(cool.b, 0.75f);
    EXPECT_FLOAT_EQ(warm.r, 0.71f);
    v.diverging = false;
    v.lo = 1;
    v.hi = 3;
    EXPECT_FLOAT_EQ(analysis_colour(v, 1).r, 0.27f);
    EXPECT_FLOAT_EQ(analysis_colour(v, 3).g, 0.91f);
}

TEST(AnalysisView, ModesMapOneToOne) {
    for (const auto& m : doc::analysis_mode_names)
        EXPECT_EQ(static_cast<int>(analysis_kind(m.value)), static_cast<int>(m.value));
    EXPECT_FALSE(analysis_title(AnalysisKind::zebra).empty());
}

} // namespace

TEST(AnalysisRange, OneOutlierDoesNotSetTheRange) {
    // 99 values near 1 and one pole at 165: the bar spans the 99 (the washed-out view).
    std::vector<double> v;
    for (int k = 0; k < 99; ++k) v.push_back(0.5 + k * 0.01);
    v.push_back(165);
    const Range r = robust_range(v);
    EXPECT_LT(r.hi, 2);
    EXPECT_GE(r.hi, 1.4);
    EXPECT_DOUBLE_EQ(r.all_hi, 165);
    EXPECT_DOUBLE_EQ(r.lo, 0.52);
    EXPECT_DOUBLE_EQ(r.all_lo, 0.5);
    // Few values: the extremes themselves.
    const Range few = robust_range({-1, 3});
    EXPECT_DOUBLE_EQ(few.lo, -1);
    EXPECT_DOUBLE_EQ(few.hi, 3);
    EXPECT_DOUBLE_EQ(robust_range({}).hi, 0);
}

TEST(AnalysisRange, TheNoteSaysWhatLiesBeyondTheBar) {
    AnalysisView v;
    v.kind = AnalysisKind::gaussian;
    EXPECT_EQ(analysis_range_note(v), "");
    v.clipped = true;
    v.data_lo = -165;
    v.data_hi = 3.25f;
    EXPECT_EQ(analysis_range_note(v), "all values -165 .. 3.25; the bar spans 96% of them");
}
