// Geometry objects <-> JSON as the geom protocol defines them (shared by protocol and scenes).
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <string_view>

#include "core/geom/status.hpp"
#include "core/geom/triangle.hpp"
#include "core/geom/types.hpp"

namespace isoparm::json_io {

// Parse and fully validate (schema, degree, knots, weights, limit). Error paths are relative
// to j ("/knots/5"); the caller prefixes its own location with Error::under().
geom::Expected<geom::Curve> curve_from_json(const nlohmann::json& j);
geom::Expected<geom::Surface> surface_from_json(const nlohmann::json& j);

// Always writes type, degree, knots, points (3D) and, for rational types, weights.
nlohmann::json curve_to_json(const geom::Curve& c);

// Triangular Bezier patches: {"type": "triangle_bezier" | "rational_triangle_bezier",
// "degree": n, "points": [...], "weights": [...]} (geom/triangle.hpp gives the order).
geom::Expected<geom::TrianglePatch> triangle_from_json(const nlohmann::json& j);
nlohmann::json triangle_to_json(const geom::TrianglePatch& t);
// A triangle parameter [r, s, t]: three finite numbers (`schema` at `path`, or at "path/k" for
// the coordinate at fault). Whether it lies in the triangle is the caller's rule.
geom::Expected<geom::Barycentric> triangle_param_from_json(const nlohmann::json& v,
                                                           const std::string& path);
nlohmann::json surface_to_json(const geom::Surface& s);

// A point [x, y] or [x, y, z] of finite numbers (z = 0 when omitted); `what` names it in the
// message ("a control point is [x, y] or [x, y, z]").
geom::Expected<glm::dvec3> read_point(const nlohmann::json& v, const std::string& path,
                                      std::string_view what = "a control point");

// A point that may not exist: [x, y, z], or null when any coordinate is not finite.
nlohmann::json point_to_json(const glm::dvec3& p);

} // namespace isoparm::json_io
