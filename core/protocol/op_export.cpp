// The `export` op (geom-protocol-2.md, Exchange): one object as the text of a file in an exact
// format (iges, step, obj) or as a mesh (obj_mesh, stl_ascii, ply).
#include "core/exchange/iges_writer.hpp"
#include "core/exchange/obj_writer.hpp"
#include "core/exchange/step_writer.hpp"
#include "core/geom/tessellate.hpp"
#include "core/geom/triangle.hpp"
#include "core/geom/trim/trimmed_tessellator.hpp"
#include "core/geom/work_budget.hpp"
#include "core/json/shapes.hpp"
#include "core/protocol/detail.hpp"

namespace isoparm::protocol {

using geom::Expected;

namespace {

enum class Format { iges, step, obj, obj_mesh, stl_ascii, ply };
constexpr geom::EnumName<Format> format_names[] = {
    {Format::iges, "iges"},         {Format::step, "step"},           {Format::obj, "obj"},
    {Format::obj_mesh, "obj_mesh"}, {Format::stl_ascii, "stl_ascii"}, {Format::ply, "ply"}};
static_assert(geom::in_declaration_order(format_names));
constexpr std::span<const geom::EnumName<Format>> enum_names(Format) {
    return format_names;
}

bool is_mesh(Format f) {
    return f == Format::obj_mesh || f == Format::stl_ascii || f == Format::ply;
}

Expected<Format> read_format(const json& request) {
    const json* f = find_member(request, "format");
    if (!f) return missing_member("", "format");
    if (const std::optional<Format> format = enum_value<Format>(*f)) return *format;
    return schema_error("format must be one of " + geom::names_list<Format>(", "), "/format");
}

std::string mesh_text(Format f, const geom::Mesh& mesh) {
    if (f == Format::obj_mesh) return exchange::obj_mesh_text({mesh});
    if (f == Format::stl_ascii) return exchange::stl_ascii_text({mesh}, "isoparm");
    return exchange::ply_text({mesh});
}

// A triangle's samples: [n, n] subdivisions per edge (the first is used), default 32.
Expected<int> triangle_samples(const json& request, const geom::TrianglePatch& t) {
    int n = 32;
    if (const json* s = find_member(request, "samples")) {
        if (!s->is_array() || s->size() != 2)
            return schema_error("samples is [n_u, n_v]", "/samples");
        Expected<std::int64_t> k = read_integer((*s)[0], "/samples/0", "samples", 1, 4096);
        if (!k) return k.error();
        n = static_cast<int>(*k);
    }
    if (geom::Status ok = geom::spend_work(
            geom::estimate_triangle_de_casteljau((n + 1.0) * (n + 2.0) / 2, t.degree, 1, false),
            "/samples", "a triangle mesh");
        !ok)
        return ok.error();
    return n;
}

json text_answer(std::string text) {
    json answer = json::object();
    answer["text"] = std::move(text);
    return answer;
}

} // namespace

OpResult op_export(const json& request) {
    if (geom::Status s = check_fields(
            request, "export", {"curve", "surface", "trim", "triangle", "format", "samples"});
        !s)
        return s.error();
    if (find_member(request, "triangle")) {
        if (find_member(request, "curve") || find_member(request, "surface"))
            return schema_error("give exactly one of curve, surface or triangle", "/triangle");
        Expected<geom::TrianglePatch> t = triangle_from_json(*find_member(request, "triangle"));
        if (!t) return t.error().under("/triangle");
        Expected<Format> format = read_format(request);
        if (!format) return format.error();
        if (!is_mesh(*format))
            return schema_error("a triangle exports as a mesh: obj_mesh, stl_ascii or ply",
                                "/format");
        Expected<int> n = triangle_samples(request, *t);
        if (!n) return n.error();
        return text_answer(mesh_text(*format, geom::tessellate_triangle(*t, *n)));
    }
    Expected<Subject> subject = read_subject(request, true, true);
    if (!subject) return subject.error();
    Expected<Format> format = read_format(request);
    if (!format) return format.error();
    const char* member = subject->is_surface ? "/surface" : "/curve";
    if (!subject->is_surface && find_member(request, "trim"))
        return schema_error("a trim belongs to a surface", "/trim");
    Expected<std::optional<geom::Trim>> trim =
        subject->is_surface ? read_trim(request, subject->surface)
                            : Expected<std::optional<geom::Trim>>(std::optional<geom::Trim>{});
    if (!trim) return trim.error();
    if (is_mesh(*format)) {
        if (!subject->is_surface)
            return schema_error("a curve has no mesh: export it as iges, step or obj", "/format");
        json defaults = request;
        if (!find_member(request, "samples")) defaults["samples"] = json::array({32, 32});
        Expected<std::array<int, 2>> n =
            read_grid_samples(defaults, subject->surface.degree_u, subject->surface.degree_v);
        if (!n) return n.error();
        return text_answer(mesh_text(
            *format, *trim ? geom::tessellate_trimmed(subject->surface, **trim, (*n)[0], (*n)[1])
                           : geom::tessellate(subject->surface, (*n)[0], (*n)[1])));
    }
    const exchange::ExactShape shape =
        !subject->is_surface ? exchange::ExactShape(subject->curve)
        : *trim              ? exchange::ExactShape(geom::TrimmedSurface{subject->surface, **trim})
                             : exchange::ExactShape(subject->surface);
    if (*format == Format::obj) return text_answer(exchange::obj_freeform_text({shape}));
    Expected<std::string> text = *format == Format::step ? exchange::step_text({shape}, "isoparm")
                                                         : exchange::iges_text({shape}, "isoparm");
    if (!text) return text.error().under(member);
    return text_answer(std::move(text).value());
}

} // namespace isoparm::protocol
