#include "app/view_options.hpp"

#include <cctype>
#include <charconv>
#include <cmath>

#include "core/doc/patches.hpp"
#include "core/geom/knots.hpp"
#include "ui/view/current_patch.hpp"
#include "ui/view/doc_access.hpp"
#include "ui/view/triangle_domain.hpp"

namespace isoparm::app {

std::optional<std::vector<double>> numbers(const std::string& text, size_t min, size_t max) {
    std::vector<double> out;
    size_t start = 0;
    while (true) {
        const size_t comma = text.find(',', start);
        std::string_view part(text);
        part = part.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
        while (!part.empty() && std::isspace(static_cast<unsigned char>(part.front())))
            part.remove_prefix(1);
        while (!part.empty() && std::isspace(static_cast<unsigned char>(part.back())))
            part.remove_suffix(1);
        if (part.size() > 1 && part.front() == '+' && part[1] != '-') part.remove_prefix(1);
        double x = 0;
        const auto [end, ec] = std::from_chars(part.data(), part.data() + part.size(), x);
        if (part.empty() || ec != std::errc{} || end != part.data() + part.size() ||
            !std::isfinite(x))
            return std::nullopt;
        out.push_back(x);
        if (comma == std::string::npos) break;
        start = comma + 1;
    }
    if (out.size() < min || out.size() > max) return std::nullopt;
    return out;
}

std::optional<std::pair<int, int>> picture_size(std::string_view text) {
    const size_t x = text.find('x');
    if (x == std::string_view::npos) return std::nullopt;
    auto side = [](std::string_view digits) -> std::optional<int> {
        int v = 0;
        const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), v);
        if (digits.empty() || digits.size() > 5 || ec != std::errc{} ||
            end != digits.data() + digits.size() || digits.front() == '-' || v < 16 || v > 8192)
            return std::nullopt;
        return v;
    };
    const auto w = side(text.substr(0, x)), h = side(text.substr(x + 1));
    if (!w || !h) return std::nullopt;
    return std::pair{*w, *h};
}

namespace {

void apply_toggle(int flag, bool& setting) {
    if (flag > 0) setting = true;
    if (flag < 0) setting = false;
}

} // namespace

std::string apply_view_options(const ViewOptions& o, ui::AppContext& ctx) {
    doc::Document& d = ctx.doc;
    if (!o.style.empty()) {
        // The option's values were checked against the same names (add_options).
        d.view.display.style =
            geom::parse_name<doc::DisplayStyle>(o.style).value_or(doc::DisplayStyle::both);
    }
    if (!o.analysis.empty())
        d.view.display.analysis =
            geom::parse_name<doc::AnalysisMode>(o.analysis).value_or(doc::AnalysisMode::off);
    apply_toggle(o.points, d.view.display.control_points);
    apply_toggle(o.net, d.view.display.control_net);
    apply_toggle(o.ids, d.view.display.point_ids);
    apply_toggle(o.knot_curves, d.view.display.knot_curves);
    apply_toggle(o.indicator_point, d.view.display.indicator_point);
    apply_toggle(o.deboor, d.view.display.deboor);
    if (!o.select.empty() || !o.indicator.empty()) {
        if (!ui::current_surface(d)) {
            // Select the first surface so the options have something to act on.
            for (const doc::Object& obj : d.objects)
                if (obj.surface()) {
                    d.view.selection = {obj.id, -1, -1};
                    break;
                }
        }
        if (!ui::current_surface(d)) return "the scene has no surface for --select or --indicator";
        // The indicator first: in a patch group it picks the current patch (the one under it),
        // and --select then names a point of that patch.
        if (!o.indicator.empty()) {
            const auto uv = numbers(o.indicator, 2, 2);
            // Subpatches take the original domain their group tiles (core/doc/patches.hpp).
            const doc::Object* current = nullptr;
            ui::current_surface(d, &current);
            const geom::ParamRect r = doc::tracing_domain(d, *current);
            const geom::Interval du = r.u, dv = r.v;
            if (!uv || !du.contains((*uv)[0]) || !dv.contains((*uv)[1]))
                return "--indicator '" + o.indicator + "' must be U,V inside the domain [" +
                       geom::format_number(du.lo) + ", " + geom::format_number(du.hi) + "] x [" +
                       geom::format_number(dv.lo) + ", " + geom::format_number(dv.hi) + "]";
            d.view.indicator = {((*uv)[0] - du.lo) / (du.hi - du.lo),
                                ((*uv)[1] - dv.lo) / (dv.hi - dv.lo)};
            ui::follow_indicator(d, current->id);
        }
        if (!o.select.empty()) {
            const doc::Object* current = nullptr;
            const geom::Surface* s = ui::current_surface(d, &current);
            const auto ij = numbers(o.select, 2, 2);
            const int i = ij ? static_cast<int>((*ij)[0]) : -1,
                      j = ij ? static_cast<int>((*ij)[1]) : -1;
            if (!ij || (*ij)[0] != i || (*ij)[1] != j || i < 0 || j < 0 || i >= s->n_u ||
                j >= s->n_v)
                return "--select '" + o.select + "' must be I,J with 0 <= I < " +
                       std::to_string(s->n_u) + " and 0 <= J < " + std::to_string(s->n_v) +
                       " (a point of " + current->name + ")";
            d.view.selection = {current->id, i, j};
        }
    }
    if (o.deboor_step != -1) {
        // A selected triangle steps through de Casteljau's levels 0..n instead.
        const geom::TrianglePatch* t = ui::selected_triangle(d);
        const doc::Object* current = nullptr;
        const geom::Surface* s = t ? nullptr : ui::current_surface(d, &current);
        const int last = t ? t->degree : s ? s->degree_u + s->degree_v + 1 : 0;
        if ((!s && !t) || o.deboor_step < 0 || o.deboor_step > last)
            return "--deboor-step " + std::to_string(o.deboor_step) + " must be 0.." +
                   std::to_string(last) +
                   (t ? " (the levels of the selected triangle's de Casteljau construction)"
                      : " (p_u + p_v + 1 steps for the current surface)");
        d.view.display.deboor = true;
        ctx.ui.deboor.step = static_cast<int>(o.deboor_step);
    }
    if (!o.camera.empty()) {
        const auto c = numbers(o.camera, 2, 3);
        if (!c || std::abs((*c)[1]) >= 90 || (c->size() == 3 && (*c)[2] <= 0))
            return "--camera '" + o.camera +
                   "' must be YAW,PITCH[,ZOOM]: degrees, pitch strictly between -90 and 90, zoom a "
                   "percentage above 0 (100 = fit to view)";
        ctx.ui.camera.yaw = (*c)[0] * M_PI / 180.0;
        ctx.ui.camera.pitch = (*c)[1] * M_PI / 180.0;
        if (c->size() == 3) ctx.ui.zoom_after_fit = (*c)[2] / 100.0;
    }
    return "";
}

namespace {

// The names --analysis accepts: the scene file's, from the same table.
std::vector<std::string> analysis_names() {
    std::vector<std::string> out;
    for (const auto& entry : doc::analysis_mode_names) out.emplace_back(entry.name);
    return out;
}

// The names --style accepts: the scene file's, from the same table.
std::vector<std::string> display_style_names() {
    std::vector<std::string> out;
    for (const auto& entry : doc::display_style_names) out.emplace_back(entry.name);
    return out;
}

} // namespace

void add_view_options(CLI::App* sub, ViewOptions& o) {
    sub->add_option("--indicator", o.indicator,
                    "position indicator U,V (parameters in the domain)");
    sub->add_option("--select", o.select, "select control point I,J of the current surface");
    sub->add_option("--style", o.style, "shaded, wireframe or both")
        ->check(CLI::IsMember(display_style_names()));
    sub->add_option("--analysis", o.analysis,
                    "colour the shaded surfaces: gauss, mean, kmax, kmin (curvature, with a colour "
                    "bar), zebra, isophote or off")
        ->check(CLI::IsMember(analysis_names()));
    sub->add_option("--camera", o.camera,
                    "YAW,PITCH[,ZOOM]: orbit angles in degrees, zoom in percent of fit-to-view");
    sub->add_flag("--points,!--no-points", o.points, "show / hide control points");
    sub->add_flag("--net,!--no-net", o.net, "show / hide the control net");
    sub->add_flag("--ids,!--no-ids", o.ids, "show / hide control-point IDs (P_ij)");
    sub->add_flag("--knot-curves,!--no-knot-curves", o.knot_curves, "show / hide knot curves");
    sub->add_flag("--indicator-point,!--no-indicator-point", o.indicator_point,
                  "show / hide the point S(u,v) under the indicator");
    sub->add_flag("--deboor,!--no-deboor", o.deboor, "show / hide de Boor's construction");
    sub->add_option("--deboor-step", o.deboor_step,
                    "de Boor's construction up to step N (0: the acting control points; "
                    "a selected triangle: de Casteljau's level N; implies --deboor)");
}

} // namespace isoparm::app
