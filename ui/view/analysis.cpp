// Analysis display: the automatic colour range and the colour maps of the colour bar.
#include "ui/view/analysis.hpp"

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>
#include <iterator>
#include <limits>
#include <variant>
#include <vector>

#include "core/geom/implicit/curvature.hpp"
#include "core/geom/status.hpp"
#include "ui/view/implicit_meshes.hpp"

#include "core/geom/curvature.hpp"

namespace isoparm::ui {

namespace {

constexpr int range_samples = 17;

} // namespace

Range robust_range(std::vector<double> values, double tail) {
    Range r;
    if (values.empty()) return r;
    std::sort(values.begin(), values.end());
    const std::size_t n = values.size();
    r.all_lo = values.front();
    r.all_hi = values.back();
    // Nearest-rank percentiles: with few values the ends are the extremes themselves.
    const auto at = [&](double q) {
        const double pos = q * static_cast<double>(n - 1);
        return values[static_cast<std::size_t>(
            std::clamp(std::round(pos), 0.0, static_cast<double>(n - 1)))];
    };
    r.lo = at(tail);
    r.hi = at(1 - tail);
    return r;
}

std::string analysis_range_note(const AnalysisView& v) {
    if (!is_curvature(v.kind) || !v.clipped) return "";
    return "all values " + geom::format_short(v.data_lo, 3) + " .. " +
           geom::format_short(v.data_hi, 3) + (v.fixed ? "" : "; the bar spans 96% of them");
}

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

std::vector<double> implicit_vertex_curvature(const doc::ImplicitObject& o, const geom::Mesh& mesh,
                                              AnalysisKind kind, std::size_t stride) {
    stride = std::max<std::size_t>(stride, 1);
    const std::size_t n = (mesh.positions.size() + stride - 1) / stride;
    std::vector<double> out(n, std::numeric_limits<double>::quiet_NaN());
    const auto program = geom::implicit::compile(o.expression, o.parameter_names);
    if (!program) return out;
    const double* params = o.parameter_values.empty() ? nullptr : o.parameter_values.data();
    const geom::CurvatureKind k = curvature_kind(kind);
    for (std::size_t q = 0; q < n; ++q)
        out[q] = geom::implicit::implicit_curvature_value(*program, mesh.positions[q * stride], k,
                                                          params);
    return out;
}

AnalysisView analysis_view(const doc::Document& doc, const ImplicitMeshes* implicit) {
    const doc::DisplaySettings& d = doc.view.display;
    AnalysisView v;
    v.kind = analysis_kind(d.analysis);
    v.stripes = d.stripes;
    v.zebra_angle = static_cast<float>(d.zebra_angle);
    v.diverging = v.kind == AnalysisKind::gaussian || v.kind == AnalysisKind::mean;
    if (!is_curvature(v.kind)) return v;
    double lo = 0, hi = 0;
    std::vector<double> values;
    // The range of the kinds the 3D view colours by curvature: surfaces (a grid of samples)
    // and implicit surfaces (their meshes' vertices).
    auto add_surface = [&](const geom::Surface& s) {
        for (double k :
             geom::curvature_grid(s, range_samples, range_samples, curvature_kind(v.kind)))
            if (std::isfinite(k)) values.push_back(k);
    };
    auto add_implicit = [&](const doc::Object& o, const doc::ImplicitObject& im) {
        const ImplicitMeshes::View mv = implicit ? implicit->drawn(o.id) : ImplicitMeshes::View{};
        if (!mv.mesh || mv.mesh->positions.empty()) return;
        const std::size_t stride = std::max<std::size_t>(mv.mesh->positions.size() / 300, 1);
        for (double k : implicit_vertex_curvature(im, *mv.mesh, v.kind, stride))
            if (std::isfinite(k)) values.push_back(k);
    };
    for (const doc::Object& o : doc.objects) {
        if (!o.visible) continue;
        std::visit(doc::overloaded{
                       [&](const doc::SurfaceObject& s) { add_surface(s.surface); },
                       [](const doc::CurveObject&) {},
                       [&](const doc::ImplicitObject& im) { add_implicit(o, im); },
                       [](const doc::TriangleObject&) {},
                   },
                   o.shape);
    }
    const Range robust = robust_range(values);
    v.data_lo = static_cast<float>(robust.all_lo);
    v.data_hi = static_cast<float>(robust.all_hi);
    if (d.analysis_fixed) {
        v.fixed = true;
        lo = d.analysis_lo;
        hi = d.analysis_hi;
    } else {
        lo = robust.lo;
        hi = robust.hi;
        if (v.diverging) {
            const double m = std::max(std::abs(lo), std::abs(hi));
            lo = -m;
            hi = m;
        }
    }
    v.clipped = !values.empty() && (robust.all_lo < lo || robust.all_hi > hi);
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

namespace {

// The colour bar's title of each kind ("" when off), in declaration order.
constexpr const char* analysis_titles[] = {
    "",
    "K (Gaussian curvature)",
    "H (mean curvature)",
    "k1 (largest principal curvature)",
    "k2 (smallest principal curvature)",
    "zebra stripes",
    "isophotes",
};
static_assert(std::size(analysis_titles) == static_cast<std::size_t>(AnalysisKind::isophote) + 1);

} // namespace

std::string analysis_title(AnalysisKind kind) {
    const auto k = static_cast<std::size_t>(kind);
    return k < std::size(analysis_titles) ? analysis_titles[k] : "";
}

} // namespace isoparm::ui
