// De Boor's levels as overlay lines and points, the current level highlighted and labelled.
#include "ui/view/deboor_overlay.hpp"

#include <algorithm>
#include <array>

namespace isoparm::ui {

namespace {

std::vector<glm::vec3> cartesian_points(const std::vector<geom::HPoint>& level) {
    // A point with weight 0 has no Cartesian position: the polyline skips it.
    std::vector<glm::vec3> out;
    for (const geom::HPoint& h : level)
        if (const auto p = geom::DeBoorTriangle::cartesian(h)) out.emplace_back(*p);
    return out;
}

glm::vec4 faded(glm::vec4 c, float alpha) {
    c.a *= alpha;
    return c;
}

// The batches a level goes to: the current step's level (or every level when all are shown)
// in full, the levels already passed faint and small.
struct Layers {
    LineBatch current_lines, past_lines;
    PointBatch current_points, past_points;

    void add_level(const std::vector<geom::HPoint>& level, const glm::vec4& color, bool current) {
        const std::vector<glm::vec3> pts = cartesian_points(level);
        const glm::vec4 c = current ? color : faded(color, DeBoorSizes::past_alpha);
        Overlay::add_polyline(current ? current_lines : past_lines, pts, c);
        for (const glm::vec3& p : pts)
            (current ? current_points : past_points).points.push_back({p, c});
    }
};

// The rows of the u-stage the v-stage uses: first_row .. first_row + p_v.
bool row_used(const geom::DeBoorSurfaceTrace& trace, int row, int p_v) {
    return row >= trace.v_stage.first_index && row <= trace.v_stage.first_index + p_v;
}

// The column polygon of the v-stage's step: every row's result at u (the rows the v-stage
// does not use included, so the whole column curve's polygon shows).
std::vector<geom::HPoint> row_results(const geom::DeBoorSurfaceTrace& trace) {
    std::vector<geom::HPoint> column;
    for (const geom::DeBoorTriangle& row : trace.u_stage) column.push_back(row.levels.back()[0]);
    return column;
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

std::string deboor_point_name(bool u_stage, int level, int index, int row) {
    const std::string i = std::to_string(index);
    if (u_stage) {
        const std::string j = std::to_string(row);
        return level == 0 ? "P" + i + "," + j : "d^" + std::to_string(level) + "_" + i + "," + j;
    }
    return level == 0 ? "Q" + i : "d^" + std::to_string(level) + "_" + i;
}

void add_deboor_overlay(const geom::DeBoorSurfaceTrace& trace, int p_u, int p_v, int step,
                        float scale, Overlay& out) {
    const int last = p_u + p_v + 1;
    const bool all = step < 0;
    const int upto = all ? last : std::min(step, last);
    auto is_current = [&](int s) { return all || s == upto; };
    // Every level at once is busy: medium points then; one level at a time, large ones.
    const float current_point = all ? (DeBoorSizes::current_point + DeBoorSizes::past_point) / 2
                                    : DeBoorSizes::current_point;
    Layers layers{{{}, DeBoorSizes::current_line * scale, true},
                  {{}, DeBoorSizes::past_line * scale, true},
                  {{}, current_point * scale, false, true},
                  {{}, DeBoorSizes::past_point * scale, false, true}};
    PointBatch acting{{}, DeBoorSizes::acting_point * scale, false, true};
    PointBatch result{{}, DeBoorSizes::result_point * scale, true, true};

    // Step 0: the (p_u + 1) x (p_v + 1) control points that act at (u, v), in white (faint
    // once the construction has moved on).
    const glm::vec4 white{1, 1, 1, 1};
    for (const glm::dvec3& p : deboor_acting_points(trace, p_v)) {
        if (is_current(0))
            acting.points.push_back({glm::vec3(p), white});
        else
            layers.past_points.points.push_back({glm::vec3(p), faded(white, 0.6f)});
    }

    // u-stage: level k of every row curve; rows the v-stage does not use are drawn fainter.
    for (int k = 1; k <= std::min(upto, p_u); ++k)
        for (std::size_t j = 0; j < trace.u_stage.size(); ++j) {
            const geom::DeBoorTriangle& row = trace.u_stage[j];
            if (k >= static_cast<int>(row.levels.size())) continue;
            const bool used = row_used(trace, static_cast<int>(j), p_v);
            layers.add_level(row.levels[static_cast<std::size_t>(k)],
                             faded(deboor_level_color(true, k), used ? 1 : 0.35f), is_current(k));
        }

    // v-stage: the column polygon through every row's result, then its levels.
    if (upto >= p_u + 1) {
        layers.add_level(row_results(trace), faded(deboor_level_color(false, 1), 0.55f),
                         is_current(p_u + 1));
        for (int k = 1; k <= std::min(upto - p_u - 1, p_v); ++k)
            layers.add_level(trace.v_stage.levels[static_cast<std::size_t>(k)],
                             deboor_level_color(false, k + 1), is_current(p_u + 1 + k));
    }
    if (upto >= last)
        if (const auto p = trace.point())
            result.points.push_back({glm::vec3(*p), {1, 0.1f, 0.1f, 1}});

    // Faint first, so the current level draws over what it was computed from.
    for (LineBatch* b : {&layers.past_lines, &layers.current_lines})
        if (!b->vertices.empty()) out.lines.push_back(std::move(*b));
    for (PointBatch* b : {&layers.past_points, &acting, &layers.current_points, &result})
        if (!b->points.empty()) out.points.push_back(std::move(*b));
}

std::vector<DeBoorLabel> deboor_step_labels(const geom::DeBoorSurfaceTrace& trace, int p_u, int p_v,
                                            int step) {
    std::vector<DeBoorLabel> out;
    const int last = p_u + p_v + 1;
    if (step < 0) return out;
    auto label_triangle_level = [&](const geom::DeBoorTriangle& t, bool u_stage, int level, int row,
                                    const glm::vec4& color) {
        if (level >= static_cast<int>(t.levels.size())) return;
        const auto& pts = t.levels[static_cast<std::size_t>(level)];
        for (std::size_t i = 0; i < pts.size(); ++i)
            if (const auto p = geom::DeBoorTriangle::cartesian(pts[i]))
                out.push_back({glm::vec3(*p),
                               deboor_point_name(u_stage, level,
                                                 t.first_index + static_cast<int>(i) + level, row),
                               color});
    };
    const int s = std::min(step, last);
    if (s <= p_u) {
        // The rows the v-stage uses only: the others do not reach S(u, v).
        for (int j = trace.v_stage.first_index;
             j <= trace.v_stage.first_index + p_v && j < static_cast<int>(trace.u_stage.size());
             ++j)
            label_triangle_level(trace.u_stage[static_cast<std::size_t>(j)], true, s, j,
                                 s == 0 ? glm::vec4{1, 1, 1, 1} : deboor_level_color(true, s));
    } else if (s < last) {
        const int level = s - p_u - 1;
        label_triangle_level(trace.v_stage, false, level, -1, deboor_level_color(false, level + 1));
    } else if (const auto p = trace.point()) {
        out.push_back({glm::vec3(*p), "S(u,v)", {1, 0.35f, 0.35f, 1}});
    }
    return out;
}

std::vector<glm::dvec3> deboor_acting_points(const geom::DeBoorSurfaceTrace& trace, int p_v) {
    std::vector<glm::dvec3> out;
    const int first_row = trace.v_stage.first_index;
    for (int j = first_row; j <= first_row + p_v && j < static_cast<int>(trace.u_stage.size()); ++j)
        for (const geom::HPoint& h : trace.u_stage[static_cast<std::size_t>(j)].levels.front())
            if (const auto p = geom::DeBoorTriangle::cartesian(h)) out.push_back(*p);
    return out;
}

} // namespace isoparm::ui
