// The multires_edit command: one shape edit (shape_edit.hpp) whose new shape is the
// multiresolution edit's (geom/multires_edit.hpp); the knots, degree and type stay.
#include "core/doc/commands_multires.hpp"

#include <cmath>
#include <sstream>
#include <string>

#include "core/doc/commands_common.hpp"
#include "core/doc/commands_curve.hpp"
#include "core/doc/shape_edit.hpp"
#include "core/geom/multires.hpp"
#include "core/geom/multires_edit.hpp"

namespace isoparm::doc {

namespace {

using geom::ErrorCode;
using geom::make_error;

std::string number_text(double x) {
    std::ostringstream out;
    out << x;
    return out.str();
}

// The spec's own rules, before any geometry: one kind of edit, and the members that kind of
// object takes.
geom::Status check_members(const MultiresEditSpec& s, const Object& obj) {
    if (!s.position && !s.detail_scale)
        return make_error(ErrorCode::schema,
                          "a multiresolution edit needs a position (move a coarse point) or a "
                          "detail_scale (scale the detail)",
                          "/position");
    if (s.position && s.detail_scale)
        return make_error(ErrorCode::schema,
                          "a multiresolution edit either moves a coarse point (position) or "
                          "scales the detail (detail_scale), not both",
                          "/detail_scale");
    if (s.position)
        for (int a = 0; a < 3; ++a)
            if (!std::isfinite((*s.position)[a]))
                return make_error(ErrorCode::schema,
                                  "a coarse control point needs finite coordinates",
                                  "/position/" + std::to_string(a));
    const bool surface = obj.surface() != nullptr;
    if (surface && !s.level_v)
        return make_error(ErrorCode::schema,
                          "object '" + obj.name + "' is a surface: give its v level (level_v)",
                          "/level_v");
    if (!surface && s.level_v)
        return make_error(ErrorCode::schema,
                          "object '" + obj.name + "' is a curve: it has one level (no level_v)",
                          "/level_v");
    if (!surface && s.j != -1)
        return make_error(ErrorCode::schema,
                          "object '" + obj.name +
                              "' is a curve: its coarse points take i alone "
                              "(j = " +
                              std::to_string(s.j) + " given)",
                          "/j");
    return geom::Ok{};
}

geom::Expected<Shape> edited_shape(const MultiresEditSpec& s, const Object& obj) {
    if (auto levels = multires_levels_of(obj); !levels) return levels.error();
    if (auto st = check_members(s, obj); !st) return st.error();
    Shape out = obj.shape;
    if (const geom::Surface* surface = obj.surface()) {
        auto made = s.position ? geom::multires_move_coarse_point(*surface, s.level, *s.level_v,
                                                                  s.i, s.j, *s.position)
                               : geom::multires_scale_detail(*surface, s.level, *s.level_v,
                                                             *s.detail_scale);
        if (!made) return made.error();
        *surface_of(out) = std::move(made).value();
    } else {
        const geom::Curve& curve = *obj.curve();
        auto made = s.position ? geom::multires_move_coarse_point(curve, s.level, s.i, *s.position)
                               : geom::multires_scale_detail(curve, s.level, *s.detail_scale);
        if (!made) return made.error();
        *curve_of(out) = std::move(made).value();
    }
    return out;
}

std::string label_of(const MultiresEditSpec& s) {
    const std::string level =
        s.level_v ? "levels " + std::to_string(s.level) + " x " + std::to_string(*s.level_v)
                  : "level " + std::to_string(s.level);
    if (s.position)
        return "Move coarse point " +
               (s.j < 0 ? std::to_string(s.i) : std::to_string(s.i) + "," + std::to_string(s.j)) +
               " at " + level + " (detail kept)";
    if (*s.detail_scale == 0.0) return "Remove the detail above " + level;
    return "Scale the detail above " + level + " by " + number_text(*s.detail_scale);
}

// The geometry names the offending value inside the shape ("/knots/5"); the command's member
// at fault is the object.
geom::Error about_object(geom::Error e, const Object& object) {
    e.message = "object '" + object.name + "': " + e.message;
    e.path = "/id";
    return e;
}

} // namespace

geom::Expected<std::pair<int, int>> multires_levels_of(const Object& object) {
    if (const geom::Surface* s = object.surface()) {
        auto J = geom::multires_levels(*s);
        if (!J) return about_object(J.error(), object);
        return J;
    }
    const CurveObject* c = object.curve_object();
    if (!c)
        return kind_refusal(object,
                            "multiresolution editing decomposes a cubic B-spline curve or surface");
    if (c->knot_mode == CurveKnotMode::chord || c->knot_mode == CurveKnotMode::centripetal ||
        c->knot_mode == CurveKnotMode::closed)
        return make_error(ErrorCode::knots,
                          "curve '" + object.name + "' has " + knot_mode_label(c->knot_mode) +
                              " knots, which follow its polygon: set the knot mode to clamped "
                              "uniform first",
                          "/id");
    auto J = geom::multires_level(c->curve);
    if (!J) return about_object(J.error(), object);
    return std::pair{*J, -1};
}

std::unique_ptr<Command> multires_edit(MultiresEditSpec spec) {
    detail::ShapeEditRule rule;
    rule.make = [spec](const Object& obj) { return edited_shape(spec, obj); };
    rule.label = [label = label_of(spec)](const Shape&, const Shape&) { return label; };
    if (spec.position)
        rule.merge_key = "multires " + std::to_string(spec.level) + " " +
                         std::to_string(spec.level_v.value_or(-1)) + " " + std::to_string(spec.i) +
                         " " + std::to_string(spec.j);
    rule.shape_path = "/shape";
    const std::uint64_t id = spec.id;
    return detail::shape_edit(id, std::move(spec), std::move(rule));
}

} // namespace isoparm::doc
