#include "core/geom/gordon.hpp"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <numeric>

#include "core/geom/construct.hpp"
#include "core/geom/construct_common.hpp"
#include "core/geom/coons.hpp"
#include "core/geom/evaluate.hpp"
#include "core/geom/interpolate.hpp"
#include "core/geom/surface_sum.hpp"

namespace isoparm::geom {

namespace {

// Parameters of one family that must agree across the other family: within this of [0, 1].
constexpr double parameter_agreement = 1e-6;
// Two curves meet when their closest points are within this of the network's size.
constexpr double meeting_tolerance = 1e-6;
constexpr int start_samples = 64;
constexpr std::size_t max_network_pairs = 4096;

std::string at(const char* family, std::size_t k) {
    return std::string("/") + family + "/" + std::to_string(k);
}

// Equal weights describe the polynomial curve of the Cartesian points.
Expected<std::vector<Curve>> polynomial_family(const std::vector<Curve>& curves,
                                               const char* family) {
    if (curves.size() < 2)
        return make_error(ErrorCode::schema,
                          std::string("a Gordon network needs at least 2 ") + family + ", got " +
                              std::to_string(curves.size()),
                          std::string("/") + family);
    std::vector<Curve> out;
    for (std::size_t k = 0; k < curves.size(); ++k) {
        Curve c = curves[k];
        for (double w : c.weights)
            if (w != c.weights.front())
                return make_error(ErrorCode::weights,
                                  "a Gordon surface blends polynomial curves: this one has "
                                  "weights that differ",
                                  at(family, k));
        c.weights.assign(c.points.size(), 1.0);
        c.type = is_bezier(c.type) ? SplineType::bezier : SplineType::bspline;
        out.push_back(std::move(c));
    }
    auto compatible = make_compatible(out); // errors at "/curves/k": re-home them
    if (!compatible) {
        Error e = compatible.error();
        const std::string prefix = "/curves";
        if (e.path.rfind(prefix, 0) == 0)
            e.path = std::string("/") + family + e.path.substr(prefix.size());
        return e;
    }
    return compatible;
}

// The closest points of C(u) and D(v) on [0, 1]^2: damped Newton on the gradient of
// |C - D|^2 / 2 from the nearest pairs and local minima of a sampled grid (two curves may pass
// close to each other in several places; the meeting is the deepest valley, not always the first
// found).
struct Meeting {
    double u = 0, v = 0, distance = 0;
};

Meeting polish(const Curve& C, const Curve& D, Meeting m) {
    // A step is taken only where it brings the curves closer (halved up to 20 times
    // otherwise), so the search never leaves its valley for a worse one.
    auto gap = [&](double u, double v) {
        return glm::length(*curve_point(C, u) - *curve_point(D, v));
    };
    for (int iteration = 0; iteration < 50 && m.distance > 0; ++iteration) {
        const auto c = *curve_derivatives(C, m.u, 2), d = *curve_derivatives(D, m.v, 2);
        const glm::dvec3 r = c[0] - d[0];
        const double g0 = glm::dot(r, c[1]), g1 = -glm::dot(r, d[1]);
        const double a = glm::dot(c[1], c[1]) + glm::dot(r, c[2]), b = -glm::dot(c[1], d[1]),
                     e = glm::dot(d[1], d[1]) - glm::dot(r, d[2]);
        const double det = a * e - b * b;
        if (!(std::abs(det) > 0)) break;
        double du = (e * g0 - b * g1) / det, dv = (a * g1 - b * g0) / det;
        bool moved = false;
        for (int halving = 0; halving < 20 && !moved; ++halving, du /= 2, dv /= 2) {
            const double u = std::clamp(m.u - du, 0.0, 1.0), v = std::clamp(m.v - dv, 0.0, 1.0);
            const double distance = gap(u, v);
            if (distance < m.distance) m = {u, v, distance}, moved = true;
        }
        if (!moved) break;
    }
    return m;
}

Meeting closest(const Curve& C, const Curve& D) {
    std::vector<glm::dvec3> cs(start_samples + 1), ds(start_samples + 1);
    for (int k = 0; k <= start_samples; ++k) {
        cs[k] = *curve_point(C, static_cast<double>(k) / start_samples);
        ds[k] = *curve_point(D, static_cast<double>(k) / start_samples);
    }
    // Starts: the 16 nearest grid pairs and the 16 deepest local minima of the grid (one per
    // valley, so that a near miss elsewhere cannot crowd out the meeting).
    const int n = start_samples + 1;
    auto distance = [&](int a, int b) { return glm::length(cs[a] - ds[b]); };
    std::vector<Meeting> nearest, valleys;
    for (int a = 0; a < n; ++a)
        for (int b = 0; b < n; ++b) {
            const Meeting here{static_cast<double>(a) / start_samples,
                               static_cast<double>(b) / start_samples, distance(a, b)};
            nearest.push_back(here);
            bool lowest = true;
            for (int da = -1; da <= 1 && lowest; ++da)
                for (int db = -1; db <= 1 && lowest; ++db) {
                    const int x = a + da, y = b + db;
                    if ((da || db) && x >= 0 && x < n && y >= 0 && y < n &&
                        distance(x, y) < here.distance)
                        lowest = false;
                }
            if (lowest) valleys.push_back(here);
        }
    std::vector<Meeting> grid;
    for (auto* list : {&nearest, &valleys}) {
        const std::size_t keep = std::min<std::size_t>(list->size(), 16);
        std::partial_sort(
            list->begin(), list->begin() + static_cast<long>(keep), list->end(),
            [](const Meeting& x, const Meeting& y) { return x.distance < y.distance; });
        grid.insert(grid.end(), list->begin(), list->begin() + static_cast<long>(keep));
    }
    const std::size_t starts = grid.size();
    Meeting best{0, 0, INFINITY};
    for (std::size_t k = 0; k < starts; ++k) {
        const Meeting m = polish(C, D, grid[k]);
        if (m.distance < best.distance) best = m;
    }
    return best;
}

double network_size(const std::vector<Curve>& a, const std::vector<Curve>& b) {
    const glm::dvec3 origin = a.front().points.front();
    double size = 0;
    for (const auto* family : {&a, &b})
        for (const Curve& c : *family)
            for (const glm::dvec3& p : c.points) size = std::max(size, glm::length(p - origin));
    return size;
}

// The mean of one curve's meeting parameters, refused when they spread.
Expected<double> common_parameter(const std::vector<double>& params, const char* family,
                                  std::size_t index, const char* name) {
    const auto [lo, hi] = std::minmax_element(params.begin(), params.end());
    if (*hi - *lo > parameter_agreement)
        return make_error(ErrorCode::geometry,
                          std::string("this curve meets the other family at ") + name + " from " +
                              format_number(*lo) + " to " + format_number(*hi) +
                              ": a Gordon network needs one " + name + " per curve",
                          at(family, index));
    return std::accumulate(params.begin(), params.end(), 0.0) / static_cast<double>(params.size());
}

// Curves in increasing order of their parameters; equal parameters are refused.
Expected<std::vector<std::size_t>> order_by(const std::vector<double>& params, const char* family) {
    std::vector<std::size_t> order(params.size());
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(), [&](auto x, auto y) { return params[x] < params[y]; });
    for (std::size_t k = 1; k < order.size(); ++k)
        if (!(params[order[k]] > params[order[k - 1]]))
            return make_error(ErrorCode::geometry,
                              "two curves lie at the same parameter " +
                                  format_number(params[order[k]]),
                              at(family, order[k]));
    return order;
}

} // namespace

Expected<Gordon> gordon(const std::vector<Curve>& u_curves, const std::vector<Curve>& v_curves) {
    auto C = polynomial_family(u_curves, "u_curves");
    if (!C) return C.error();
    auto D = polynomial_family(v_curves, "v_curves");
    if (!D) return D.error();
    const std::size_t K = C->size(), L = D->size();
    // Every pair is searched on a 65 x 65 grid: bound the pairs, so a request stays in seconds.
    if (K * L > max_network_pairs)
        return make_error(ErrorCode::limit,
                          "a network of " + std::to_string(K) + " x " + std::to_string(L) +
                              " curves has more than " + std::to_string(max_network_pairs) +
                              " crossings to find",
                          "/v_curves");
    // The result has at least as many points per direction as its longest curve of that
    // direction: the caps are checked before the work (degree-1500 curves took 18 s to be
    // refused at the end).
    auto longest = [](const std::vector<Curve>& curves) {
        long n = 0;
        for (const Curve& c : curves) n = std::max(n, static_cast<long>(c.count()));
        return n;
    };
    if (Status st = construct_detail::check_result_size(longest(*C), longest(*D)); !st)
        return st.error();
    const double tolerance = meeting_tolerance * std::max(network_size(*C, *D), 1e-300);

    // meetings[k][l]: where u-curve k and v-curve l meet.
    std::vector<std::vector<Meeting>> meetings(K, std::vector<Meeting>(L));
    for (std::size_t k = 0; k < K; ++k)
        for (std::size_t l = 0; l < L; ++l) {
            meetings[k][l] = closest((*C)[k], (*D)[l]);
            if (!(meetings[k][l].distance <= tolerance))
                return make_error(ErrorCode::geometry,
                                  "this curve does not meet u-curve " + std::to_string(k) +
                                      " (closest distance " +
                                      format_number(meetings[k][l].distance) + ")",
                                  at("v_curves", l));
        }
    Gordon out;
    for (std::size_t l = 0; l < L; ++l) {
        std::vector<double> us;
        for (std::size_t k = 0; k < K; ++k) us.push_back(meetings[k][l].u);
        auto u = common_parameter(us, "v_curves", l, "u");
        if (!u) return u.error();
        out.u_params.push_back(*u);
    }
    for (std::size_t k = 0; k < K; ++k) {
        std::vector<double> vs;
        for (std::size_t l = 0; l < L; ++l) vs.push_back(meetings[k][l].v);
        auto v = common_parameter(vs, "u_curves", k, "v");
        if (!v) return v.error();
        out.v_params.push_back(*v);
    }
    // The boundary curves of each family must be there: the skins span their curves'
    // parameters and the curves of the other family span [0, 1].
    for (auto* params : {&out.u_params, &out.v_params}) {
        const char* family = params == &out.u_params ? "v_curves" : "u_curves";
        const auto [lo, hi] = std::minmax_element(params->begin(), params->end());
        if (!(*lo <= parameter_agreement) || !(*hi >= 1 - parameter_agreement))
            return make_error(ErrorCode::geometry,
                              std::string("the ") + family + " must include both boundary curves " +
                                  "(parameters 0 and 1); they run from " + format_number(*lo) +
                                  " to " + format_number(*hi),
                              std::string("/") + family);
        *lo = 0.0;
        *hi = 1.0;
    }
    auto u_order = order_by(out.u_params, "v_curves");
    if (!u_order) return u_order.error();
    auto v_order = order_by(out.v_params, "u_curves");
    if (!v_order) return v_order.error();

    // The families in parameter order, with their parameters.
    std::vector<Curve> Cs, Ds;
    std::vector<double> vs, us;
    for (std::size_t k : *v_order) Cs.push_back((*C)[k]), vs.push_back(out.v_params[k]);
    for (std::size_t l : *u_order) Ds.push_back((*D)[l]), us.push_back(out.u_params[l]);
    const int qv = std::min<int>(3, static_cast<int>(K) - 1),
              pu = std::min<int>(3, static_cast<int>(L) - 1);

    auto Pu = skin_compatible(Cs, qv, vs); // P_u(u, v_k) = C_k(u)
    if (!Pu) return Pu.error();
    auto Pv = skin_compatible(Ds, pu, us); // P_v'(v, u_l) = D_l(v)
    if (!Pv) return Pv.error();
    // T: the intersections, interpolated in u at the u_l (as P_v does) and in v at the v_k (as
    // P_u does), so that T cancels P_v on every u-curve and P_u on every v-curve.
    std::vector<Curve> rows;
    for (std::size_t k = 0; k < K; ++k) {
        Curve row;
        row.degree = pu;
        row.knots = averaged_knots(us, pu);
        row.weights.assign(L, 1.0);
        std::vector<double> data;
        for (std::size_t l : *u_order) {
            const Meeting& m = meetings[(*v_order)[k]][l];
            const glm::dvec3 q =
                0.5 * (*curve_point((*C)[(*v_order)[k]], m.u) + *curve_point((*D)[l], m.v));
            data.insert(data.end(), {q.x, q.y, q.z});
        }
        if (!solve_collocation(row.knots, pu, us, data, 3))
            return make_error(ErrorCode::geometry, "the intersection grid is singular",
                              "/v_curves");
        for (std::size_t l = 0; l < L; ++l)
            row.points.push_back({data[3 * l], data[3 * l + 1], data[3 * l + 2]});
        rows.push_back(std::move(row));
    }
    auto T = skin_compatible(rows, qv, vs);
    if (!T) return T.error();
    auto sum =
        sum_of_surfaces({{1.0, Pu->surface}, {1.0, transposed(Pv->surface)}, {-1.0, T->surface}});
    if (!sum) return sum.error();
    out.surface = std::move(sum).value();
    out.surface.type = SplineType::bspline;
    return out;
}

} // namespace isoparm::geom
