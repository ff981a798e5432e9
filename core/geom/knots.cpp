// Knot vector validation, spans and multiplicities (exact comparisons throughout).
#include "core/geom/knots.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace isoparm::geom {

Status validate_knots(const Knots& U, int p, int n) {
    const size_t expected = static_cast<size_t>(n) + p + 1;
    if (U.size() != expected) {
        return make_error(ErrorCode::knots, "expected " + std::to_string(expected) +
                                                " knots, got " + std::to_string(U.size()));
    }
    for (size_t k = 0; k < U.size(); ++k) {
        if (!std::isfinite(U[k])) {
            return make_error(ErrorCode::knots,
                              "knot " + std::to_string(k) + " must be a finite number",
                              pointer_step(static_cast<long>(k)));
        }
    }
    int run = 1;
    for (size_t k = 1; k < U.size(); ++k) {
        if (U[k] < U[k - 1]) {
            return make_error(ErrorCode::knots,
                              "knot vector must be non-decreasing: knot " + std::to_string(k) +
                                  " (" + format_number(U[k]) + ") < knot " + std::to_string(k - 1) +
                                  " (" + format_number(U[k - 1]) + ")",
                              pointer_step(static_cast<long>(k)));
        }
        run = U[k] == U[k - 1] ? run + 1 : 1;
        if (run > p + 1) {
            return make_error(
                ErrorCode::knots,
                "knot " + format_number(U[k]) + " appears " + std::to_string(run) +
                    " times; the multiplicity may not exceed degree + 1 = " + std::to_string(p + 1),
                pointer_step(static_cast<long>(k)));
        }
    }
    if (!(U[p] < U[n])) {
        return make_error(ErrorCode::knots, "the domain [knot " + std::to_string(p) + ", knot " +
                                                std::to_string(n) + "] = [" + format_number(U[p]) +
                                                ", " + format_number(U[n]) + "] is empty");
    }
    return Ok{};
}

int find_span(const Knots& U, int p, int n, double t) {
    assert(U[p] <= t && t <= U[n]);
    // End of the domain: the left limit, i.e. the last non-empty span ending at U[n].
    if (t >= U[n]) {
        int s = n - 1;
        while (s > p && U[s] == U[n]) --s;
        return s;
    }
    // Binary search for U[s] <= t < U[s+1] with s in [p, n-1] (Piegl & Tiller A2.1).
    auto it = std::upper_bound(U.begin() + p, U.begin() + n + 1, t);
    return static_cast<int>(it - U.begin()) - 1;
}

int multiplicity(const Knots& U, double t) {
    auto [lo, hi] = std::equal_range(U.begin(), U.end(), t);
    return static_cast<int>(hi - lo);
}

bool is_clamped(const Knots& U, int p, int n) {
    for (int k = 0; k < p; ++k)
        if (U[k] != U[p]) return false;
    for (int k = n + 1; k <= n + p; ++k)
        if (U[k] != U[n]) return false;
    return true;
}

std::vector<KnotRun> knot_runs(const Knots& U) {
    std::vector<KnotRun> runs;
    for (size_t k = 0; k < U.size(); ++k) {
        if (!runs.empty() && runs.back().value == U[k]) {
            ++runs.back().multiplicity;
        } else {
            runs.push_back({U[k], 1, static_cast<int>(k)});
        }
    }
    return runs;
}

Knots clamped_uniform_knots(int n, int p, double a, double b) {
    assert(n >= p + 1 && p >= 1);
    Knots U(static_cast<size_t>(n) + p + 1);
    const int interior = n - p - 1;
    for (int k = 0; k <= p; ++k) {
        U[k] = a;
        U[n + k] = b;
    }
    for (int k = 1; k <= interior; ++k) {
        U[p + k] = a + (b - a) * k / (interior + 1);
    }
    return U;
}

Knots bezier_knots(int p, double a, double b) {
    Knots U(2 * static_cast<size_t>(p) + 2, a);
    std::fill(U.begin() + p + 1, U.end(), b);
    return U;
}

std::string continuity_text(int degree, int multiplicity) {
    const int c = continuity_at_knot(degree, multiplicity);
    if (c < 0) return "not continuous here (C-1): the pieces need not meet";
    std::string text = "C" + std::to_string(c) + " here";
    if (c == 0) text += ": the pieces meet, a corner may appear";
    return text;
}

double greville_abscissa(const Knots& U, int p, int i) {
    double g = 0;
    for (int k = 1; k <= p; ++k) g += (U[i + k] - g) / k;
    return g;
}

} // namespace isoparm::geom
