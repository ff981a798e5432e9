// The triangular patch's overlay: net, isoparametric lines and de Casteljau's levels.
#include "ui/view/triangle_scene.hpp"

#include <algorithm>

#include "ui/view/deboor_overlay.hpp"

namespace isoparm::ui {

void add_triangle_net(LineBatch& out, int n, const std::vector<std::optional<glm::dvec3>>& pts,
                      const glm::vec4& color) {
    auto at = [&](int i, int j) { return pts[geom::TrianglePatch::index(n, i, j)]; };
    auto join = [&](const std::optional<glm::dvec3>& a, const std::optional<glm::dvec3>& b) {
        if (!a || !b) return;
        out.vertices.push_back({glm::vec3(*a), color});
        out.vertices.push_back({glm::vec3(*b), color});
    };
    for (int i = 0; i <= n; ++i)
        for (int j = 0; i + j <= n; ++j) {
            if (i > 0) join(at(i, j), at(i - 1, j + 1)); // b_ijk - b_(i-1)(j+1)k
            if (i > 0) join(at(i, j), at(i - 1, j));     // b_ijk - b_(i-1)j(k+1)
            if (j > 0) join(at(i, j), at(i, j - 1));     // b_ijk - b_i(j-1)(k+1)
        }
}

void add_triangle_net(LineBatch& out, const geom::TrianglePatch& t, const glm::vec4& color) {
    std::vector<std::optional<glm::dvec3>> pts(t.points.begin(), t.points.end());
    add_triangle_net(out, t.degree, pts, color);
}

std::vector<std::vector<glm::vec3>> triangle_iso_lines(const geom::TrianglePatch& t,
                                                       const geom::Barycentric& p, int samples) {
    std::vector<std::vector<glm::vec3>> out;
    for (int fixed = 0; fixed < 3; ++fixed) {
        // Coordinate `fixed` held, the other two share 1 - p[fixed] from one edge to the other.
        const int a = (fixed + 1) % 3, b = (fixed + 2) % 3;
        const double rest = 1 - p[fixed];
        std::vector<glm::vec3> piece;
        for (int k = 0; k < samples; ++k) {
            const double f = static_cast<double>(k) / (samples - 1);
            geom::Barycentric q{};
            q[fixed] = p[fixed];
            q[a] = rest * f;
            q[b] = rest - q[a];
            if (const auto s = geom::triangle_point(t, q)) {
                piece.emplace_back(*s);
            } else if (!piece.empty()) {
                out.push_back(std::move(piece));
                piece.clear();
            }
        }
        if (piece.size() > 1) out.push_back(std::move(piece));
    }
    return out;
}

void add_triangle_de_casteljau(const geom::TrianglePatch& t, const geom::Barycentric& p, int step,
                               float scale, Overlay& out) {
    const auto levels = geom::triangle_de_casteljau(t, p);
    const int n = t.degree;
    const bool all = step < 0;
    const int upto = all ? n : std::min(step, n);
    LineBatch current_lines{{}, DeBoorSizes::current_line * scale, true};
    LineBatch past_lines{{}, DeBoorSizes::past_line * scale, true};
    PointBatch current_points{{}, DeBoorSizes::current_point * scale, false, true};
    PointBatch past_points{{}, DeBoorSizes::past_point * scale, false, true};
    PointBatch result{{}, DeBoorSizes::result_point * scale, true, true};
    for (int l = 0; l <= upto; ++l) {
        const bool current = all || l == upto;
        glm::vec4 c = l == 0 ? glm::vec4{1, 1, 1, 1} : deboor_level_color(true, l);
        if (!current) c.a *= DeBoorSizes::past_alpha;
        const auto& level = levels[static_cast<std::size_t>(l)];
        if (l == n) {
            if (level[0]) result.points.push_back({glm::vec3(*level[0]), {1, 0.1f, 0.1f, 1}});
            continue;
        }
        add_triangle_net(current ? current_lines : past_lines, n - l, level, c);
        for (const auto& q : level)
            if (q) (current ? current_points : past_points).points.push_back({glm::vec3(*q), c});
    }
    for (LineBatch* b : {&past_lines, &current_lines})
        if (!b->vertices.empty()) out.lines.push_back(std::move(*b));
    for (PointBatch* b : {&past_points, &current_points, &result})
        if (!b->points.empty()) out.points.push_back(std::move(*b));
}

} // namespace isoparm::ui
