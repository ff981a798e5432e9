// The 3D drawing view: the rendered scene as an image, mouse orbit/pan/zoom, picking and
// dragging control points, point labels, and the paper's translate/rotate/zoom sliders.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <imgui.h>
#include <optional>
#include <string>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "core/doc/commands.hpp"
#include "core/doc/commands_curve.hpp"
#include "core/doc/placement.hpp"
#include "core/geom/deboor.hpp"
#include "core/geom/status.hpp"
#include "ui/actions.hpp"
#include "ui/modeler_actions.hpp"
#include "ui/panels/panels.hpp"
#include "ui/panels/picture_draw.hpp"
#include "ui/panels/view3d_mouse.hpp"
#include "ui/render/renderer.hpp"
#include "ui/ui_report.hpp"
#include "ui/view/analysis.hpp"
#include "ui/view/canvas_map.hpp"
#include "ui/view/contrast.hpp"
#include "ui/view/deboor_overlay.hpp"
#include "ui/view/doc_access.hpp"
#include "ui/view/picking.hpp"
#include "ui/view/scene_builder.hpp"

namespace isoparm::ui {

namespace {

std::string point_label(int i, int j, int n_u, int n_v) {
    return point_name('P', i, j, n_u, n_v);
}

// The selection's handle and the box being drawn.
void draw_selection(const AppContext& ctx, const Viewport& vp, ImDrawList* dl) {
    const float k = ctx.ui.scale();
    const SelectionGesture& g = ctx.ui.modeler.selection.gesture;
    if (g.kind == SelectionGesture::Kind::box) {
        const ImVec2 a(static_cast<float>(g.press.x), static_cast<float>(g.press.y));
        const ImVec2 b(static_cast<float>(g.now.x), static_cast<float>(g.now.y));
        dl->AddRectFilled(a, b, IM_COL32(120, 170, 255, 40));
        dl->AddRect(a, b, IM_COL32(140, 190, 255, 220), 0, 0, 1.5f * k);
    }
    const std::optional<HandleLayout> h = selection_handle(ctx, vp);
    if (!h) return;
    report_point("view3d/handle", static_cast<float>(h->centre.x), static_cast<float>(h->centre.y));
    const ImU32 colors[3] = {IM_COL32(240, 80, 80, 255), IM_COL32(90, 215, 90, 255),
                             IM_COL32(90, 140, 255, 255)};
    const char* names[3] = {"x", "y", "z"};
    auto iv = [](const glm::dvec2& p) {
        return ImVec2(static_cast<float>(p.x), static_cast<float>(p.y));
    };
    for (int a = 0; a < 3; ++a) {
        const auto& ring = h->ring[a];
        if (ring.size() > 2) {
            std::vector<ImVec2> pts;
            for (const glm::dvec2& p : ring) pts.push_back(iv(p));
            dl->AddPolyline(pts.data(), static_cast<int>(pts.size()),
                            (colors[a] & 0x00FFFFFF) | 0xA0000000, ImDrawFlags_Closed, 1.5f * k);
            report_point(std::string("view3d/handle/ring_") + names[a], pts.front().x,
                         pts.front().y);
        }
    }
    for (int a = 0; a < 3; ++a) {
        if (!h->axis_shown[a]) continue;
        const ImVec2 c = iv(h->centre), t = iv(h->tip[a]);
        dl->AddLine(c, t, colors[a], 2.5f * k);
        dl->AddCircleFilled(t, 4.5f * k, colors[a], 12);
        report_point(std::string("view3d/handle/") + names[a], t.x, t.y);
    }
    const ImVec2 c = iv(h->centre);
    dl->AddCircleFilled(c, static_cast<float>(h->centre_radius), IM_COL32(255, 255, 255, 200), 20);
    dl->AddCircle(c, static_cast<float>(h->centre_radius), IM_COL32(0, 0, 0, 255), 20, 1.5f * k);
    const ImVec2 sb = iv(h->scale_box);
    const float hb = static_cast<float>(h->box_half);
    dl->AddRectFilled(ImVec2(sb.x - hb, sb.y - hb), ImVec2(sb.x + hb, sb.y + hb),
                      IM_COL32(250, 210, 80, 230));
    dl->AddRect(ImVec2(sb.x - hb, sb.y - hb), ImVec2(sb.x + hb, sb.y + hb), IM_COL32(0, 0, 0, 255));
    report_point("view3d/handle/scale", sb.x, sb.y);
}

glm::vec3 background_of(const doc::Document& d) {
    return {d.colors.background.r, d.colors.background.g, d.colors.background.b};
}

// For the GUI scenario tests: where the current surface's control points are on screen.
void report_projected_points(const AppContext& ctx, const Viewport& vp) {
    if (!ui_report_enabled()) return;
    const doc::Object* obj = nullptr;
    const geom::Surface* s = current_surface(ctx.doc, &obj);
    if (!s) return;
    const glm::dmat4 m = view_projection(ctx.ui.camera, vp.aspect());
    for (int i = 0; i < s->n_u; ++i)
        for (int j = 0; j < s->n_v; ++j)
            if (const Projected p = project(m, vp, s->point(i, j)); p.visible)
                report_point("view3d/" + obj->name + "/" + std::to_string(i) + "," +
                                 std::to_string(j),
                             static_cast<float>(p.pixel.x), static_cast<float>(p.pixel.y));
}

Rgba8 rgba(const glm::vec4& c) {
    auto byte = [](float x) { return static_cast<unsigned>(std::clamp(x, 0.f, 1.f) * 255 + 0.5f); };
    return rgba8(byte(c.r), byte(c.g), byte(c.b), byte(c.a));
}

// The current surface's control points named P_ij (Display > Point IDs), beside their points.
void point_id_labels(const AppContext& ctx, const Viewport& vp, Picture& pic) {
    const doc::Document& d = ctx.doc;
    const doc::Object* obj = nullptr;
    const geom::Surface* s = current_surface(d, &obj);
    if (!s || !obj->visible || !doc::display_of(d.view, obj->id).point_ids) return;
    const glm::dmat4 m = view_projection(ctx.ui.camera, vp.aspect());
    const doc::Rgba& c = d.colors.control_points;
    const glm::vec4 t = readable_on(glm::vec4(c.r, c.g, c.b, 1), background_of(d), text_contrast);
    // A plate the opposite of the text outlines it on any background.
    const Rgba8 plate =
        relative_luminance(glm::vec3(t)) > 0.3f ? rgba8(0, 0, 0, 150) : rgba8(255, 255, 255, 150);
    for (int i = 0; i < s->n_u; ++i)
        for (int j = 0; j < s->n_v; ++j) {
            const Projected p = project(m, vp, s->point(i, j));
            if (!p.visible) continue;
            pic.label(glm::vec2(p.pixel), point_label(i, j, s->n_u, s->n_v),
                      rgba(glm::vec4(glm::vec3(t), 1)), 0)
                .plate = plate;
        }
}

// The names of the current de Boor level's points (the de Boor tab's names), beside them in
// the level's colour on a dark plate: the lecture can say "d^2_3,1" and the room finds it.
void deboor_labels(const AppContext& ctx, const Viewport& vp, Picture& pic) {
    const doc::Document& d = ctx.doc;
    if (!d.view.display.deboor || ctx.ui.deboor.step < 0) return;
    const doc::Object* obj = nullptr;
    const geom::Surface* s = current_surface(d, &obj);
    if (!s || !obj->visible) return;
    const glm::dvec2 uv = indicator_params(d, *obj);
    const std::vector<DeBoorLabel> labels = deboor_step_labels(
        geom::deboor_surface(*s, uv.x, uv.y), s->degree_u, s->degree_v, ctx.ui.deboor.step);
    const glm::dmat4 m = view_projection(ctx.ui.camera, vp.aspect());
    for (const DeBoorLabel& l : labels) {
        const Projected p = project(m, vp, glm::dvec3(l.position));
        if (!p.visible) continue;
        const glm::vec4& c = l.color;
        // The level's colour, lightened toward white to read well on the plate.
        LabelRequest& r =
            pic.label(glm::vec2(p.pixel), l.text,
                      rgba({0.65f * c.r + 0.35f, 0.65f * c.g + 0.35f, 0.65f * c.b + 0.35f, 1}), 20);
        r.plate = rgba8(10, 12, 18, 200);
        r.frame = rgba({c.r, c.g, c.b, 0.6f});
    }
}

void draw_hover_ring(const AppContext& ctx, const Viewport& vp, ImDrawList* dl) {
    if (ctx.ui.drag.kind != ViewDrag::Kind::none || !ImGui::IsItemHovered()) return;
    const ImVec2 mp = ImGui::GetIO().MousePos;
    if (const auto hit = pick_point(ctx, vp, {mp.x, mp.y})) {
        const Projected p = project(view_projection(ctx.ui.camera, vp.aspect()), vp, hit->position);
        dl->AddCircle(ImVec2(static_cast<float>(p.pixel.x), static_cast<float>(p.pixel.y)),
                      9.f * ctx.ui.scale(), IM_COL32(255, 255, 255, 220), 24, 2.f * ctx.ui.scale());
        const std::string tip =
            point_name('P', hit->ref.i, hit->ref.j, ctx.doc.find(hit->ref.object));
        ImGui::SetTooltip("%s  (%.3g, %.3g, %.3g)", tip.c_str(), hit->position.x, hit->position.y,
                          hit->position.z);
    }
}

// The x/y/z triad in the lower-left corner, so the control-point planes are easy to relate.
void draw_axes(const AppContext& ctx, const Viewport& vp, Picture& pic) {
    const float k = ctx.ui.scale();
    const glm::vec2 o(static_cast<float>(vp.x) + 38 * k, static_cast<float>(vp.y + vp.h) - 38 * k);
    const glm::dvec3 right = camera_right(ctx.ui.camera), up = camera_up(ctx.ui.camera);
    const char* names[3] = {"x", "y", "z"};
    const Rgba8 colors[3] = {rgba8(240, 80, 80), rgba8(90, 215, 90), rgba8(90, 140, 255)};
    for (int a = 0; a < 3; ++a) {
        glm::dvec3 e(0);
        e[a] = 1;
        const glm::vec2 tip(o.x + static_cast<float>(glm::dot(e, right)) * 26 * k,
                            o.y - static_cast<float>(glm::dot(e, up)) * 26 * k);
        pic.line(o, tip, colors[a], 2.f * k);
        pic.label(tip, names[a], colors[a], 60);
    }
}

void help_line(const AppContext& ctx, const Viewport& vp, Picture& pic, float reserved) {
    if (ctx.ui.presentation) return;
    // The longest wording that fits beside the analysis title: a hint cut in the middle reads
    // as a bug, and one under the title reads as neither.
    static const char* const wordings[] = {
        "drag: orbit   right-drag: pan   wheel: zoom   click or drag a point (X/Y/Z: along "
        "an axis)   Shift+click: add   Ctrl+drag: box",
        "drag: orbit   right-drag: pan   wheel: zoom   drag a point",
        "drag: orbit   right: pan   wheel: zoom",
    };
    const float room = static_cast<float>(vp.w) - 24 - reserved;
    const char* help = nullptr;
    for (const char* w : wordings)
        if (ImGui::CalcTextSize(w).x <= room) {
            help = w;
            break;
        }
    if (!help) return;
    const glm::vec4 c =
        readable_on(glm::vec4(0.86f, 0.86f, 0.86f, 1), background_of(ctx.doc), text_contrast);
    pic.fixed_label({static_cast<float>(vp.x) + 6, static_cast<float>(vp.y) + 4}, help,
                    rgba({c.r, c.g, c.b, 0.85f}), LabelAlign::top_left, 70);
}

// Rows the slider strip needs: one when the panel is wide enough for all controls, two
// (move + zoom, rotate + fit), or three in a narrow view (zoom and fit on their own row), so
// the zoom's value is never cut.
int slider_rows(float width, float scale) {
    const ImGuiStyle& st = ImGui::GetStyle();
    const float labels =
        ImGui::CalcTextSize("Move Rotate Zoom Fit").x + ImGui::GetStyle().ItemSpacing.x * 10;
    if (width >= labels + 7.5f * 64 * scale) return 1;
    const float zoom = ImGui::CalcTextSize("Zoom").x + ImGui::CalcTextSize("1000%").x +
                       st.FramePadding.x * 2 + st.ItemSpacing.x;
    const float two = ImGui::CalcTextSize("Rotate").x + 3 * 20 * scale + zoom +
                      st.ItemSpacing.x * 5 + st.WindowPadding.x;
    return width >= two ? 2 : 3;
}

// One spring-loaded slider (k: 0..2 move along x/y/z, 3..5 rotate about x/y/z): while held,
// its offset from the press is applied as transform_object commands that merge into one
// undo step; released, it springs back to 0.
void transform_slider(AppContext& ctx, int k, float width) {
    TransformSliders& sl = ctx.ui.sliders;
    const doc::Object* sel = ctx.doc.selected();
    const std::uint64_t id = sel ? sel->id : 0;
    static const char* ids[6] = {"##mx", "##my", "##mz", "##rx", "##ry", "##rz"};
    static const char* axis_names[3] = {"x", "y", "z"};
    const int a = k % 3;
    float* value = k < 3 ? &sl.move[a] : &sl.rotate[a];
    const bool held = sl.active == k;
    ImGui::SetNextItemWidth(width);
    // A jog control: dragging left or right changes the offset from the press (a slider
    // would jump to wherever it was clicked). Idle, it shows its axis; held, the offset.
    // Move: 1/400 of the scene per pixel; rotate: half a degree per pixel.
    if (k < 3)
        ImGui::DragFloat(ids[k], value, static_cast<float>(1.0 / 400.0), 0.f, 0.f,
                         held ? "%+.3f" : axis_names[a]);
    else
        ImGui::DragFloat(ids[k], value, 0.5f, 0.f, 0.f, held ? "%+.1f deg" : axis_names[a]);
    report_item(std::string(k < 3 ? "view3d/move_" : "view3d/rotate_") + axis_names[a]);
    if (ImGui::IsItemHovered() && !held)
        ImGui::SetTooltip(k < 3 ? "Drag left or right to move the selected object along %s"
                                : "Drag left or right to rotate the selected object about %s",
                          axis_names[a]);
    // A constructed object follows its curves: the slider asks to detach it first.
    if (ImGui::IsItemActivated() && id != 0 && may_edit_points(ctx, id)) {
        sl.active = k;
        sl.applied = 0;
        ctx.seal();
        // Pivot and step size are fixed for the whole gesture.
        if (const std::span<const glm::dvec3> pts = doc::control_points_of(sel->shape);
            !pts.empty()) {
            glm::dvec3 c(0);
            for (const glm::dvec3& p : pts) c += p;
            sl.pivot = c / static_cast<double>(pts.size());
        }
        const auto box = doc::scene_bounds(ctx.doc);
        sl.scale = box ? std::max(glm::length(box->hi - box->lo), 1e-3) : 1.0;
    }
    if (ImGui::IsItemActive() && held && id != 0 && *value != sl.applied) {
        const double delta = *value - sl.applied;
        glm::dmat4 m(1.0);
        if (k < 3) {
            glm::dvec3 t(0);
            t[a] = delta * sl.scale;
            m = glm::translate(glm::dmat4(1.0), t);
        } else {
            glm::dvec3 axis(0);
            axis[a] = 1;
            m = glm::translate(glm::dmat4(1.0), sl.pivot) *
                glm::rotate(glm::dmat4(1.0), glm::radians(delta), axis) *
                glm::translate(glm::dmat4(1.0), -sl.pivot);
        }
        if (ctx.execute(doc::transform_object(id, m))) sl.applied = *value;
    }
    if (ImGui::IsItemDeactivated()) {
        *value = 0;
        sl.applied = 0;
        sl.active = -1;
        ctx.seal();
    }
}

// The paper's sliders below the drawing: translate and rotate the selected surface, zoom
// the scene; on one row, or two in a narrow panel.
void draw_sliders(AppContext& ctx, int rows) {
    UiState& ui = ctx.ui;
    const ImGuiStyle& st = ImGui::GetStyle();
    const float avail = ImGui::GetContentRegionAvail().x;
    const float label_w = rows == 1 ? 0.f : ImGui::CalcTextSize("Rotate").x;
    const float fixed = ImGui::CalcTextSize(rows == 1 ? "Move Rotate Zoom Fit" : "Rotate Zoom").x +
                        ImGui::CalcTextSize("Fit").x + st.FramePadding.x * 2 +
                        st.ItemSpacing.x * (rows == 1 ? 11 : 7);
    const float w = rows == 3 ? std::max((avail - label_w - st.ItemSpacing.x * 4) / 3, 20.f)
                              : std::max((avail - fixed) / (rows == 1 ? 7.5f : 4.5f), 20.f);
    const bool none = ctx.doc.selected() == nullptr;

    auto label = [&](const char* text) {
        ImGui::AlignTextToFramePadding();
        ImGui::TextUnformatted(text);
        ImGui::SameLine(rows == 1 ? 0.f : label_w + st.ItemSpacing.x + st.WindowPadding.x);
    };
    auto zoom = [&]() {
        ImGui::TextUnformatted("Zoom");
        ImGui::SameLine();
        // Never narrower than its own "1000%": a narrow view still reads its zoom.
        ImGui::SetNextItemWidth(
            std::max(w * 1.5f, ImGui::CalcTextSize("1000%").x + st.FramePadding.x * 2));
        // Zoom relative to the last fit, on a log scale (the wheel changes the same value).
        float pct = static_cast<float>(100.0 * ui.fit_distance / ui.camera.distance);
        if (ImGui::SliderFloat("##zoom", &pct, 10.f, 1000.f, "%.0f%%",
                               ImGuiSliderFlags_Logarithmic))
            ui.camera.distance = ui.fit_distance / (std::max(pct, 1.f) / 100.0);
    };

    ImGui::BeginDisabled(none);
    label("Move");
    for (int k = 0; k < 3; ++k) {
        transform_slider(ctx, k, w);
        if (k < 2 || rows != 3) ImGui::SameLine();
    }
    ImGui::EndDisabled();
    if (rows == 2) {
        zoom();
        ImGui::BeginDisabled(none);
        label("Rotate");
    } else {
        ImGui::BeginDisabled(none);
        if (rows == 3)
            label("Rotate");
        else {
            ImGui::TextUnformatted("Rotate");
            ImGui::SameLine();
        }
    }
    for (int k = 3; k < 6; ++k) {
        transform_slider(ctx, k, w);
        if (k < 5 || rows != 3) ImGui::SameLine();
    }
    ImGui::EndDisabled();
    if (rows != 2) {
        zoom();
        ImGui::SameLine();
    }
    if (ImGui::Button("Fit")) fit_view(ctx);
}

} // namespace

namespace {

// The analysis mode's colour bar at the view's right edge: the map from the range's low to its
// high end with both values and zero, the mode's name, and the hatch of undefined points.
// Returns the width the title takes along the top (the help line keeps clear of it).
float colour_bar(AppContext& ctx, const Viewport& vp, Picture& pic) {
    const AnalysisView& a = ctx.ui.analysis;
    if (a.kind == AnalysisKind::off) return 0;
    const float k = ctx.ui.scale();
    const Rgba8 text = rgba8(230, 230, 230);
    const Rgba8 plate = rgba8(0, 0, 0, 140);
    const std::string title = analysis_title(a.kind);
    const float line = ImGui::GetTextLineHeight();
    const float vx = static_cast<float>(vp.x), vy = static_cast<float>(vp.y);
    const float vw = static_cast<float>(vp.w), vh = static_cast<float>(vp.h);
    pic.fixed_label({vx + vw - 8 * k, vy + 6 * k}, title, text, LabelAlign::top_right, 95).plate =
        plate;
    const float title_w = ImGui::CalcTextSize(title.c_str()).x + 16 * k;
    if (!is_curvature(a.kind)) return title_w;
    const float w = 16 * k, h = std::min(vh * 0.45f, 260 * k);
    const float x = vx + vw - w - 12 * k, y = vy + 14 * k + line;
    const int steps = 48;
    for (int s = 0; s < steps; ++s) {
        // Top is the high end.
        const double v = a.hi + (a.lo - a.hi) * (s + 0.5) / steps;
        const glm::vec3 c = analysis_colour(a, v);
        pic.box({x, y + h * s / steps}, {x + w, y + h * (s + 1) / steps + 0.5f},
                rgba(glm::vec4(c, 1)));
    }
    pic.box({x, y}, {x + w, y + h}, 0, rgba8(20, 20, 20), 1);
    auto value_label = [&](double v, float at, int priority) {
        pic.line({x - 3 * k, at}, {x, at}, text);
        pic.fixed_label({x - 6 * k, at}, geom::format_short(v, 3), text, LabelAlign::center_right,
                        priority)
            .plate = plate;
    };
    value_label(a.hi, y, 94);
    value_label(a.lo, y + h, 94);
    if (a.lo < 0 && a.hi > 0)
        value_label(0.0, y + h * static_cast<float>(a.hi / (a.hi - a.lo)), 93);
    // The hatch the surface shows where the value is undefined (a pole, a zero denominator).
    const float hy = y + h + line;
    for (int s = 0; s < 4; ++s)
        pic.box({x + w * s / 4, hy}, {x + w * (s + 1) / 4, hy + 8 * k},
                s % 2 ? rgba8(140, 140, 140) : rgba8(90, 90, 90));
    pic.fixed_label({x - 6 * k, hy + 4 * k}, "undefined", text, LabelAlign::center_right, 92)
        .plate = plate;
    // The range shown: what lies beyond the bar (a robust range leaves outliers out).
    if (const std::string note = analysis_range_note(a); !note.empty())
        pic.fixed_label({x + w, hy + 8 * k + line}, note, text, LabelAlign::top_right, 91).plate =
            plate;
    return title_w;
}

} // namespace

void draw_view3d_panel(AppContext& ctx) {
    UiState& ui = ctx.ui;
    // Alone, on the stage (de Boor) and in the four-view layout: the picture without sliders.
    const bool alone = ui.view_mode == ViewMode::view3d_only;
    const bool bare = alone || ui.stage.active();
    ImVec2 avail = ImGui::GetContentRegionAvail();
    const int rows = bare ? 0 : slider_rows(avail.x, ui.scale());
    if (!bare)
        avail.y -= ImGui::GetFrameHeightWithSpacing() * static_cast<float>(rows) +
                   ImGui::GetStyle().ItemSpacing.y;
    avail.x = std::max(avail.x, 16.f);
    avail.y = std::max(avail.y, 16.f);
    const ImVec2 p0 = ImGui::GetCursorScreenPos();
    ui.view_rect = {p0.x, p0.y, avail.x, avail.y};
    report_rect("view3d/image", p0.x, p0.y, avail.x, avail.y); // what Export picture takes
    const ImVec2 fb_scale = ImGui::GetIO().DisplayFramebufferScale;
    ui.view_fb_width = std::max(1, static_cast<int>(std::lround(avail.x * fb_scale.x)));
    ui.view_fb_height = std::max(1, static_cast<int>(std::lround(avail.y * fb_scale.y)));
    if (ui.camera_needs_fit) {
        fit_view(ctx);
        ui.camera_needs_fit = false;
        if (ui.zoom_after_fit != 1.0) {
            zoom(ui.camera, 1.0 / ui.zoom_after_fit);
            ui.zoom_after_fit = 1.0;
        }
    }

    ImGui::InvisibleButton("##view3d", avail,
                           ImGuiButtonFlags_MouseButtonLeft | ImGuiButtonFlags_MouseButtonRight |
                               ImGuiButtonFlags_MouseButtonMiddle);
    const Viewport vp{p0.x, p0.y, avail.x, avail.y};
    handle_mouse(ctx, vp);

    // The picture itself is copied into the frame under ImGui's drawing (Workstation::frame):
    // drawn as a textured quad it cost a CPU rasteriser several milliseconds a frame. This
    // panel has no background, so what it draws here lies on top of the picture.
    ImDrawList* dl = ImGui::GetWindowDrawList();
    report_projected_points(ctx, vp);
    report_rect("view3d/image", p0.x, p0.y, avail.x, avail.y);
    // Every text over the picture through the one label placer (label/view3d/<n>).
    Picture pic;
    pic.view = "view3d";
    pic.frame = {p0.x, p0.y, avail.x, avail.y};
    pic.style.offset = 7 * ui.scale();
    point_id_labels(ctx, vp, pic);
    deboor_labels(ctx, vp, pic);
    draw_axes(ctx, vp, pic);
    ui.analysis = analysis_view(ctx.doc, ctx.implicit_meshes);
    const float title_w = colour_bar(ctx, vp, pic);
    if (!bare)
        help_line(ctx, vp, pic, title_w);
    else if (alone && !ui.headless)
        pic.fixed_label({p0.x + 8, p0.y + 6}, "Shift+P or Esc: back to the workstation",
                        rgba8(160, 160, 160, 200), LabelAlign::top_left, 70);
    draw_picture(pic, dl);
    dl->PushClipRect(p0, ImVec2(p0.x + avail.x, p0.y + avail.y), true);
    if (!ui.headless) draw_hover_ring(ctx, vp, dl);
    draw_selection(ctx, vp, dl); // the box being drawn, the many points' handle
    dl->PopClipRect();

    if (!bare) draw_sliders(ctx, rows);
}

} // namespace isoparm::ui
