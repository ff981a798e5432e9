#include "core/geom/convert.hpp"

#include <functional>

#include "core/geom/knots.hpp"
#include "core/geom/refine.hpp"
#include "core/geom/validate.hpp"

namespace isoparm::geom {

namespace {

// Equal weights describe the polynomial object of the Cartesian points: they may go.
Status drop_equal_weights(std::vector<double>& weights,
                          const std::function<std::string(std::size_t)>& path_of) {
    for (std::size_t k = 1; k < weights.size(); ++k)
        if (weights[k] != weights[0])
            return make_error(ErrorCode::weights,
                              "a non-rational type needs equal weights: weight " +
                                  format_number(weights[k]) + " differs from the first, " +
                                  format_number(weights[0]),
                              path_of(k));
    weights.assign(weights.size(), 1.0);
    return Ok{};
}

// The distinct knots strictly inside the domain.
std::vector<double> interior_breaks(const Knots& U, int p, int n) {
    std::vector<double> out;
    for (int k = p + 1; k < n; ++k)
        if (U[k] > U[p] && U[k] < U[n] && (out.empty() || out.back() != U[k])) out.push_back(U[k]);
    return out;
}

bool single_clamped_span(const Knots& U, int p, int n) {
    return n == p + 1 && is_clamped(U, p, n);
}

// Cuts at every break, left to right: each split leaves the right part to cut further.
template <class Shape, class Split>
Expected<std::vector<Shape>> cut(Shape whole, const std::vector<double>& breaks, Split split) {
    std::vector<Shape> pieces;
    for (double t : breaks) {
        auto halves = split(whole, t);
        if (!halves) return halves.error();
        pieces.push_back(std::move(halves->first));
        whole = std::move(halves->second);
    }
    pieces.push_back(std::move(whole));
    return pieces;
}

// A single clamped span: clamp() (a no-op when already clamped) then the one piece.
Expected<Curve> clamped(const Curve& c) {
    return is_clamped(c.knots, c.degree, c.count()) ? Expected<Curve>(c) : clamp(c);
}

Expected<Surface> clamped(const Surface& s) {
    Surface out = s;
    for (Dir dir : {Dir::u, Dir::v}) {
        if (is_clamped(out.knots(dir), out.degree(dir), out.count(dir))) continue;
        // Clamping a surface is clamping each of its lines (one implementation: clamp()).
        std::vector<Curve> lines;
        const int across = out.count(opposite(dir));
        for (int k = 0; k < across; ++k) {
            auto line = clamp(surface_line(out, dir, k));
            if (!line) return line.error();
            lines.push_back(std::move(line).value());
        }
        out = surface_from_lines(out, dir, lines);
    }
    return out;
}

} // namespace

Expected<std::vector<Curve>> convert(const Curve& c, SplineType to) {
    Curve base = c;
    if (is_rational(c.type) && !is_rational(to)) {
        if (Status st = drop_equal_weights(
                base.weights, [](std::size_t k) { return "/weights/" + std::to_string(k); });
            !st)
            return st.error();
    }
    if (!is_bezier(to) || single_clamped_span(base.knots, base.degree, base.count())) {
        base.type = to;
        return std::vector<Curve>{base};
    }
    auto whole = clamped(base);
    if (!whole) return whole.error();
    auto pieces = cut(*whole, interior_breaks(whole->knots, whole->degree, whole->count()),
                      [](const Curve& x, double t) { return split(x, t); });
    if (!pieces) return pieces.error();
    for (Curve& p : *pieces) p.type = to;
    return pieces;
}

Expected<std::vector<Surface>> convert(const Surface& s, SplineType to) {
    Surface base = s;
    if (is_rational(s.type) && !is_rational(to)) {
        const int n_v = s.n_v;
        if (Status st = drop_equal_weights(base.weights,
                                           [n_v](std::size_t k) {
                                               return "/weights/" + std::to_string(k / n_v) + "/" +
                                                      std::to_string(k % n_v);
                                           });
            !st)
            return st.error();
    }
    if (!is_bezier(to) || (single_clamped_span(base.knots_u, base.degree_u, base.n_u) &&
                           single_clamped_span(base.knots_v, base.degree_v, base.n_v))) {
        base.type = to;
        return std::vector<Surface>{base};
    }
    auto whole = clamped(base);
    if (!whole) return whole.error();
    const double pieces_points =
        static_cast<double>(interior_breaks(whole->knots_u, whole->degree_u, whole->n_u).size() +
                            1) *
        static_cast<double>(interior_breaks(whole->knots_v, whole->degree_v, whole->n_v).size() +
                            1) *
        (whole->degree_u + 1) * (whole->degree_v + 1);
    if (pieces_points > static_cast<double>(max_points_per_surface))
        return make_error_nopath(ErrorCode::limit,
                                 "the Bezier patches would hold " + format_number(pieces_points) +
                                     " control points in all; at most " +
                                     std::to_string(max_points_per_surface) + " are allowed");
    auto strips = cut(*whole, interior_breaks(whole->knots_u, whole->degree_u, whole->n_u),
                      [](const Surface& x, double t) { return split(x, Dir::u, t); });
    if (!strips) return strips.error();
    std::vector<Surface> pieces;
    for (const Surface& strip : *strips) {
        auto cells = cut(strip, interior_breaks(strip.knots_v, strip.degree_v, strip.n_v),
                         [](const Surface& x, double t) { return split(x, Dir::v, t); });
        if (!cells) return cells.error();
        for (Surface& cell : *cells) {
            cell.type = to;
            pieces.push_back(std::move(cell));
        }
    }
    return pieces;
}

} // namespace isoparm::geom
