#include "core/exchange/obj_writer.hpp"

#include <glm/geometric.hpp>

#include "core/exchange/real_text.hpp"
#include "core/geom/knots.hpp"

namespace isoparm::exchange {

namespace {

std::string point_text(const glm::dvec3& p) {
    return real_text(p.x) + " " + real_text(p.y) + " " + real_text(p.z);
}

std::string parm_line(char dir, const geom::Knots& knots) {
    std::string line = std::string("parm ") + dir;
    for (double t : knots) line += " " + real_text(t);
    return line + "\n";
}

} // namespace

std::string obj_freeform_text(const std::vector<ExactShape>& shapes) {
    std::string out = "# isoparm: exact NURBS geometry (OBJ free-form)\n";
    long next_vertex = 1, next_vp = 1, next_curv2 = 1;
    for (const ExactShape& shape : shapes) {
        if (const auto* c = std::get_if<geom::Curve>(&shape)) {
            const bool rational = geom::is_rational(c->type);
            const long first = next_vertex;
            for (int i = 0; i < c->count(); ++i, ++next_vertex)
                out += "v " + point_text(c->points[i]) +
                       (rational ? " " + real_text(c->weights[i]) : "") + "\n";
            const geom::Interval d = geom::domain(*c);
            out += std::string("cstype ") + (rational ? "rat " : "") + "bspline\ndeg " +
                   std::to_string(c->degree) + "\ncurv " + real_text(d.lo) + " " + real_text(d.hi);
            for (long k = first; k < next_vertex; ++k) out += " " + std::to_string(k);
            out += "\n" + parm_line('u', c->knots) + "end\n";
            continue;
        }
        const geom::Surface& s = *surface_of(shape);
        // A trimmed surface's loop curves first: curv2 elements on parameter vertices (vp),
        // numbered from 1 in file order as the trim and hole statements refer to them.
        std::string loops;
        if (const auto* t = std::get_if<geom::TrimmedSurface>(&shape)) {
            auto loop_line = [&](const char* keyword, const geom::TrimLoop& loop) {
                std::string line = keyword;
                for (const geom::Curve& c : loop.curves) {
                    const bool rat = geom::is_rational(c.type);
                    const long first_vp = next_vp;
                    for (int i = 0; i < c.count(); ++i, ++next_vp)
                        out += "vp " + real_text(c.points[i].x) + " " + real_text(c.points[i].y) +
                               (rat ? " " + real_text(c.weights[i]) : "") + "\n";
                    out += std::string("cstype ") + (rat ? "rat " : "") + "bspline\ndeg " +
                           std::to_string(c.degree) + "\ncurv2";
                    for (long k = first_vp; k < next_vp; ++k) out += " " + std::to_string(k);
                    out += "\n" + parm_line('u', c.knots) + "end\n";
                    const geom::Interval d = geom::domain(c);
                    line += " " + real_text(d.lo) + " " + real_text(d.hi) + " " +
                            std::to_string(next_curv2++);
                }
                loops += line + "\n";
            };
            if (t->trim.outer) loop_line("trim", *t->trim.outer);
            for (const geom::TrimLoop& h : t->trim.holes) loop_line("hole", h);
        }
        const bool rational = geom::is_rational(s.type);
        const long first = next_vertex;
        for (int j = 0; j < s.n_v; ++j)
            for (int i = 0; i < s.n_u; ++i, ++next_vertex)
                out += "v " + point_text(s.point(i, j)) +
                       (rational ? " " + real_text(s.weight(i, j)) : "") + "\n";
        const geom::Interval du = geom::domain(s, geom::Dir::u);
        const geom::Interval dv = geom::domain(s, geom::Dir::v);
        out += std::string("cstype ") + (rational ? "rat " : "") + "bspline\ndeg " +
               std::to_string(s.degree_u) + " " + std::to_string(s.degree_v) + "\nsurf " +
               real_text(du.lo) + " " + real_text(du.hi) + " " + real_text(dv.lo) + " " +
               real_text(dv.hi);
        for (long k = first; k < next_vertex; ++k) out += " " + std::to_string(k);
        out += "\n" + parm_line('u', s.knots_u) + parm_line('v', s.knots_v) + loops + "end\n";
    }
    return out;
}

std::string obj_mesh_text(const std::vector<geom::Mesh>& meshes) {
    std::string out = "# isoparm: triangle mesh\n";
    std::size_t base = 1;
    for (const geom::Mesh& m : meshes) {
        for (std::size_t k = 0; k < m.positions.size(); ++k)
            out += "v " + point_text(m.positions[k]) + "\n";
        for (std::size_t k = 0; k < m.normals.size(); ++k)
            out += "vn " + point_text(m.normals[k]) + "\n";
        for (const auto& t : m.triangles) {
            out += "f";
            for (std::uint32_t v : t)
                out += " " + std::to_string(base + v) + "//" + std::to_string(base + v);
            out += "\n";
        }
        base += m.positions.size();
    }
    return out;
}

std::string stl_ascii_text(const std::vector<geom::Mesh>& meshes, const std::string& name) {
    std::string out = "solid " + name + "\n";
    for (const geom::Mesh& m : meshes)
        for (const auto& t : m.triangles) {
            const glm::dvec3 &a = m.positions[t[0]], &b = m.positions[t[1]], &c = m.positions[t[2]];
            const glm::dvec3 n = glm::cross(b - a, c - a);
            const double length = glm::length(n);
            out += "  facet normal " + point_text(length > 0 ? n / length : glm::dvec3(0.0)) +
                   "\n    outer loop\n";
            for (const glm::dvec3* p : {&a, &b, &c}) out += "      vertex " + point_text(*p) + "\n";
            out += "    endloop\n  endfacet\n";
        }
    return out + "endsolid " + name + "\n";
}

std::string ply_text(const std::vector<geom::Mesh>& meshes) {
    std::size_t vertices = 0, faces = 0;
    for (const geom::Mesh& m : meshes) vertices += m.positions.size(), faces += m.triangles.size();
    std::string out = "ply\nformat ascii 1.0\ncomment isoparm: triangle mesh\nelement vertex " +
                      std::to_string(vertices) +
                      "\nproperty double x\nproperty double y\nproperty double z\n"
                      "property double nx\nproperty double ny\nproperty double nz\n"
                      "element face " +
                      std::to_string(faces) +
                      "\nproperty list uchar uint vertex_indices\nend_header\n";
    for (const geom::Mesh& m : meshes)
        for (std::size_t k = 0; k < m.positions.size(); ++k)
            out += point_text(m.positions[k]) + " " + point_text(m.normals[k]) + "\n";
    std::size_t base = 0;
    for (const geom::Mesh& m : meshes) {
        for (const auto& t : m.triangles)
            out += "3 " + std::to_string(base + t[0]) + " " + std::to_string(base + t[1]) + " " +
                   std::to_string(base + t[2]) + "\n";
        base += m.positions.size();
    }
    return out;
}

} // namespace isoparm::exchange
