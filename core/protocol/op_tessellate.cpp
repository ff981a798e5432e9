// The `tessellate` op: a surface over a uniform n_u x n_v parameter grid.
#include "core/geom/implicit/polygonize.hpp" // the mesh caps
#include "core/geom/tessellate.hpp"
#include "core/geom/trim/trimmed_tessellator.hpp"
#include "core/geom/validate.hpp"
#include "core/geom/work_budget.hpp"
#include "core/json/fields.hpp"
#include "core/json/shapes.hpp"
#include "core/protocol/detail.hpp"

namespace isoparm::protocol {

using geom::Expected;

// positions / normals / triangles as the protocol writes meshes (shared with polygonize):
// a vertex that does not exist is null in both positions and normals.
json mesh_to_json(const geom::Mesh& mesh) {
    json positions = json::array();
    json normals = json::array();
    for (std::size_t k = 0; k < mesh.positions.size(); ++k) {
        const bool exists = mesh.exists.empty() || mesh.exists[k];
        positions.push_back(exists ? point_to_json(mesh.positions[k]) : json(nullptr));
        normals.push_back(exists ? point_to_json(mesh.normals[k]) : json(nullptr));
    }
    json triangles = json::array();
    for (const auto& t : mesh.triangles) triangles.push_back(json::array({t[0], t[1], t[2]}));
    return json{{"positions", std::move(positions)},
                {"normals", std::move(normals)},
                {"triangles", std::move(triangles)}};
}

Expected<std::array<int, 2>> read_grid_samples(const json& request, int degree_u, int degree_v) {
    const json* samples = find_member(request, "samples");
    if (!samples) return missing_member("", "samples");
    if (!samples->is_array() || samples->size() != 2)
        return schema_error("samples is [n_u, n_v]", "/samples");
    std::int64_t n[2];
    for (int k = 0; k < 2; ++k) {
        const std::optional<std::int64_t> v =
            integer_value((*samples)[static_cast<std::size_t>(k)]);
        if (!v || *v < 2)
            return schema_error("samples are integers >= 2", "/samples/" + std::to_string(k));
        n[k] = *v;
    }
    // The cap before any allocation (saturated values keep the product from overflowing).
    const std::int64_t cap = geom::max_evaluation_points;
    if (n[0] > cap || n[1] > cap || n[0] * n[1] > cap) {
        return geom::make_error(geom::ErrorCode::limit,
                                "too many grid points (" + std::to_string(n[0]) + " x " +
                                    std::to_string(n[1]) + " > " + std::to_string(cap) + ")",
                                "/samples");
    }
    // The answer-size cap (docs/protocol.md): n_u * n_v vertices, 2 (n_u - 1)(n_v - 1)
    // triangles, both within the mesh caps when the vertices are.
    if (static_cast<std::size_t>(n[0] * n[1]) > geom::max_mesh_vertices) {
        return geom::make_error(geom::ErrorCode::limit,
                                "the mesh would have " + std::to_string(n[0] * n[1]) +
                                    " vertices (" + std::to_string(n[0]) + " x " +
                                    std::to_string(n[1]) + "); at most " +
                                    std::to_string(geom::max_mesh_vertices) + " are allowed",
                                "/samples");
    }
    const geom::WorkEstimate cost = geom::estimate_tessellation(
        static_cast<double>(n[0]), static_cast<double>(n[1]), degree_u, degree_v);
    if (geom::Status ok =
            geom::spend_work(cost, "/samples",
                             "a " + std::to_string(n[0]) + " x " + std::to_string(n[1]) +
                                 " tessellation of a degree (" + std::to_string(degree_u) + ", " +
                                 std::to_string(degree_v) + ") surface");
        !ok)
        return ok.error();
    return std::array<int, 2>{static_cast<int>(n[0]), static_cast<int>(n[1])};
}

Expected<geom::Mesh> tessellate_mesh(const json& request) {
    if (find_member(request, "curve"))
        return schema_error("tessellate takes a surface, not a curve", "/curve");
    if (geom::Status s =
            check_fields(request, "tessellate", {"surface", "samples", "trim", "tolerance"});
        !s)
        return s.error();
    Expected<Subject> subject = read_subject(request, false, true);
    if (!subject) return subject.error();
    Expected<std::optional<geom::Trim>> trim = read_trim(request, subject->surface);
    if (!trim) return trim.error();
    Expected<std::array<int, 2>> n =
        read_grid_samples(request, subject->surface.degree_u, subject->surface.degree_v);
    if (!n) return n.error();
    double tolerance = 0; // the default: geom::default_chord_tolerance
    if (const json* t = find_member(request, "tolerance")) {
        if (!*trim)
            return schema_error("tolerance is for a trimmed tessellation (give trim)",
                                "/tolerance");
        if (!is_finite_number(*t) || !(t->get<double>() > 0))
            return schema_error("tolerance is a positive number (the largest distance, in the "
                                "model's units, between a loop on the surface and the mesh)",
                                "/tolerance");
        tolerance = t->get<double>();
        // Chords are cut at 1/1024 of the default at the finest: a far smaller tolerance asks
        // for more chords than the mesh caps allow.
        const double floor = 1e-6 * geom::default_chord_tolerance(subject->surface);
        if (tolerance < floor)
            return geom::make_error(geom::ErrorCode::limit,
                                    "tolerance " + geom::format_number(tolerance) +
                                        " is below the smallest allowed here (" +
                                        geom::format_short(floor, 3) +
                                        ", a millionth of the default)",
                                    "/tolerance");
    }
    if (*trim)
        return geom::tessellate_trimmed(subject->surface, **trim, (*n)[0], (*n)[1], tolerance);
    return geom::tessellate(subject->surface, (*n)[0], (*n)[1]);
}

OpResult op_tessellate(const json& request) {
    Expected<geom::Mesh> mesh = tessellate_mesh(request);
    if (!mesh) return mesh.error();
    return mesh_to_json(*mesh);
}

} // namespace isoparm::protocol
