// The oriented sweep: placed copies of the profile along rotation-minimizing frames, skinned.
#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>

#include "core/geom/construct.hpp"
#include "core/geom/evaluate.hpp"
#include "core/geom/knots.hpp"
#include "core/geom/validate.hpp"

namespace isoparm::geom {

namespace {

// The reflection in the plane through the origin perpendicular to v (identity for v = 0).
glm::dmat3 reflection(const glm::dvec3& v) {
    const double c = glm::dot(v, v);
    glm::dmat3 H(1.0);
    if (c == 0.0) return H;
    return H - (2.0 / c) * glm::outerProduct(v, v);
}

// Samples of the trajectory at equal arc-length spacing (from a polyline four times finer,
// inverted linearly), with unit tangents. Equal arc length rather than equal parameter steps
// keeps the placed copies' control points smooth functions of v even where the trajectory's
// speed is only continuous (the joins of a rational circle's quarter arcs), so the skin
// converges at its full order. A tangent that vanishes (a cusp, a stationary point) is taken
// from the chord to a neighbour, then from a neighbouring sample.
struct Track {
    std::vector<double> t;
    std::vector<glm::dvec3> X, tangent;
};

Expected<Track> sample_track(const Curve& T, int steps) {
    const Interval dom = domain(T);
    auto point_at = [&](double t) -> Expected<glm::dvec3> {
        const auto X = curve_point(T, t);
        if (!X) {
            return make_error(ErrorCode::weights,
                              "the trajectory has no point at " + format_number(t) +
                                  " (its weights there sum to zero)",
                              "/trajectory/weights");
        }
        return *X;
    };
    const int fine = 4 * steps;
    std::vector<double> ft(fine + 1), length(fine + 1, 0.0);
    glm::dvec3 last{};
    for (int f = 0; f <= fine; ++f) {
        ft[f] = f == fine ? dom.hi : dom.lo + (dom.hi - dom.lo) * f / fine;
        auto X = point_at(ft[f]);
        if (!X) return X.error();
        if (f > 0) length[f] = length[f - 1] + glm::distance(*X, last);
        last = *X;
    }
    const double L = length.back();
    if (!(L > 0.0) || !std::isfinite(L)) {
        return make_error(ErrorCode::geometry,
                          "the trajectory is a single point, so it has no direction to follow",
                          "/trajectory");
    }
    Track tr;
    tr.t.resize(steps + 1);
    tr.X.resize(steps + 1);
    tr.tangent.assign(steps + 1, glm::dvec3(0.0));
    std::vector<bool> known(steps + 1, false);
    for (int m = 0; m <= steps; ++m) {
        const double target = L * m / steps;
        int f = static_cast<int>(std::lower_bound(length.begin(), length.end(), target) -
                                 length.begin());
        f = std::clamp(f, 1, fine);
        const double span = length[f] - length[f - 1];
        const double alpha =
            span > 0.0 ? std::clamp((target - length[f - 1]) / span, 0.0, 1.0) : 1.0;
        tr.t[m] = m == 0 ? dom.lo : m == steps ? dom.hi : ft[f - 1] + alpha * (ft[f] - ft[f - 1]);
        const auto d = curve_derivatives(T, tr.t[m], 1);
        if (!d) return point_at(tr.t[m]).error();
        tr.X[m] = (*d)[0];
        const double len = glm::length((*d)[1]);
        if (len > 0.0 && std::isfinite(len)) {
            tr.tangent[m] = (*d)[1] / len;
            known[m] = true;
        }
    }
    for (int m = 0; m <= steps; ++m) { // chords where the derivative vanished
        if (known[m]) continue;
        const glm::dvec3 chord = m < steps ? tr.X[m + 1] - tr.X[m] : tr.X[m] - tr.X[m - 1];
        const double len = glm::length(chord);
        if (len > 0.0) {
            tr.tangent[m] = chord / len;
            known[m] = true;
        }
    }
    const auto first = std::find(known.begin(), known.end(), true);
    if (first == known.end()) {
        return make_error(ErrorCode::geometry, "the trajectory has no direction at any sample",
                          "/trajectory");
    }
    for (int m = static_cast<int>(first - known.begin()) - 1; m >= 0; --m)
        tr.tangent[m] = tr.tangent[m + 1];
    for (int m = 1; m <= steps; ++m)
        if (!known[m]) tr.tangent[m] = tr.tangent[m - 1];
    return tr;
}

} // namespace

Expected<OrientedSweep> oriented_sweep(const Curve& profile, const Curve& trajectory,
                                       const OrientedSweepOptions& options) {
    const int K = options.sections;
    if (K < 1 || K + 1 > max_points_per_direction) {
        return make_error(ErrorCode::schema,
                          "the number of sections must lie between 1 and " +
                              std::to_string(max_points_per_direction - 1) + ", got " +
                              std::to_string(K),
                          "/sections");
    }
    const int degree = options.degree == 0 ? std::min(3, K) : options.degree;
    if (degree < 1 || degree > std::min(3, K)) {
        return make_error(ErrorCode::schema,
                          "the sweep's v-degree must lie between 1 and " +
                              std::to_string(std::min(3, K)) + ", got " +
                              std::to_string(options.degree),
                          "/degree");
    }
    const int S = std::max(1, options.substeps), M = K * S;
    auto track = sample_track(trajectory, M);
    if (!track) return track.error();
    const Track& tr = *track;

    // Double reflection (Wang et al. 2008, Algorithm 1) applied to the whole frame: R[m] maps
    // the frame at the start to the frame at t_m. The first reflection takes t_m across the
    // chord's bisecting plane, the second turns it onto the tangent at t_m+1; their product is
    // a rotation, so R[m] stays orthogonal, and the rotation about the tangent is minimal.
    std::vector<glm::dmat3> R(M + 1, glm::dmat3(1.0));
    for (int m = 0; m < M; ++m) {
        const glm::dmat3 H1 = reflection(tr.X[m + 1] - tr.X[m]);
        const glm::dvec3 tL = H1 * tr.tangent[m];
        const glm::dmat3 H2 = reflection(tr.tangent[m + 1] - tL);
        R[m + 1] = H2 * H1 * R[m];
    }

    // Copies at t_k = t_{kS} (equal arc-length steps, skinned at uniform v_k = k / K): X(t_k) + R_k
    // (P - X(a)), a rigid motion, exact on the rational profile (applied to its control points,
    // weights kept).
    std::vector<Curve> copies(K + 1, profile);
    for (int k = 0; k <= K; ++k) {
        const int m = k * S;
        for (int i = 0; i < profile.count(); ++i)
            copies[k].points[i] = tr.X[m] + R[m] * (profile.points[i] - tr.X[0]);
        if (k == 0) copies[k].points = profile.points;
    }
    auto skinned = skin(copies, degree, Parametrization::uniform);
    if (!skinned) {
        Error e = skinned.error();
        e.has_path = false;
        e.path.clear();
        return e;
    }
    OrientedSweep out;
    out.sections = K;
    out.skinned = std::move(skinned).value();

    // The deviation: the skin S(u, v) against the ideal S*(u, t(v)) = X(t) + R(t) (P(u) - X(a))
    // at every frame sample (v = m / M at arc length m / M of the trajectory, t = t_m) and
    // samples_u + 1 profile parameters; the skin's u is the profile's domain mapped to [0, 1].
    const Interval pd = domain(profile);
    const int NU = std::max(2, options.samples_u);
    for (int a = 0; a <= NU; ++a) {
        const double u01 = static_cast<double>(a) / NU;
        const double u = a == NU ? pd.hi : pd.lo + (pd.hi - pd.lo) * u01;
        const auto P = curve_point(profile, u);
        if (!P) continue;
        for (int m = 0; m <= M; ++m) {
            const double v = static_cast<double>(m) / M;
            const auto Sp = surface_point(out.skinned.surface, u01, v);
            if (!Sp) continue;
            const glm::dvec3 ideal = tr.X[m] + R[m] * (*P - tr.X[0]);
            const double dev = glm::distance(*Sp, ideal);
            if (dev > out.max_deviation) {
                out.max_deviation = dev;
                out.deviation_u = u01;
                out.deviation_v = v;
            }
        }
    }
    return out;
}

} // namespace isoparm::geom
