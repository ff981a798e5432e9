// The `basis` op: all n B-spline (or rational) basis functions and derivatives at a parameter.
#include <cmath>

#include "core/geom/basis.hpp"
#include "core/geom/evaluate.hpp"
#include "core/geom/knots.hpp"
#include "core/geom/validate.hpp"
#include "core/json/fields.hpp"
#include "core/protocol/detail.hpp"

namespace isoparm::protocol {

using geom::ErrorCode;
using geom::Expected;

namespace {

json numbers(const std::vector<double>& v) {
    json a = json::array();
    for (double x : v) a.push_back(x);
    return a;
}

} // namespace

OpResult op_basis(const json& request) {
    if (geom::Status s =
            check_fields(request, "basis", {"degree", "knots", "param", "weights", "derivatives"});
        !s)
        return s.error();

    // Degree first (an integer >= 1), then the knots validated as a curve's would be.
    const json* degree = find_member(request, "degree");
    if (!degree) return missing_member("", "degree");
    const std::optional<std::int64_t> p64 = integer_value(*degree);
    if (!p64) return schema_error("the degree is an integer", "/degree");
    if (*p64 < 1)
        return geom::make_error(ErrorCode::degree, "the degree must be at least 1", "/degree");

    const json* knots = find_member(request, "knots");
    if (!knots) return missing_member("", "knots");
    if (!knots->is_array()) return schema_error("knots is an array of numbers", "/knots");
    geom::Knots U;
    U.reserve(knots->size());
    for (std::size_t k = 0; k < knots->size(); ++k) {
        Expected<double> t = read_finite((*knots)[k], "/knots/" + std::to_string(k), "a knot");
        if (!t) return t.error();
        U.push_back(*t);
    }
    // n = len(knots) - degree - 1 functions (convention 12); a curve needs n >= degree + 1.
    const auto len = static_cast<std::int64_t>(U.size());
    if (len < 2 * *p64 + 2) {
        return geom::make_error(ErrorCode::knots,
                                "degree " + std::to_string(*p64) + " needs at least " +
                                    std::to_string(2 * *p64 + 2) + " knots, got " +
                                    std::to_string(len),
                                "/knots");
    }
    const int p = static_cast<int>(*p64);
    const int n = static_cast<int>(len - p - 1);
    if (n > geom::max_points_per_direction) {
        return geom::make_error(ErrorCode::limit,
                                "too many basis functions (" + std::to_string(n) + " > " +
                                    std::to_string(geom::max_points_per_direction) + ")",
                                "/knots");
    }
    if (geom::Status s = geom::validate_knots(U, p, n); !s) return s.error().under("/knots");

    std::vector<double> w;
    const json* weights = find_member(request, "weights");
    if (weights) {
        if (!weights->is_array() || weights->size() != static_cast<std::size_t>(n)) {
            return geom::make_error(ErrorCode::weights,
                                    "expected " + std::to_string(n) +
                                        " weights (one per basis "
                                        "function)",
                                    "/weights");
        }
        for (std::size_t i = 0; i < weights->size(); ++i) {
            const json& x = (*weights)[i];
            if (!x.is_number() || !std::isfinite(x.get<double>())) {
                return geom::make_error(ErrorCode::weights, "a weight must be a finite number",
                                        "/weights/" + std::to_string(i));
            }
            w.push_back(x.get<double>());
        }
    }

    Expected<std::int64_t> d = integer_option(
        request, "derivatives", 0, 0, geom::max_derivative_order, "derivatives is an integer 0..3");
    if (!d) return d.error();
    Expected<double> t = required_number(request, "param");
    if (!t) return t.error();
    if (geom::Status s = check_in_domain(*t, geom::domain(U, p, n), "/param"); !s) return s.error();

    const int order = static_cast<int>(*d);
    std::vector<std::vector<double>> values;
    if (weights) {
        auto R = geom::rational_basis(U, p, w, *t, order);
        const auto finite = [](const std::vector<std::vector<double>>& rows) {
            for (const auto& row : rows)
                for (double x : row)
                    if (!std::isfinite(x)) return false;
            return true;
        };
        if (!R || !finite(*R)) {
            // No rational basis exists where sum N_i w_i = 0 (convention 7's missing point).
            return geom::make_error(
                ErrorCode::weights,
                "the weighted sum of the basis functions is zero (or too close to "
                "zero) at " +
                    geom::format_number(*t) + ", so the rational basis does not exist there",
                "/weights");
        }
        values = std::move(*R);
    } else {
        values = geom::all_basis(U, p, n, *t, order);
    }
    json out = {{"values", numbers(values[0])}};
    if (order >= 1) {
        json ders = json::array();
        for (int k = 1; k <= order; ++k)
            ders.push_back(numbers(values[static_cast<std::size_t>(k)]));
        out["derivatives"] = std::move(ders);
    }
    return out;
}

} // namespace isoparm::protocol
