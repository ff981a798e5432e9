// De Boor's algorithm keeping every intermediate point (Piegl & Tiller eq. 5.10-5.12).
#include "core/geom/deboor.hpp"

#include "core/geom/knots.hpp"

namespace isoparm::geom {

std::optional<glm::dvec3> DeBoorTriangle::cartesian(const HPoint& h) {
    if (h.w == 0.0) return std::nullopt;
    return glm::dvec3(h) / h.w;
}

DeBoorTriangle deboor_polar(const Knots& U, int p, const std::vector<HPoint>& Pw, int span,
                            const std::vector<double>& args) {
    DeBoorTriangle tri;
    tri.span = span;
    tri.first_index = span - p;
    tri.levels.resize(p + 1);
    tri.levels[0].assign(Pw.begin() + tri.first_index, Pw.begin() + span + 1);
    // Level k, entry r stands for P_i^k with i = s - p + k + r:
    // P_i^k = (1 - a) P_{i-1}^{k-1} + a P_i^{k-1},  a = (t_k - U_i) / (U_{i+p+1-k} - U_i).
    // On the span s the denominators are positive (U_{i+p+1-k} >= U_{s+1} > U_s >= U_i), so
    // this is right at knots of any multiplicity. Outside [0, 1] (a blossom's arguments may be
    // anywhere) (1 - a) and a are large and of opposite signs, and their terms would cancel
    // what is equal in both points (the line from (0, 1) to (1, 1) at 1e16 would lose its
    // y = 1, and every weight its exact 1): there it is the nearer point plus the difference.
    for (int k = 1; k <= p; ++k) {
        const double t = args[k - 1];
        const auto& prev = tri.levels[k - 1];
        auto& cur = tri.levels[k];
        cur.resize(p + 1 - k);
        for (int r = 0; r <= p - k; ++r) {
            const int i = span - p + k + r;
            const double a = (t - U[i]) / (U[i + p + 1 - k] - U[i]);
            if (a >= 0.0 && a <= 1.0)
                cur[r] = (1.0 - a) * prev[r] + a * prev[r + 1];
            else if (a > 1.0)
                cur[r] = prev[r + 1] + (a - 1.0) * (prev[r + 1] - prev[r]);
            else
                cur[r] = prev[r] + a * (prev[r + 1] - prev[r]);
        }
    }
    return tri;
}

DeBoorTriangle deboor_homogeneous(const Knots& U, int p, const std::vector<HPoint>& Pw, double t) {
    const int span = find_span(U, p, static_cast<int>(Pw.size()), t);
    return deboor_polar(U, p, Pw, span, std::vector<double>(p, t));
}

DeBoorTriangle deboor_curve(const Curve& c, double t) {
    std::vector<HPoint> Pw(c.count());
    for (int i = 0; i < c.count(); ++i) Pw[i] = c.hpoint(i);
    return deboor_homogeneous(c.knots, c.degree, Pw, t);
}

DeBoorSurfaceTrace deboor_surface(const Surface& s, double u, double v) {
    DeBoorSurfaceTrace trace;
    trace.u_stage.reserve(s.n_v);
    std::vector<HPoint> column(s.n_u), results(s.n_v);
    for (int j = 0; j < s.n_v; ++j) {
        for (int i = 0; i < s.n_u; ++i) column[i] = s.hpoint(i, j);
        trace.u_stage.push_back(deboor_homogeneous(s.knots_u, s.degree_u, column, u));
        results[j] = trace.u_stage.back().levels.back().front();
    }
    trace.v_stage = deboor_homogeneous(s.knots_v, s.degree_v, results, v);
    return trace;
}

std::optional<glm::dvec3> DeBoorSurfaceTrace::point() const {
    return DeBoorTriangle::cartesian(v_stage.levels.back().front());
}

} // namespace isoparm::geom
