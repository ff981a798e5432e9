// The `polygonize` op: a triangle mesh of f(x, y, z) = 0 inside a box.
#include <cmath>

#include "core/geom/implicit/expression.hpp"
#include "core/geom/implicit/polygonize.hpp"
#include "core/geom/validate.hpp"
#include "core/geom/work_budget.hpp"
#include "core/protocol/detail.hpp"

namespace isoparm::protocol {

using geom::ErrorCode;
using geom::Expected;

Expected<geom::Mesh> polygonize_mesh(const json& request) {
    if (geom::Status s = check_fields(request, "polygonize", {"implicit", "bounds", "cell"}); !s)
        return s.error();

    const json* implicit = find_member(request, "implicit");
    if (!implicit) return missing_member("", "implicit");
    if (!implicit->is_string())
        return schema_error("implicit is an expression in x, y, z (a string)", "/implicit");
    Expected<geom::implicit::Program> program =
        geom::implicit::compile(implicit->get_ref<const std::string&>());
    if (!program) {
        geom::Error e = program.error();
        e.path = "/implicit"; // the message names the column
        e.has_path = true;
        return e;
    }

    // bounds: [[xmin, ymin, zmin], [xmax, ymax, zmax]] with min < max on every axis.
    const json* bounds = find_member(request, "bounds");
    if (!bounds) return missing_member("", "bounds");
    if (!bounds->is_array() || bounds->size() != 2)
        return schema_error("bounds is [[xmin, ymin, zmin], [xmax, ymax, zmax]]", "/bounds");
    glm::dvec3 corner[2];
    for (int c = 0; c < 2; ++c) {
        const json& b = (*bounds)[static_cast<std::size_t>(c)];
        const std::string path = "/bounds/" + std::to_string(c);
        if (!b.is_array() || b.size() != 3) return schema_error("a corner is [x, y, z]", path);
        for (int k = 0; k < 3; ++k) {
            Expected<double> x = read_finite(b[static_cast<std::size_t>(k)],
                                             path + "/" + std::to_string(k), "a coordinate");
            if (!x) return x.error();
            corner[c][k] = *x;
        }
    }
    for (int k = 0; k < 3; ++k) {
        if (!(corner[0][k] < corner[1][k])) {
            return schema_error(std::string("the box is empty along ") + "xyz"[k] + ": min " +
                                    geom::format_number(corner[0][k]) + " must be less than max " +
                                    geom::format_number(corner[1][k]),
                                "/bounds");
        }
        if (!std::isfinite(corner[1][k] - corner[0][k]))
            return schema_error("the box is too large", "/bounds");
    }

    Expected<double> cell = required_number(request, "cell");
    if (!cell) return cell.error();
    if (!(*cell > 0)) return schema_error("cell is a number > 0", "/cell");

    // ceil(extent / cell) cells per axis (convention 18); the grid's corners count toward
    // the evaluation cap (convention 19), checked before anything is allocated.
    double points = 1;
    for (int k = 0; k < 3; ++k) {
        const double cells = std::max(1.0, std::ceil((corner[1][k] - corner[0][k]) / *cell));
        points *= cells + 1;
    }
    if (!(points <= static_cast<double>(geom::max_evaluation_points))) {
        return geom::make_error(
            ErrorCode::limit,
            "the grid would have " + geom::format_number(points) + " points; at most " +
                std::to_string(geom::max_evaluation_points) + " are allowed (use a larger cell)",
            "/cell");
    }

    const auto instructions = static_cast<double>(program->instruction_count());
    const geom::WorkEstimate cost = geom::estimate_polygonization(points, instructions);
    // Blame the long expression when it is long, else the fine grid.
    if (geom::Status ok = geom::spend_work(
            cost, instructions > 64 ? "/implicit" : "/cell",
            "an expression of " + std::to_string(program->instruction_count()) +
                " operations on a grid of " + geom::with_thousands(points) + " points");
        !ok)
        return ok.error();

    geom::implicit::PolygonizeOptions options;
    options.lo = corner[0];
    options.hi = corner[1];
    options.cell = *cell;
    Expected<geom::Mesh> mesh = geom::implicit::polygonize(*program, options);
    if (!mesh) {
        geom::Error e = mesh.error();
        if (!e.has_path || e.path.empty()) {
            // Map the polygonizer's errors onto the request's fields.
            e.has_path = true;
            e.path = e.code == ErrorCode::limit   ? "/cell"
                     : e.code == ErrorCode::parse ? "/implicit"
                                                  : "/bounds";
        }
        return e;
    }
    return mesh;
}

OpResult op_polygonize(const json& request) {
    Expected<geom::Mesh> mesh = polygonize_mesh(request);
    if (!mesh) return mesh.error();
    return mesh_to_json(*mesh);
}

} // namespace isoparm::protocol
