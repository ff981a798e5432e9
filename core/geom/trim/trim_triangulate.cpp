// Trimmed-domain triangulation: whole grid cells by parity along their rows, the cells the
// loops cross by CGAL's constrained Delaunay triangulation (the classic "mark domains" flood
// fill, CGAL manual 2D Triangulations 8.3, keeps its faces inside the loops).
#include "core/geom/trim/trim_triangulate.hpp"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Spatial_sort_traits_adapter_2.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>
#include <CGAL/property_map.h>
#include <CGAL/spatial_sort.h>
#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <deque>
#include <glm/geometric.hpp>
#include <limits>
#include <utility>

namespace isoparm::geom {

namespace {

constexpr std::uint32_t none = std::numeric_limits<std::uint32_t>::max();

struct VertexInfo {
    std::uint32_t id = none; // grid index (grid) or loop point index; none: made by CGAL
    bool grid = false;
};
struct FaceInfo {
    int kept = -1; // -1 not reached yet, 0 cut away, 1 kept
};

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Vb = CGAL::Triangulation_vertex_base_with_info_2<VertexInfo, Kernel>;
using Fb =
    CGAL::Triangulation_face_base_with_info_2<FaceInfo, Kernel,
                                              CGAL::Constrained_triangulation_face_base_2<Kernel>>;
using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
// Exact_predicates_tag: constraints that cross (chords of two loops closer than the flattening
// tolerance) get a vertex where they meet instead of failing.
using Cdt = CGAL::Constrained_Delaunay_triangulation_2<Kernel, Tds, CGAL::Exact_predicates_tag>;

double distance_to_segment(glm::dvec2 p, glm::dvec2 a, glm::dvec2 b) {
    const glm::dvec2 ab = b - a;
    const double len2 = glm::dot(ab, ab);
    if (len2 == 0.0) return glm::length(p - a);
    const double s = std::clamp(glm::dot(p - a, ab) / len2, 0.0, 1.0);
    return glm::length(p - (a + s * ab));
}

// The grid's cells, and which of them the loops cross.
class Cells {
public:
    Cells(const std::vector<double>& us, const std::vector<double>& vs) : us_(us), vs_(vs) {
        cu_ = static_cast<int>(us.size()) - 1;
        cv_ = static_cast<int>(vs.size()) - 1;
        cut_.assign(static_cast<std::size_t>(cu_) * cv_, 0);
        kept_.assign(cut_.size(), 0);
    }
    int cu() const { return cu_; }
    int cv() const { return cv_; }
    std::size_t at(int i, int j) const { return static_cast<std::size_t>(i) * cv_ + j; }
    // The cells [i0, i1] x [j0, j1] that a box [lo, hi] touches.
    int cell_u(double u) const { return cell(us_, u); }
    int cell_v(double v) const { return cell(vs_, v); }
    void mark_cut(glm::dvec2 lo, glm::dvec2 hi) {
        const int i0 = cell_u(lo.x), i1 = cell_u(hi.x), j0 = cell_v(lo.y), j1 = cell_v(hi.y);
        for (int i = i0; i <= i1; ++i)
            for (int j = j0; j <= j1; ++j) cut_[at(i, j)] = 1;
    }
    bool cut(int i, int j) const { return cut_[at(i, j)] != 0; }
    bool whole_kept(int i, int j) const {
        return i >= 0 && j >= 0 && i < cu_ && j < cv_ && kept_[at(i, j)] != 0 && !cut(i, j);
    }
    void set_kept(int i, int j) { kept_[at(i, j)] = 1; }
    std::uint32_t corner(int i, int j) const {
        return static_cast<std::uint32_t>(i) * static_cast<std::uint32_t>(vs_.size()) +
               static_cast<std::uint32_t>(j);
    }
    glm::dvec2 corner_uv(int i, int j) const {
        return {us_[static_cast<std::size_t>(i)], vs_[static_cast<std::size_t>(j)]};
    }

private:
    static int cell(const std::vector<double>& ts, double t) {
        const auto it = std::upper_bound(ts.begin(), ts.end(), t);
        const int k = static_cast<int>(it - ts.begin()) - 1;
        return std::clamp(k, 0, static_cast<int>(ts.size()) - 2);
    }
    const std::vector<double>& us_;
    const std::vector<double>& vs_;
    int cu_ = 0, cv_ = 0;
    std::vector<std::uint8_t> cut_, kept_;
};

} // namespace

glm::dvec2 TrimmedLayout::param(std::uint32_t k) const {
    if (k < grid_vertices.size()) {
        const auto g = grid_vertices[k];
        const auto nv = static_cast<std::uint32_t>(vs.size());
        return {us[g / nv], vs[g % nv]};
    }
    return loop_points[k - grid_vertices.size()];
}

namespace {

// The smallest cell's side: snapping distances are a millionth of it.
double smallest_cell(const std::vector<double>& us, const std::vector<double>& vs) {
    double cell_size = INFINITY;
    for (std::size_t i = 0; i + 1 < us.size(); ++i)
        cell_size = std::min(cell_size, us[i + 1] - us[i]);
    for (std::size_t j = 0; j + 1 < vs.size(); ++j)
        cell_size = std::min(cell_size, vs[j + 1] - vs[j]);
    return cell_size;
}

// The loops' chords, without repeated points.
std::vector<std::vector<glm::dvec2>> flat_loops(const Trim& trim, const FlattenRule& rule) {
    std::vector<std::vector<glm::dvec2>> loops;
    for (int k = 0; k < trim.loop_count(); ++k) {
        const FlatLoop flat = flatten_loop(trim.loop(k), rule);
        std::vector<glm::dvec2> pts;
        for (const glm::dvec2& p : flat.points)
            if (pts.empty() || p != pts.back()) pts.push_back(p);
        while (pts.size() > 1 && pts.back() == pts.front()) pts.pop_back();
        loops.push_back(std::move(pts));
    }
    return loops;
}

using Loops = std::vector<std::vector<glm::dvec2>>;

// Calls f(a, b) for every chord of every loop.
template <class F> void for_each_chord(const Loops& loops, F&& f) {
    for (const auto& pts : loops)
        for (std::size_t k = 0; k < pts.size(); ++k) f(pts[k], pts[(k + 1) % pts.size()]);
}

// Whole cells: kept by parity of the chords crossing their row to the left of their centre.
void keep_whole_cells(Cells& cells, const Loops& loops, const std::vector<double>& us,
                      const std::vector<double>& vs, bool start_kept) {
    std::vector<std::vector<double>> crossings(static_cast<std::size_t>(cells.cv()));
    std::vector<double> centres_v(static_cast<std::size_t>(cells.cv()));
    for (int j = 0; j < cells.cv(); ++j)
        centres_v[static_cast<std::size_t>(j)] =
            0.5 * (vs[static_cast<std::size_t>(j)] + vs[static_cast<std::size_t>(j) + 1]);
    for_each_chord(loops, [&](glm::dvec2 a, glm::dvec2 b) {
        const double lo = std::min(a.y, b.y), hi = std::max(a.y, b.y);
        // Rows whose centre c has (a.y > c) != (b.y > c): lo <= c < hi.
        auto first = std::lower_bound(centres_v.begin(), centres_v.end(), lo);
        for (auto it = first; it != centres_v.end() && *it < hi; ++it) {
            const double c = *it;
            if ((a.y > c) == (b.y > c)) continue;
            crossings[static_cast<std::size_t>(it - centres_v.begin())].push_back(
                a.x + (c - a.y) / (b.y - a.y) * (b.x - a.x));
        }
    });
    for (int j = 0; j < cells.cv(); ++j) {
        auto& xs = crossings[static_cast<std::size_t>(j)];
        std::sort(xs.begin(), xs.end());
        std::size_t passed = 0;
        for (int i = 0; i < cells.cu(); ++i) {
            const double c =
                0.5 * (us[static_cast<std::size_t>(i)] + us[static_cast<std::size_t>(i) + 1]);
            while (passed < xs.size() && xs[passed] < c) ++passed;
            if (!cells.cut(i, j) && (start_kept != (passed % 2 == 1))) cells.set_kept(i, j);
        }
    }
}

using Triangles = std::vector<std::array<std::uint32_t, 3>>;

// Two triangles per whole kept cell, as the grid has them (grid indices).
Triangles whole_cell_triangles(const Cells& cells, std::uint32_t nv) {
    Triangles tris;
    for (int i = 0; i < cells.cu(); ++i) {
        for (int j = 0; j < cells.cv(); ++j) {
            if (!cells.whole_kept(i, j)) continue;
            const std::uint32_t k = cells.corner(i, j);
            tris.push_back({k, k + nv, k + nv + 1});
            tris.push_back({k, k + nv + 1, k + 1});
        }
    }
    return tris;
}

constexpr std::size_t absent = std::numeric_limits<std::size_t>::max();

// What goes into the constrained triangulation: the loops' points, then the crossed cells'
// corners (those not on a chord), each with its info.
struct CutPoints {
    std::vector<glm::dvec2> loop_points;
    std::vector<Kernel::Point_2> points;
    std::vector<VertexInfo> infos;
    std::vector<std::vector<std::size_t>> loop_indices; // per loop, its indices in points
    std::vector<std::size_t> corner_index;              // per grid corner, or absent
};

// Grid corners within snap of a chord (left out: the loop's own points stand there).
std::vector<std::uint8_t> corners_near_loops(const Cells& cells, const Loops& loops,
                                             const std::vector<double>& us,
                                             const std::vector<double>& vs, double snap) {
    std::vector<std::uint8_t> near_loop(us.size() * vs.size(), 0);
    for_each_chord(loops, [&](glm::dvec2 a, glm::dvec2 b) {
        const glm::dvec2 lo = glm::min(a, b) - snap, hi = glm::max(a, b) + snap;
        const std::size_t i0 = std::lower_bound(us.begin(), us.end(), lo.x) - us.begin();
        const std::size_t j0 = std::lower_bound(vs.begin(), vs.end(), lo.y) - vs.begin();
        for (std::size_t i = i0; i < us.size() && us[i] <= hi.x; ++i)
            for (std::size_t j = j0; j < vs.size() && vs[j] <= hi.y; ++j)
                if (distance_to_segment({us[i], vs[j]}, a, b) <= snap)
                    near_loop[cells.corner(static_cast<int>(i), static_cast<int>(j))] = 1;
    });
    return near_loop;
}

CutPoints cut_points(const Cells& cells, const Loops& loops, const std::vector<double>& us,
                     const std::vector<double>& vs, double snap, std::uint32_t loop_base) {
    CutPoints c;
    c.loop_indices.resize(loops.size());
    for (std::size_t l = 0; l < loops.size(); ++l) {
        for (const glm::dvec2& p : loops[l]) {
            c.loop_indices[l].push_back(c.points.size());
            c.points.emplace_back(p.x, p.y);
            c.infos.push_back(
                {loop_base + static_cast<std::uint32_t>(c.loop_points.size()), false});
            c.loop_points.push_back(p);
        }
    }
    const std::vector<std::uint8_t> near_loop = corners_near_loops(cells, loops, us, vs, snap);
    c.corner_index.assign(us.size() * vs.size(), absent);
    for (int i = 0; i < cells.cu(); ++i) {
        for (int j = 0; j < cells.cv(); ++j) {
            if (!cells.cut(i, j)) continue;
            for (int di = 0; di <= 1; ++di)
                for (int dj = 0; dj <= 1; ++dj) {
                    const std::uint32_t g = cells.corner(i + di, j + dj);
                    if (near_loop[g] || c.corner_index[g] != absent) continue;
                    c.corner_index[g] = c.points.size();
                    const glm::dvec2 p = cells.corner_uv(i + di, j + dj);
                    c.points.emplace_back(p.x, p.y);
                    c.infos.push_back({g, true});
                }
        }
    }
    return c;
}

// The points go in along a Hilbert curve (CGAL's spatial_sort), each located from the one
// before; the handles come back in the points' order.
std::vector<Cdt::Vertex_handle> insert_points(Cdt& cdt, const CutPoints& c) {
    std::vector<std::size_t> order(c.points.size());
    for (std::size_t k = 0; k < order.size(); ++k) order[k] = k;
    // CGAL's property map takes &points[0]: an untrimmed domain has no point to sort.
    if (!c.points.empty())
        CGAL::spatial_sort(order.begin(), order.end(),
                           CGAL::Spatial_sort_traits_adapter_2<
                               Kernel, CGAL::Pointer_property_map<Kernel::Point_2>::const_type>(
                               CGAL::make_property_map(c.points)));
    std::vector<Cdt::Vertex_handle> handles(c.points.size());
    Cdt::Face_handle hint;
    for (std::size_t k : order) {
        handles[k] = cdt.insert(c.points[k], hint);
        if (handles[k]->info().id == none) handles[k]->info() = c.infos[k];
        hint = handles[k]->face();
    }
    return handles;
}

// The loops' chords, and the borders between a crossed cell and a whole kept one.
void insert_constraints(Cdt& cdt, const std::vector<Cdt::Vertex_handle>& handles,
                        const CutPoints& c, const Cells& cells) {
    for (const auto& idx : c.loop_indices)
        for (std::size_t k = 0; k < idx.size(); ++k) {
            const auto a = handles[idx[k]], b = handles[idx[(k + 1) % idx.size()]];
            if (a != b) cdt.insert_constraint(a, b);
        }
    auto border = [&](int ai, int aj, int bi, int bj) {
        const std::size_t a = c.corner_index[cells.corner(ai, aj)];
        const std::size_t b = c.corner_index[cells.corner(bi, bj)];
        if (a != absent && b != absent) cdt.insert_constraint(handles[a], handles[b]);
    };
    for (int i = 0; i < cells.cu(); ++i) {
        for (int j = 0; j < cells.cv(); ++j) {
            if (!cells.cut(i, j)) continue;
            if (cells.whole_kept(i - 1, j)) border(i, j, i, j + 1);
            if (cells.whole_kept(i + 1, j)) border(i + 1, j, i + 1, j + 1);
            if (cells.whole_kept(i, j - 1)) border(i, j, i + 1, j);
            if (cells.whole_kept(i, j + 1)) border(i, j + 1, i + 1, j + 1);
        }
    }
}

// Kept faces: parity of the loop constraints crossed from the infinite face (outside every
// loop: kept only without an outer loop, where the domain's edge bounds the mesh instead).
void mark_kept_faces(Cdt& cdt, bool start_kept) {
    auto loop_edge = [&](Cdt::Face_handle f, int i) {
        if (!cdt.is_constrained({f, i})) return false;
        const auto a = f->vertex(Cdt::cw(i)), b = f->vertex(Cdt::ccw(i));
        return !(a->info().grid && b->info().grid);
    };
    std::deque<std::pair<Cdt::Face_handle, int>> queue;
    if (cdt.dimension() == 2) queue.push_back({cdt.infinite_face(), start_kept ? 1 : 0});
    std::deque<std::pair<Cdt::Face_handle, int>> next_region;
    while (!queue.empty() || !next_region.empty()) {
        if (queue.empty()) {
            queue.swap(next_region);
            continue;
        }
        auto [f, kept] = queue.front();
        queue.pop_front();
        if (f->info().kept != -1) continue;
        f->info().kept = kept;
        for (int i = 0; i < 3; ++i) {
            const Cdt::Face_handle n = f->neighbor(i);
            if (n->info().kept != -1) continue;
            if (loop_edge(f, i))
                next_region.push_back({n, 1 - kept});
            else
                queue.push_back({n, kept});
        }
    }
}

// A corner's place in the plane, compared x first.
std::pair<double, double> corner(const Cdt::Face_handle f, int k) {
    return {f->vertex(k)->point().x(), f->vertex(k)->point().y()};
}

int lowest_corner(const Cdt::Face_handle f) {
    int low = 0;
    for (int k = 1; k < 3; ++k)
        if (corner(f, k) < corner(f, low)) low = k;
    return low;
}

// The kept faces sorted by their corners. CGAL visits faces in the order it allocated them,
// which follows the order the points went in: spatial_sort's, which differs between standard
// libraries where keys are equal (libstdc++ here, libc++ in the browser build). The
// triangulation itself is the same (its degenerate cases are decided by the points' order in
// the plane), so sorted the triangles come out the same everywhere: the browser build answers
// as the command line does, triangle for triangle.
std::vector<Cdt::Face_handle> kept_faces_in_corner_order(Cdt& cdt) {
    using Corners = std::array<std::pair<double, double>, 3>;
    std::vector<std::pair<Corners, Cdt::Face_handle>> faces;
    for (auto f = cdt.finite_faces_begin(); cdt.dimension() == 2 && f != cdt.finite_faces_end();
         ++f) {
        if (f->info().kept != 1) continue;
        Corners c{corner(f, 0), corner(f, 1), corner(f, 2)};
        std::sort(c.begin(), c.end());
        faces.push_back({c, f});
    }
    std::sort(faces.begin(), faces.end(),
              [](const auto& a, const auto& b) { return a.first < b.first; });
    std::vector<Cdt::Face_handle> out;
    out.reserve(faces.size());
    for (const auto& f : faces) out.push_back(f.second);
    return out;
}

// The kept faces outside whole kept cells, appended to tris; a vertex CGAL made where two
// chords cross becomes a loop point.
void add_kept_faces(Cdt& cdt, const Cells& cells, std::uint32_t loop_base,
                    std::vector<glm::dvec2>& loop_points, Triangles& tris) {
    for (const Cdt::Face_handle f : kept_faces_in_corner_order(cdt)) {
        // Each triangle from its lowest corner on (counter-clockwise, as CGAL keeps it).
        const int first = lowest_corner(f);
        std::array<std::uint32_t, 3> t{};
        glm::dvec2 centre(0.0);
        for (int k = 0; k < 3; ++k) {
            const auto v = f->vertex((first + k) % 3);
            if (v->info().id == none) { // where two chords cross
                v->info().id = loop_base + static_cast<std::uint32_t>(loop_points.size());
                loop_points.push_back({v->point().x(), v->point().y()});
            }
            t[static_cast<std::size_t>(k)] = v->info().id;
            centre += glm::dvec2(v->point().x(), v->point().y()) / 3.0;
        }
        if (cells.whole_kept(cells.cell_u(centre.x), cells.cell_v(centre.y))) continue;
        tris.push_back(t);
    }
}

// Numbers the vertices the triangles use: grid corners by grid index, then loop points.
void number_vertices(TrimmedLayout& out, Triangles tris, const CutPoints& c,
                     const std::vector<Cdt::Vertex_handle>& handles, std::uint32_t loop_base) {
    std::vector<std::uint32_t> number(loop_base + c.loop_points.size(), none);
    for (const auto& t : tris)
        for (std::uint32_t v : t) number[v] = 0;
    for (std::uint32_t g = 0; g < loop_base; ++g)
        if (number[g] == 0) {
            number[g] = static_cast<std::uint32_t>(out.grid_vertices.size());
            out.grid_vertices.push_back(g);
        }
    const auto first_loop = static_cast<std::uint32_t>(out.grid_vertices.size());
    // Every loop point is a vertex (the boundary), used or not.
    for (std::size_t k = 0; k < c.loop_points.size(); ++k) {
        number[loop_base + k] = first_loop + static_cast<std::uint32_t>(k);
        out.loop_points.push_back(c.loop_points[k]);
    }
    for (auto& t : tris)
        for (auto& v : t) v = number[v];
    out.triangles = std::move(tris);
    for (const auto& idx : c.loop_indices) {
        std::vector<std::uint32_t> ids;
        for (std::size_t k : idx) ids.push_back(number[handles[k]->info().id]);
        out.loops.push_back(std::move(ids));
    }
}

} // namespace

TrimmedLayout triangulate_trimmed(const std::vector<double>& us, const std::vector<double>& vs,
                                  const Trim& trim, const ParamRect& domain,
                                  const FlattenRule& rule) {
    assert(us.size() >= 2 && vs.size() >= 2);
    (void)domain;
    Cells cells(us, vs);
    const double snap = 1e-6 * smallest_cell(us, vs);
    const Loops loops = flat_loops(trim, rule);
    for_each_chord(loops, [&](glm::dvec2 a, glm::dvec2 b) {
        cells.mark_cut(glm::min(a, b) - 2 * snap, glm::max(a, b) + 2 * snap);
    });
    const bool start_kept = !trim.outer;
    keep_whole_cells(cells, loops, us, vs, start_kept);

    TrimmedLayout out;
    out.us = us;
    out.vs = vs;
    // Mesh vertices are numbered once the triangles are known: grid corners first (by grid
    // index), then loop points. Until then triangles hold grid indices or loop_base + index.
    const auto loop_base = static_cast<std::uint32_t>(us.size() * vs.size());
    Triangles tris = whole_cell_triangles(cells, static_cast<std::uint32_t>(vs.size()));
    out.grid_triangles = tris.size();

    // The crossed cells go to CGAL's constrained Delaunay triangulation.
    CutPoints c = cut_points(cells, loops, us, vs, snap, loop_base);
    Cdt cdt;
    const std::vector<Cdt::Vertex_handle> handles = insert_points(cdt, c);
    insert_constraints(cdt, handles, c, cells);
    mark_kept_faces(cdt, start_kept);
    add_kept_faces(cdt, cells, loop_base, c.loop_points, tris);
    number_vertices(out, std::move(tris), c, handles, loop_base);
    return out;
}

} // namespace isoparm::geom
