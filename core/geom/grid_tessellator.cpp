// Grid tessellation kernel. Per sample row the control net is contracted in u once (Q, dQ),
// then each vertex needs (q + 1) homogeneous multiply-adds for S, S_u and S_v each.
#include "core/geom/grid_tessellator.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <thread>

#include "core/geom/basis.hpp"
#include "core/geom/evaluate.hpp"
#include "core/geom/grid_kernel.hpp"
#include "core/geom/knots.hpp"

namespace isoparm::geom {

namespace {

GridTessellator::Table tabulate(const Knots& U, int p, int n, const std::vector<double>& params) {
    GridTessellator::Table t;
    t.p = p;
    t.first.resize(params.size());
    t.N.resize(params.size() * (p + 1));
    t.dN.resize(params.size() * (p + 1));
    std::vector<double> ders(2 * (static_cast<size_t>(p) + 1));
    for (size_t k = 0; k < params.size(); ++k) {
        const int span = find_span(U, p, n, params[k]);
        t.first[k] = span - p;
        ders_basis_funs(span, params[k], p, 1, U, ders.data());
        std::copy(ders.begin(), ders.begin() + p + 1, t.N.begin() + k * (p + 1));
        std::copy(ders.begin() + p + 1, ders.end(), t.dN.begin() + k * (p + 1));
    }
    return t;
}

// The samples whose non-zero basis functions include index i: first[k] <= i <= first[k] + p.
std::pair<int, int> touching(const GridTessellator::Table& t, int i) {
    const int count = static_cast<int>(t.first.size());
    int lo = 0;
    while (lo < count && t.first[lo] + t.p < i) ++lo;
    int hi = lo - 1;
    while (hi + 1 < count && t.first[hi + 1] <= i) ++hi;
    return {lo, hi};
}

// Q_j = sum_r N_r Pw[row0 + r][j] (and dQ with N'_r when derivatives are wanted).
void contract_rows(const double* Nu, const double* dNu, const double* Pw, int p, int n_v, int j0,
                   int j1, double* Q, double* dQ) {
    // Pw rows are n_v * 4 doubles; row r of the span starts at Pw + r * n_v * 4.
    for (int j = j0; j <= j1; ++j) {
        double a[4] = {0, 0, 0, 0}, b[4] = {0, 0, 0, 0};
        for (int r = 0; r <= p; ++r) {
            const double* P = Pw + (static_cast<size_t>(r) * n_v + j) * 4;
            for (int c = 0; c < 4; ++c) a[c] += Nu[r] * P[c];
            if (dQ)
                for (int c = 0; c < 4; ++c) b[c] += dNu[r] * P[c];
        }
        for (int c = 0; c < 4; ++c) Q[4 * j + c] = a[c];
        if (dQ)
            for (int c = 0; c < 4; ++c) dQ[4 * j + c] = b[c];
    }
}

std::vector<double> homogeneous_net(const Surface& s) {
    std::vector<double> Pw(s.points.size() * 4);
    for (size_t k = 0; k < s.points.size(); ++k) {
        const double w = s.weights[k];
        Pw[4 * k + 0] = s.points[k].x * w;
        Pw[4 * k + 1] = s.points[k].y * w;
        Pw[4 * k + 2] = s.points[k].z * w;
        Pw[4 * k + 3] = w;
    }
    return Pw;
}

} // namespace

GridTessellator::GridTessellator(const Surface& s, int samples_u, int samples_v)
    : degree_u_(s.degree_u), degree_v_(s.degree_v), n_u_(s.n_u), n_v_(s.n_v), knots_u_(s.knots_u),
      knots_v_(s.knots_v) {
    assert(samples_u >= 2 && samples_v >= 2);
    us_ = uniform_params(s.knots_u[s.degree_u], s.knots_u[s.n_u], samples_u);
    vs_ = uniform_params(s.knots_v[s.degree_v], s.knots_v[s.n_v], samples_v);
    tu_ = tabulate(s.knots_u, s.degree_u, s.n_u, us_);
    tv_ = tabulate(s.knots_v, s.degree_v, s.n_v, vs_);
}

bool GridTessellator::fits(const Surface& s, int samples_u, int samples_v) const {
    return s.degree_u == degree_u_ && s.degree_v == degree_v_ && s.n_u == n_u_ && s.n_v == n_v_ &&
           s.knots_u == knots_u_ && s.knots_v == knots_v_ && samples_u == this->samples_u() &&
           samples_v == this->samples_v();
}

std::pair<int, int> GridTessellator::rows_touching(int i) const {
    return touching(tu_, i);
}
std::pair<int, int> GridTessellator::columns_touching(int j) const {
    return touching(tv_, j);
}

void GridTessellator::evaluate_block(const Surface& s, const std::vector<double>& Pw,
                                     glm::dvec3* positions, glm::dvec3* normals,
                                     std::vector<std::uint8_t>& exists, int i0, int i1, int j0,
                                     int j1) const {
    const int p = degree_u_, q = degree_v_;
    const int sv = samples_v();
    const size_t count = static_cast<size_t>(samples_u()) * sv;
    // Control columns the sample columns j0..j1 need.
    const int c0 = tv_.first[j0], c1 = tv_.first[j1] + q;
    std::vector<double> Q(static_cast<size_t>(n_v_) * 4), dQ(static_cast<size_t>(n_v_) * 4);
    std::vector<std::uint8_t> status(sv);
    static_assert(sizeof(glm::dvec3) == 3 * sizeof(double), "the kernel writes x, y, z triples");
    for (int i = i0; i <= i1; ++i) {
        const double* Nu = &tu_.N[static_cast<size_t>(i) * (p + 1)];
        const double* dNu = &tu_.dN[static_cast<size_t>(i) * (p + 1)];
        contract_rows(Nu, dNu, &Pw[static_cast<size_t>(tu_.first[i]) * n_v_ * 4], p, n_v_, c0, c1,
                      Q.data(), normals ? dQ.data() : nullptr);
        const size_t row = static_cast<size_t>(i) * sv;
        const kernel::RowArgs args{tv_.N.data(),
                                   tv_.dN.data(),
                                   tv_.first.data(),
                                   Q.data(),
                                   dQ.data(),
                                   q,
                                   j0,
                                   j1,
                                   &positions[row].x,
                                   normals ? &normals[row].x : nullptr,
                                   status.data()};
        kernel::row(args);
        for (int j = j0; j <= j1; ++j) {
            const size_t k = row + j;
            if (status[j] == kernel::vertex_missing) {
                if (exists.empty()) exists.assign(count, 1);
                exists[k] = 0;
                positions[k] = glm::dvec3(0.0);
                if (normals) normals[k] = glm::dvec3(0.0, 0.0, 1.0);
                continue;
            }
            if (!exists.empty()) exists[k] = 1;
            if (status[j] == kernel::vertex_degenerate)
                normals[k] = surface_normal_or_limit(s, us_[i], vs_[j]);
        }
    }
}

void GridTessellator::run_rows(const Surface& s, glm::dvec3* positions, glm::dvec3* normals,
                               std::vector<std::uint8_t>& exists, int threads) const {
    const int su = samples_u(), sv = samples_v();
    const size_t count = static_cast<size_t>(su) * sv;
    exists.clear();
    const std::vector<double> Pw = homogeneous_net(s);
    threads = std::clamp(threads, 1, su);
    if (threads == 1) {
        evaluate_block(s, Pw, positions, normals, exists, 0, su - 1, 0, sv - 1);
        return;
    }
    // Threads write disjoint rows; `exists` is allocated up front so no thread resizes it.
    exists.assign(count, 1);
    {
        std::vector<std::jthread> pool;
        for (int t = 0; t < threads; ++t) {
            const int i0 = su * t / threads, i1 = su * (t + 1) / threads - 1;
            if (i0 > i1) continue;
            pool.emplace_back([&, i0, i1] {
                evaluate_block(s, Pw, positions, normals, exists, i0, i1, 0, sv - 1);
            });
        }
    } // joins
    if (std::all_of(exists.begin(), exists.end(), [](auto e) { return e != 0; })) exists.clear();
}

void GridTessellator::evaluate(const Surface& s, Mesh& mesh, int threads) const {
    const size_t count = static_cast<size_t>(samples_u()) * samples_v();
    mesh.positions.resize(count);
    mesh.normals.resize(count);
    run_rows(s, mesh.positions.data(), mesh.normals.data(), mesh.exists, threads);
    build_grid_triangles(mesh, samples_u(), samples_v());
}

void GridTessellator::evaluate_vertices(const Surface& s, std::vector<glm::dvec3>& positions,
                                        std::vector<glm::dvec3>& normals,
                                        std::vector<std::uint8_t>& exists, int threads) const {
    const size_t count = static_cast<size_t>(samples_u()) * samples_v();
    positions.resize(count);
    normals.resize(count);
    run_rows(s, positions.data(), normals.data(), exists, threads);
}

void GridTessellator::evaluate_positions(const Surface& s, std::vector<glm::dvec3>& positions,
                                         std::vector<std::uint8_t>& exists, int threads) const {
    positions.resize(static_cast<size_t>(samples_u()) * samples_v());
    run_rows(s, positions.data(), nullptr, exists, threads);
}

void GridTessellator::update_control_point(const Surface& s, Mesh& mesh, int i, int j) const {
    const auto [i0, i1] = rows_touching(i);
    const auto [j0, j1] = columns_touching(j);
    if (i0 > i1 || j0 > j1) return;
    const bool had_gaps = !mesh.exists.empty();
    std::vector<std::uint8_t> before;
    if (had_gaps) before = mesh.exists;
    const std::vector<double> Pw = homogeneous_net(s);
    evaluate_block(s, Pw, mesh.positions.data(), mesh.normals.data(), mesh.exists, i0, i1, j0, j1);
    if (mesh.exists != before) {
        if (std::all_of(mesh.exists.begin(), mesh.exists.end(), [](auto e) { return e != 0; }))
            mesh.exists.clear();
        build_grid_triangles(mesh, samples_u(), samples_v());
    }
}

void build_grid_triangles(Mesh& mesh, int samples_u, int samples_v) {
    mesh.triangles.clear();
    mesh.triangles.reserve(2 * static_cast<size_t>(samples_u - 1) * (samples_v - 1));
    const bool all = mesh.exists.empty();
    const auto nv = static_cast<std::uint32_t>(samples_v);
    for (int i = 0; i + 1 < samples_u; ++i) {
        for (int j = 0; j + 1 < samples_v; ++j) {
            const auto k = static_cast<std::uint32_t>(i) * nv + static_cast<std::uint32_t>(j);
            const std::array<std::uint32_t, 3> t0{k, k + nv, k + nv + 1}, t1{k, k + nv + 1, k + 1};
            for (const auto& t : {t0, t1})
                if (all || (mesh.exists[t[0]] && mesh.exists[t[1]] && mesh.exists[t[2]]))
                    mesh.triangles.push_back(t);
        }
    }
}

} // namespace isoparm::geom
