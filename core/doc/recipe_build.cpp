// The isocurve construction and the refinements a recipe repeats after its construction.
#include "core/doc/recipe_build.hpp"

#include <cmath>

#include "core/doc/commands_common.hpp"
#include "core/geom/knots.hpp"
#include "core/geom/rational_picture.hpp"
#include "core/geom/refine.hpp"
#include "core/geom/refine_within_limits.hpp"

namespace isoparm::doc::detail {

using geom::ErrorCode;
using geom::make_error;

geom::Expected<ConstructionResult> build_isocurve(const Document& doc,
                                                  const ConstructionRequest& request) {
    if (request.curves.size() != 1)
        return make_error(ErrorCode::schema,
                          "Isocurve takes 1 surface, got " + std::to_string(request.curves.size()),
                          "/curves");
    const Object* o = doc.find(request.curves[0]);
    if (!o)
        return make_error(ErrorCode::schema,
                          "there is no object with id " + std::to_string(request.curves[0]),
                          "/curves/0");
    const geom::Surface* s = o->surface();
    if (!s)
        return make_error(ErrorCode::schema,
                          "an isocurve is taken from a surface; '" + o->name + "' is " +
                              kind_noun(o->kind()),
                          "/curves/0");
    const double t = request.iso_t;
    if (!std::isfinite(t) || t < 0 || t > 1)
        return make_error(ErrorCode::schema,
                          "the isocurve's parameter is in [0, 1] over the domain, got " +
                              geom::format_number(t),
                          "/param");
    const geom::Interval d = geom::domain(*s, request.iso_dir);
    // The ends exactly: a clamped edge is then the boundary row of control points itself.
    const double at = t == 0 ? d.lo : t == 1 ? d.hi : d.lo + t * (d.hi - d.lo);
    std::optional<geom::Curve> c = geom::isocurve(*s, request.iso_dir, at);
    const char* dir = geom::name_of(request.iso_dir);
    if (!c)
        return make_error(ErrorCode::weights,
                          "the isocurve of '" + o->name + "' at " + dir + " = " +
                              geom::format_number(at) +
                              " has a control point at infinity (its weights sum to 0)",
                          "/curves/0");
    ConstructionResult out;
    out.object.name = "isocurve " + o->name + " " + dir + " = " + geom::format_number(at);
    out.object.shape = CurveObject{std::move(*c), CurvePlane::free3d, CurveKnotMode::custom};
    out.note = std::string("the curve of '") + o->name + "' at " + dir + " = " +
               geom::format_number(at) + ", exact (Piegl & Tiller 3.4)";
    return out;
}

geom::Status apply_refinements(ConstructionResult& built,
                               const std::vector<RecipeRefinement>& refinements) {
    for (std::size_t k = 0; k < refinements.size(); ++k) {
        const RecipeRefinement& r = refinements[k];
        const std::string at = "/refinements/" + std::to_string(k);
        const bool insert = r.kind == RecipeRefinement::Kind::insert_knot;
        if (geom::Surface* s = built.object.surface()) {
            auto next = insert ? geom::insert_knot(*s, r.dir, r.t, r.times)
                               : geom::elevate_degree(*s, r.dir, r.times);
            if (!next) return next.error().under(at);
            *s = std::move(next).value();
            if (auto st = geom::check_net_size(*s, at); !st) return st;
        } else if (geom::Curve* c = built.object.curve()) {
            if (r.dir != geom::Dir::u)
                return make_error(ErrorCode::schema, "a curve has only one direction (u)",
                                  at + "/direction");
            auto next =
                insert ? geom::insert_knot(*c, r.t, r.times) : geom::elevate_degree(*c, r.times);
            if (!next) return next.error().under(at);
            *c = std::move(next).value();
            if (auto st = geom::check_net_size(*c, at); !st) return st;
        }
    }
    return geom::Ok{};
}

} // namespace isoparm::doc::detail
