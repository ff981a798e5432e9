// De Boor's levels as overlay lines and points.
#include "ui/deboor_overlay.hpp"

#include <array>
#include <vector>

namespace isoparm::ui {

namespace {

std::vector<glm::vec3> cartesian_points(const std::vector<geom::HPoint>& level) {
    // A point with weight 0 has no Cartesian position: the polyline skips it.
    std::vector<glm::vec3> out;
    for (const geom::HPoint& h : level)
        if (const auto p = geom::DeBoorTriangle::cartesian(h)) out.emplace_back(*p);
    return out;
}

void add_level(const std::vector<geom::HPoint>& level, const glm::vec4& color, LineBatch& lines,
               PointBatch& points) {
    const std::vector<glm::vec3> pts = cartesian_points(level);
    Overlay::add_polyline(lines, pts, color);
    for (const glm::vec3& p : pts) points.points.push_back({p, color});
}

} // namespace

DeBoorStepInfo deboor_step_info(int step, int p_u, int p_v) {
    DeBoorStepInfo info;
    const int last = p_u + p_v + 1;
    if (step < 0 || step >= last) {
        info.u_stage = false;
        info.level = p_v;
        info.text = step < 0 ? "all levels" : "S(u, v): the last level of the v-stage";
        return info;
    }
    if (step <= p_u) {
        info.u_stage = true;
        info.level = step;
        info.text = step == 0
                        ? "the control points P_ij that act at (u, v)"
                        : "u-stage, level " + std::to_string(step) + " of " + std::to_string(p_u) +
                              ": every row curve's level " + std::to_string(step) + " at u";
        return info;
    }
    info.u_stage = false;
    info.level = step - p_u - 1;
    info.text = info.level == 0 ? "v-stage: the row results at u form the column curve's polygon"
                                : "v-stage, level " + std::to_string(info.level) + " of " +
                                      std::to_string(p_v) + " at v";
    return info;
}

glm::vec4 deboor_level_color(bool u_stage, int level) {
    // Magentas for the u-stage and cyans / greens for the v-stage: apart from the surface's
    // blue, the selected surface's orange and the knot curves' green-yellow.
    static constexpr std::array<glm::vec4, 5> warm = {
        glm::vec4{1.00f, 0.30f, 0.85f, 1}, glm::vec4{0.75f, 0.45f, 1.00f, 1},
        glm::vec4{1.00f, 0.55f, 0.65f, 1}, glm::vec4{0.95f, 0.80f, 1.00f, 1},
        glm::vec4{1.00f, 1.00f, 1.00f, 1}};
    static constexpr std::array<glm::vec4, 5> cool = {
        glm::vec4{0.20f, 0.90f, 1.00f, 1}, glm::vec4{0.35f, 1.00f, 0.55f, 1},
        glm::vec4{0.55f, 0.75f, 1.00f, 1}, glm::vec4{0.80f, 1.00f, 0.95f, 1},
        glm::vec4{1.00f, 1.00f, 1.00f, 1}};
    const auto& table = u_stage ? warm : cool;
    return table[static_cast<std::size_t>(std::max(level - 1, 0)) % table.size()];
}

void add_deboor_overlay(const geom::DeBoorSurfaceTrace& trace, int p_u, int p_v, int step,
                        float scale, Overlay& out) {
    const int last = p_u + p_v + 1;
    const int upto = step < 0 ? last : step;
    LineBatch lines{{}, 2.2f * scale, true};
    PointBatch points{{}, 8.f * scale, false, true};
    PointBatch result{{}, 16.f * scale, true, true};

    // Step 0: the (p_u + 1) x (p_v + 1) control points that act at (u, v), ringed in white.
    const int first_row = trace.v_stage.first_index;
    for (int j = first_row; j <= first_row + p_v && j < static_cast<int>(trace.u_stage.size()); ++j)
        for (const geom::HPoint& h : trace.u_stage[static_cast<std::size_t>(j)].levels.front())
            if (const auto p = geom::DeBoorTriangle::cartesian(h))
                points.points.push_back({glm::vec3(*p), {1, 1, 1, 1}});

    // u-stage: level k of every row curve; rows the v-stage does not use are drawn faint.
    for (int k = 1; k <= std::min(upto, p_u); ++k)
        for (std::size_t j = 0; j < trace.u_stage.size(); ++j) {
            const geom::DeBoorTriangle& row = trace.u_stage[j];
            const int r = static_cast<int>(j);
            const bool used = r >= first_row && r <= first_row + p_v;
            if (k < static_cast<int>(row.levels.size()))
                add_level(row.levels[static_cast<std::size_t>(k)],
                          deboor_level_color(true, k) * glm::vec4(1, 1, 1, used ? 1 : 0.35f), lines,
                          points);
        }

    // v-stage: the column polygon through every row's result, then its levels.
    if (upto >= p_u + 1) {
        std::vector<geom::HPoint> column;
        for (const geom::DeBoorTriangle& row : trace.u_stage)
            column.push_back(row.levels.back()[0]);
        add_level(column, deboor_level_color(false, 1) * glm::vec4(1, 1, 1, 0.55f), lines, points);
        for (int k = 1; k <= std::min(upto - p_u - 1, p_v); ++k)
            add_level(trace.v_stage.levels[static_cast<std::size_t>(k)],
                      deboor_level_color(false, k + 1), lines, points);
    }
    if (upto >= last)
        if (const auto p = trace.point())
            result.points.push_back({glm::vec3(*p), {1, 0.1f, 0.1f, 1}});

    if (!lines.vertices.empty()) out.lines.push_back(std::move(lines));
    if (!points.points.empty()) out.points.push_back(std::move(points));
    if (!result.points.empty()) out.points.push_back(std::move(result));
}

} // namespace isoparm::ui
