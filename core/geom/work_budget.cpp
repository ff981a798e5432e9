// Work estimates and the budget they are checked against (see work_budget.hpp).
#include "core/geom/work_budget.hpp"

#include <algorithm>
#include <cmath>

namespace isoparm::geom {

namespace {

// What the current batch may still spend (only while a BatchBudget lives).
thread_local double batch_steps_left = max_work_steps;
thread_local bool batch_active = false;

double sq(double x) {
    return x * x;
}

// Derivative entries of a surface up to order d: the (d+1)(d+2)/2 partials a + b <= d.
double surface_terms(int d) {
    return (d + 1.0) * (d + 2.0) / 2.0;
}

} // namespace

WorkEstimate estimate_curve_evaluation(double count, int p, int d) {
    // Basis functions and their derivatives: (p + 1)^2 steps each order; the point and its
    // derivatives: (p + 1) per order.
    const double orders = d + 1.0;
    WorkEstimate e;
    e.steps = count * (sq(p + 1.0) * orders + (p + 1.0) * orders);
    // points: 3 numbers each; derivatives: d + 1 points per parameter.
    e.answer_numbers = count * 3 * (d >= 1 ? 1 + orders : 1);
    e.steps += e.answer_numbers * steps_per_answer_number;
    return e;
}

WorkEstimate estimate_surface_evaluation(double count, int p, int q, int d, bool normals) {
    const double orders = d + 1.0;
    // Normals need the first partials even without asked derivatives.
    const double terms = surface_terms(normals ? std::max(d, 1) : d);
    WorkEstimate e;
    e.steps = count * ((sq(p + 1.0) + sq(q + 1.0)) * orders + (p + 1.0) * (q + 1.0) * terms);
    // points, the (d+1) x (d+1) derivative table (nulls included), normals.
    e.answer_numbers = count * 3 * (1 + (d >= 1 ? orders * orders : 0) + (normals ? 1 : 0));
    e.steps += e.answer_numbers * steps_per_answer_number;
    return e;
}

WorkEstimate estimate_triangle_de_casteljau(double count, int n, int d, bool all_levels) {
    const double level_points = (n + 1.0) * (n + 2.0) * (n + 3.0) / 6; // every level's points
    const double nets = (d + 1.0) * (d + 2.0) / 2;
    WorkEstimate e;
    e.steps = count * level_points * 3 * nets;
    e.answer_numbers =
        all_levels ? count * level_points * 3 : count * 3 * (1 + (d >= 1 ? sq(d + 1.0) : 0));
    e.steps += e.answer_numbers * steps_per_answer_number;
    return e;
}

WorkEstimate estimate_tessellation(double n_u, double n_v, int p, int q) {
    WorkEstimate e;
    // Basis values and first derivatives once per grid line, then point and two partials per
    // grid point.
    e.steps = 2 * (n_u * sq(p + 1.0) + n_v * sq(q + 1.0)) + n_u * n_v * (p + 1.0) * (q + 1.0) * 3;
    // positions and normals (3 each per vertex), triangles (3 indices, two per cell).
    e.answer_numbers = n_u * n_v * 6 + (n_u - 1) * (n_v - 1) * 6;
    e.steps += e.answer_numbers * steps_per_answer_number;
    return e;
}

WorkEstimate estimate_polygonization(double grid_points, double instructions) {
    WorkEstimate e;
    // Every grid point runs the program (and the gradient at crossings, a fraction).
    e.steps = grid_points * std::max(1.0, instructions) * steps_per_expression_instruction;
    e.answer_numbers = 0; // unknown in advance: the mesh caps stop it while it runs
    return e;
}

WorkEstimate estimate_banded_fit(double rows, double n, int p, double columns) {
    WorkEstimate e;
    // Per data parameter: its basis, its products in the normal equations, the fitted curve
    // there (the errors of a least-squares fit): (p+1)^2 each. The factorization: p rows below
    // each pivot, each 3p + 1 wide; each right-hand side: forward and back, 3p + 1 a row.
    const double width = 3.0 * p + 1.0;
    e.steps = rows * 3 * sq(p + 1.0) + n * p * width + columns * n * width;
    // The control points and the parameters.
    e.answer_numbers = n * columns + rows;
    e.steps += e.answer_numbers * steps_per_answer_number;
    return e;
}

std::string with_thousands(double value) {
    if (!(value < 1e18)) return "more than 10^18";
    std::string digits = std::to_string(static_cast<long long>(std::llround(value)));
    std::string out;
    for (std::size_t k = 0; k < digits.size(); ++k) {
        if (k > 0 && (digits.size() - k) % 3 == 0) out += ',';
        out += digits[k];
    }
    return out;
}

namespace {

// How long `steps` take at about 1e8 a second: "10.3 s", "1,678 s".
std::string seconds(double steps) {
    const double s = steps / 1e8;
    if (s >= 100) return with_thousands(s) + " s";
    return geom::format_number(std::round(s * 10) / 10) + " s";
}

} // namespace

geom::Status spend_work(const WorkEstimate& cost, const std::string& path,
                        const std::string& what) {
    if (!(cost.answer_numbers <= max_answer_numbers)) {
        const double mib = cost.answer_numbers * bytes_per_answer_number / (1 << 20);
        return geom::make_error(geom::ErrorCode::limit,
                                what + " would make an answer of " +
                                    with_thousands(cost.answer_numbers) + " numbers (about " +
                                    with_thousands(mib) + " MiB); the work budget allows " +
                                    with_thousands(max_answer_numbers) + " (about 1 GiB)",
                                path);
    }
    if (!(cost.steps <= max_work_steps)) {
        return geom::make_error(geom::ErrorCode::limit,
                                what + " would take about " + with_thousands(cost.steps) +
                                    " basis steps (about " + seconds(cost.steps) +
                                    "); the work budget allows " + with_thousands(max_work_steps) +
                                    " (about 10 s)",
                                path);
    }
    if (batch_active) {
        if (!(cost.steps <= batch_steps_left)) {
            return geom::make_error(geom::ErrorCode::limit,
                                    what + " would take about " + with_thousands(cost.steps) +
                                        " basis steps, but the batch has only " +
                                        with_thousands(batch_steps_left) + " of its " +
                                        with_thousands(max_work_steps) +
                                        " left (about 10 s for a whole batch)",
                                    path);
        }
        batch_steps_left -= cost.steps;
    }
    return geom::Ok{};
}

BatchBudget::BatchBudget(double steps)
    : saved_left_(batch_steps_left), saved_active_(batch_active),
      start_left_(batch_active ? std::min(batch_steps_left, steps) : steps) {
    batch_steps_left = start_left_;
    batch_active = true;
}

BatchBudget::~BatchBudget() {
    const double spent = start_left_ - batch_steps_left;
    batch_steps_left = saved_active_ ? saved_left_ - spent : saved_left_;
    batch_active = saved_active_;
}

} // namespace isoparm::geom
