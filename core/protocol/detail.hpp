// Internal to the geom protocol: the op table's handler type and the shared field readers.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <initializer_list>
#include <iosfwd>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/geom/interpolate.hpp"
#include "core/geom/status.hpp"
#include "core/geom/trim/trim.hpp"
#include "core/geom/types.hpp"
#include "core/json/fields.hpp"

namespace isoparm::geom {
struct Mesh;
}

namespace isoparm::protocol {

using json = nlohmann::json;
// The ops read requests and write answers with the strict JSON module's helpers throughout.
using namespace isoparm::json_io;

// A handler gets one request object (already known to be an object with a string "op") and
// returns the success members (without "ok") or an error whose path is relative to the
// request ("/params/3").
using OpResult = geom::Expected<json>;
using OpHandler = OpResult (*)(const json& request);

// One file per op family; each op is one line in protocol.cpp's table.
OpResult op_evaluate(const json& request);  // op_evaluate.cpp
OpResult op_basis(const json& request);     // op_basis.cpp
OpResult op_deboor(const json& request);    // op_deboor.cpp
OpResult op_curvature(const json& request); // op_curvature.cpp
OpResult op_blossom(const json& request);   // op_blossom.cpp
OpResult op_convert(const json& request);   // op_convert.cpp
OpResult op_close(const json& request);     // op_reshape.cpp
// Triangular patches (op_triangle.cpp): evaluate, elevate_degree and split hand a request with
// a `triangle` to these; de_casteljau is theirs alone.
OpResult op_triangle_evaluate(const json& request);
OpResult op_triangle_elevate(const json& request);
OpResult op_triangle_split(const json& request);
OpResult op_de_casteljau(const json& request);
OpResult op_export(const json& request); // op_export.cpp
OpResult op_import(const json& request); // op_import.cpp
OpResult op_split_knot(const json& request);
OpResult op_tessellate(const json& request);  // op_tessellate.cpp
OpResult op_insert_knot(const json& request); // op_refine.cpp
OpResult op_elevate_degree(const json& request);
OpResult op_split(const json& request);
OpResult op_polygonize(const json& request);  // op_polygonize.cpp
OpResult op_interpolate(const json& request); // op_fitting.cpp
OpResult op_approximate(const json& request);
OpResult op_remove_knot(const json& request); // op_reduce.cpp
OpResult op_reduce_degree(const json& request);
OpResult op_classify(const json& request); // op_trim.cpp
OpResult op_area(const json& request);
// The meshes of `tessellate` and `polygonize` before they become JSON: the text path writes
// them straight to the output (stream.hpp) instead of building a JSON tree.
geom::Expected<geom::Mesh> tessellate_mesh(const json& request);
geom::Expected<geom::Mesh> polygonize_mesh(const json& request);
// `evaluate` for the text path: checked and computed into compact values, written by the
// returned writer exactly as op_evaluate's answer would be (stream.hpp).
geom::Expected<std::function<void(std::string&, std::ostream&)>>
streamed_evaluate(const json& request);

// ---- fields ----------------------------------------------------------------------------
// Every member other than "op" must be in `allowed` (`schema` at the first unknown member).
geom::Status check_fields(const json& request, std::string_view op,
                          std::initializer_list<std::string_view> allowed);

geom::Expected<double> required_number(const json& request, std::string_view name);

// An integer (integral floats such as 3.0 accepted) within [lo, hi] or the default when
// absent; anything else is `schema` with `rule` as the message (convention 11).
geom::Expected<std::int64_t> integer_option(const json& request, std::string_view name,
                                            std::int64_t fallback, std::int64_t lo, std::int64_t hi,
                                            const std::string& rule);

// `parametrization`: "chord" (the default), "centripetal" or "uniform"; anything else is
// `schema` at "/parametrization".
geom::Expected<geom::Parametrization> read_parametrization(const json& request);

// An integer (integral floats such as 3.0 accepted) at `path`, saturated to the range of int so
// that the geometry code refuses a huge value with its own code and message; `schema` when it
// is not an integer.
geom::Expected<int> read_int(const json& v, const std::string& path, std::string_view what);

// ---- the geometry an op works on --------------------------------------------------------
struct Subject {
    bool is_surface = false;
    geom::Curve curve;
    geom::Surface surface;
};
// "/curve" or "/surface": where the subject is in the request.
inline std::string subject_path(const Subject& s) {
    return s.is_surface ? "/surface" : "/curve";
}
// A result the subject's weights make impossible (a control point at infinity or not finite)
// comes from geom without a path: its cause is the subject's weights.
inline geom::Error with_weights_path(const Subject& s, const geom::Error& e) {
    if (e.code != geom::ErrorCode::weights || e.has_path) return e;
    return geom::make_error(e.code, e.message, subject_path(s) + "/weights");
}
// Exactly one of "curve" / "surface" (`schema` at "/surface" when both are given), parsed
// and validated, errors under "/curve" or "/surface".
geom::Expected<Subject> read_subject(const json& request, bool allow_curve, bool allow_surface);

// `trim` (optional): read and checked against s's domain (geom::validate_trim), errors under
// "/trim" (op_trim.cpp).
geom::Expected<std::optional<geom::Trim>> read_trim(const json& request, const geom::Surface& s);

// `params`: a curve's, each a finite number in the domain; a surface's, each [u, v] with u and
// v in their domains (`schema` / `domain` at "/params/3", "/params/3/1").
geom::Expected<std::vector<double>> read_curve_params(const json& params,
                                                      const geom::Interval& domain);
geom::Expected<std::vector<std::array<double, 2>>> read_surface_params(const json& params,
                                                                       const geom::Surface& s);

// `direction` ("u" or "v"): required with a surface, refused with a curve (convention 2).
geom::Expected<geom::Dir> read_direction(const json& request, const Subject& subject);

// The start of an op on a curve, or a surface along a direction: its fields (check_fields),
// its subject (read_subject) and its direction (read_direction), in that order.
struct DirectedSubject {
    Subject subject;
    geom::Dir dir = geom::Dir::u;
};
geom::Expected<DirectedSubject>
read_directed_subject(const json& request, std::string_view op,
                      std::initializer_list<std::string_view> fields);

// `times`: an integer >= 1 (convention 11), default 1; kept as 64 bits, the ops bound it.
geom::Expected<std::int64_t> read_times(const json& request);

// `domain` error unless t lies in [lo, hi]: "parameter 1.5 outside the domain [0, 1]".
geom::Status check_in_domain(double t, const geom::Interval& domain, const std::string& path,
                             std::string_view what = "parameter");

// `samples` [n_u, n_v] of a surface grid: integers >= 2 (`schema`), within the grid and mesh
// caps and the work budget of a degree (degree_u, degree_v) tessellation (`limit`), all at
// "/samples" ("/samples/k"). Shared by tessellate and export.
geom::Expected<std::array<int, 2>> read_grid_samples(const json& request, int degree_u,
                                                     int degree_v);

// positions / normals / triangles; a vertex that does not exist is null (op_tessellate.cpp).
json mesh_to_json(const geom::Mesh& mesh);

// Writes an optional point ([x, y, z] or null).
json optional_point(const std::optional<glm::dvec3>& p);

} // namespace isoparm::protocol
