#include "core/geom/surface_sum.hpp"

#include <algorithm>
#include <map>

#include "core/geom/construct_common.hpp"
#include "core/geom/refine.hpp"

namespace isoparm::geom {

namespace {

std::map<double, int> multiplicities(const Knots& U) {
    std::map<double, int> m;
    for (double t : U) ++m[t];
    return m;
}

} // namespace

Expected<Surface> sum_of_surfaces(const std::vector<std::pair<double, Surface>>& terms) {
    int p = 0, q = 0;
    for (const auto& [factor, s] : terms) {
        p = std::max(p, s.degree_u);
        q = std::max(q, s.degree_v);
    }
    std::vector<Surface> raised;
    for (const auto& [factor, s] : terms) {
        Surface r = s;
        if (r.degree_u < p) {
            auto e = elevate_degree(r, Dir::u, p - r.degree_u);
            if (!e) return e.error();
            r = std::move(e).value();
        }
        if (r.degree_v < q) {
            auto e = elevate_degree(r, Dir::v, q - r.degree_v);
            if (!e) return e.error();
            r = std::move(e).value();
        }
        raised.push_back(std::move(r));
    }
    for (Dir dir : {Dir::u, Dir::v}) {
        std::map<double, int> merged;
        for (const Surface& r : raised)
            for (const auto& [t, m] : multiplicities(r.knots(dir)))
                merged[t] = std::max(merged[t], m);
        for (Surface& r : raised) {
            const std::map<double, int> own = multiplicities(r.knots(dir));
            for (const auto& [t, m] : merged) {
                const auto it = own.find(t);
                const int missing = m - (it == own.end() ? 0 : it->second);
                if (missing <= 0) continue;
                auto refined = insert_knot(r, dir, t, missing);
                if (!refined) return refined.error();
                r = std::move(refined).value();
            }
        }
    }
    Surface sum = raised.front();
    if (Status st = construct_detail::check_result_size(sum.n_u, sum.n_v); !st) return st.error();
    for (std::size_t k = 0; k < sum.points.size(); ++k) {
        glm::dvec3 p_sum(0.0);
        for (std::size_t term = 0; term < raised.size(); ++term)
            p_sum += terms[term].first * raised[term].points[k];
        sum.points[k] = p_sum;
    }
    return sum;
}

} // namespace isoparm::geom
