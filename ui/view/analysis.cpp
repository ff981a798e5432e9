// Analysis display: the automatic colour range and the colour maps of the colour bar.
#include "ui/view/analysis.hpp"

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>

#include "core/geom/curvature.hpp"

namespace isoparm::ui {

namespace {

constexpr int range_samples = 17;

} // namespace

// The view's kinds are the document's modes in the same order.
static_assert(static_cast<int>(AnalysisKind::isophote) ==
              static_cast<int>(doc::AnalysisMode::isophote));

geom::CurvatureKind curvature_kind(AnalysisKind k) {
    switch (k) {
    case AnalysisKind::mean:
        return geom::CurvatureKind::mean;
    case AnalysisKind::kmax:
        return geom::CurvatureKind::k_max;
    case AnalysisKind::kmin:
        return geom::CurvatureKind::k_min;
    default:
        return geom::CurvatureKind::gaussian;
    }
}

AnalysisKind analysis_kind(doc::AnalysisMode mode) {
    return static_cast<AnalysisKind>(static_cast<int>(mode));
}

AnalysisView analysis_view(const doc::Document& doc) {
    const doc::DisplaySettings& d = doc.view.display;
    AnalysisView v;
    v.kind = analysis_kind(d.analysis);
    v.stripes = d.stripes;
    v.zebra_angle = static_cast<float>(d.zebra_angle);
    v.diverging = v.kind == AnalysisKind::gaussian || v.kind == AnalysisKind::mean;
    if (!is_curvature(v.kind)) return v;
    double lo = 0, hi = 0;
    if (d.analysis_fixed) {
        lo = d.analysis_lo;
        hi = d.analysis_hi;
    } else {
        bool any = false;
        for (const doc::Object& o : doc.objects) {
            const geom::Surface* s = o.surface();
            if (!s || !o.visible) continue;
            for (double k :
                 geom::curvature_grid(*s, range_samples, range_samples, curvature_kind(v.kind))) {
                if (!std::isfinite(k)) continue;
                lo = any ? std::min(lo, k) : k;
                hi = any ? std::max(hi, k) : k;
                any = true;
            }
        }
        if (v.diverging) {
            const double m = std::max(std::abs(lo), std::abs(hi));
            lo = -m;
            hi = m;
        }
    }
    if (!(hi - lo > 1e-12)) {
        const double mid = 0.5 * (lo + hi);
        lo = mid - 1e-12;
        hi = mid + 1e-12;
    }
    v.lo = static_cast<float>(lo);
    v.hi = static_cast<float>(hi);
    return v;
}

glm::vec3 analysis_colour(const AnalysisView& view, double value) {
    if (view.diverging) {
        const double m = std::max(std::abs(view.lo), std::abs(view.hi));
        const float t = static_cast<float>(std::clamp(m > 0 ? value / m : 0.0, -1.0, 1.0));
        const glm::vec3 cool(0.23f, 0.30f, 0.75f), mid(0.87f), warm(0.71f, 0.02f, 0.15f);
        return t < 0 ? glm::mix(mid, cool, -t) : glm::mix(mid, warm, t);
    }
    const double w = view.hi - view.lo;
    const float t = static_cast<float>(std::clamp(w > 0 ? (value - view.lo) / w : 0.5, 0.0, 1.0));
    const glm::vec3 a(0.27f, 0.0f, 0.33f), b(0.13f, 0.57f, 0.55f), c(0.99f, 0.91f, 0.14f);
    return t < 0.5f ? glm::mix(a, b, t * 2) : glm::mix(b, c, t * 2 - 1);
}

std::string analysis_title(AnalysisKind kind) {
    switch (kind) {
    case AnalysisKind::gaussian:
        return "K (Gaussian curvature)";
    case AnalysisKind::mean:
        return "H (mean curvature)";
    case AnalysisKind::kmax:
        return "k1 (largest principal curvature)";
    case AnalysisKind::kmin:
        return "k2 (smallest principal curvature)";
    case AnalysisKind::zebra:
        return "zebra stripes";
    case AnalysisKind::isophote:
        return "isophotes";
    case AnalysisKind::off:
        break;
    }
    return "";
}

} // namespace isoparm::ui
