#include "core/exchange/step_writer.hpp"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <optional>

#include "core/exchange/real_text.hpp"
#include "core/exchange/step_file.hpp"
#include "core/geom/evaluate.hpp"
#include "core/geom/knots.hpp"
#include "core/geom/refine.hpp"
#include "core/geom/trim/curve_on_surface.hpp"

namespace isoparm::exchange {

namespace {

using geom::Dir;
using step::list;
using step::ref;

std::string logical(bool b) {
    return b ? ".T." : ".F.";
}

std::string reals(const std::vector<double>& xs) {
    std::vector<std::string> items;
    for (double x : xs) items.push_back(real_text(x));
    return list(items);
}

// Part 42 stores a knot vector as its distinct values and their multiplicities (knots strictly
// increasing, B_SPLINE_CURVE_WITH_KNOTS' where rules); equal values are exactly equal here.
std::pair<std::string, std::string> knots_and_multiplicities(const geom::Knots& U) {
    std::vector<double> values;
    std::vector<std::string> multiplicities;
    for (std::size_t k = 0; k < U.size();) {
        std::size_t m = 1;
        while (k + m < U.size() && U[k + m] == U[k]) ++m;
        values.push_back(U[k]);
        multiplicities.push_back(std::to_string(m));
        k += m;
    }
    return {list(multiplicities), reals(values)};
}

// The side of a surface at the low or high end of `fixed`: the curve along the other direction
// whose control points are each line's end point in homogeneous form (its first or last
// control point once clamped: Piegl & Tiller A5.4 applied to an unclamped line), so the side is
// exact for any knot vector.
geom::Curve side_curve(const geom::Surface& s, Dir fixed, bool high) {
    const Dir along = fixed == Dir::u ? Dir::v : Dir::u;
    geom::Curve c;
    c.type = s.type;
    c.degree = s.degree(along);
    c.knots = s.knots(along);
    const bool clamped = geom::is_clamped(s.knots(fixed), s.degree(fixed), s.count(fixed));
    for (int k = 0; k < s.count(along); ++k) {
        geom::Curve line = geom::surface_line(s, fixed, k);
        if (!clamped)
            if (geom::Expected<geom::Curve> c2 = geom::clamp(line); c2) line = std::move(*c2);
        c.points.push_back(high ? line.points.back() : line.points.front());
        c.weights.push_back(high ? line.weights.back() : line.weights.front());
    }
    return c;
}

bool same_point(const glm::dvec3& a, const glm::dvec3& b, double tolerance) {
    return glm::distance(a, b) <= tolerance;
}

// Two sides are one curve when their control points coincide and their weights are equal up
// to rounding (the sides of one surface share degree and knots).
bool same_curve(const geom::Curve& a, const geom::Curve& b, double tolerance) {
    for (int k = 0; k < a.count(); ++k)
        if (!same_point(a.points[k], b.points[k], tolerance) ||
            std::abs(a.weights[k] - b.weights[k]) > 1e-12 * std::max(a.weights[k], b.weights[k]))
            return false;
    return true;
}

bool collapsed(const geom::Curve& c, double tolerance) {
    for (const glm::dvec3& p : c.points)
        if (!same_point(p, c.points.front(), tolerance)) return false;
    return true;
}

class Writer {
public:
    explicit Writer(double tolerance) : tolerance_(tolerance) {}

    step::DataSection& data() { return d_; }

    int point(const glm::dvec3& p) {
        return d_.add("CARTESIAN_POINT(''," + reals({p.x, p.y, p.z}) + ")");
    }

    // One VERTEX_POINT per distinct position, so that a closed side starts and ends at one
    // vertex and the sides of a face meet.
    int vertex(const glm::dvec3& p) {
        for (const auto& [q, id] : vertices_)
            if (same_point(p, q, tolerance_)) return id;
        const int id = d_.add("VERTEX_POINT(''," + ref(point(p)) + ")");
        vertices_.emplace_back(p, id);
        return id;
    }

    int point2(const glm::dvec3& p) {
        return d_.add("CARTESIAN_POINT(''," + reals({p.x, p.y}) + ")");
    }

    // planar: a (u, v) curve, its points 2D (a p-curve's definitional representation).
    int curve(const geom::Curve& c, bool planar = false) {
        std::vector<std::string> points;
        for (const glm::dvec3& p : c.points) points.push_back(ref(planar ? point2(p) : point(p)));
        const auto [multiplicities, knots] = knots_and_multiplicities(c.knots);
        const geom::Interval dom = geom::domain(c);
        const auto a = geom::curve_point(c, dom.lo), b = geom::curve_point(c, dom.hi);
        const std::string closed = logical(a && b && same_point(*a, *b, tolerance_));
        const std::string degree = std::to_string(c.degree);
        if (!geom::is_rational(c.type))
            return d_.add("B_SPLINE_CURVE_WITH_KNOTS(''," + degree + "," + list(points) +
                          ",.UNSPECIFIED.," + closed + ",.F.," + multiplicities + "," + knots +
                          ",.UNSPECIFIED.)");
        // A complex instance lists its partial entities in alphabetical order (ISO 10303-21
        // 11.2.5.2, external mapping); BOUNDED_CURVE sorts before B_SPLINE_CURVE ('O' < '_').
        return d_.add("( BOUNDED_CURVE() B_SPLINE_CURVE(" + degree + "," + list(points) +
                      ",.UNSPECIFIED.," + closed + ",.F.) B_SPLINE_CURVE_WITH_KNOTS(" +
                      multiplicities + "," + knots +
                      ",.UNSPECIFIED.) CURVE() GEOMETRIC_REPRESENTATION_ITEM() "
                      "RATIONAL_B_SPLINE_CURVE(" +
                      reals(c.weights) + ") REPRESENTATION_ITEM('') )");
    }

    int surface(const geom::Surface& s, bool closed_u, bool closed_v) {
        // control_points_list[i][j]: the outer list runs along u (ISO 10303-42
        // b_spline_surface), which is isoparm's u-major order.
        std::vector<std::string> rows, weight_rows;
        for (int i = 0; i < s.n_u; ++i) {
            std::vector<std::string> row;
            std::vector<double> weights;
            for (int j = 0; j < s.n_v; ++j) {
                row.push_back(ref(point(s.point(i, j))));
                weights.push_back(s.weight(i, j));
            }
            rows.push_back(list(row));
            weight_rows.push_back(reals(weights));
        }
        const auto [mu, ku] = knots_and_multiplicities(s.knots_u);
        const auto [mv, kv] = knots_and_multiplicities(s.knots_v);
        const std::string head = std::to_string(s.degree_u) + "," + std::to_string(s.degree_v) +
                                 "," + list(rows) + ",.UNSPECIFIED.," + logical(closed_u) + "," +
                                 logical(closed_v) + ",.F.";
        const std::string with_knots = mu + "," + mv + "," + ku + "," + kv + ",.UNSPECIFIED.";
        if (!geom::is_rational(s.type))
            return d_.add("B_SPLINE_SURFACE_WITH_KNOTS(''," + head + "," + with_knots + ")");
        return d_.add("( BOUNDED_SURFACE() B_SPLINE_SURFACE(" + head +
                      ") B_SPLINE_SURFACE_WITH_KNOTS(" + with_knots +
                      ") GEOMETRIC_REPRESENTATION_ITEM() RATIONAL_B_SPLINE_SURFACE(" +
                      list(weight_rows) + ") REPRESENTATION_ITEM('') SURFACE() )");
    }

    // A trimmed surface: a FACE_BOUND per loop (FACE_OUTER_BOUND for the outer one, the
    // domain's rectangle where there is none), an edge per trim curve, each a SURFACE_CURVE of
    // its model-space trace with its (u, v) curve as the PCURVE master representation (ISO
    // 10303-42 surface_curve, master_representation .PCURVE_S1.).
    int face(const geom::TrimmedSurface& t, double edge_tolerance) {
        const geom::Surface& s = t.surface;
        const int surface_id = surface(s, false, false);
        std::vector<std::string> bounds;
        auto loop_bound = [&](const geom::TrimLoop& loop, bool outer) {
            // One vertex per junction: curve k starts at junction k, ends at junction k + 1.
            std::vector<int> junctions;
            for (const geom::Curve& c : loop.curves) {
                const glm::dvec2 p = geom::curve_start(c).value_or(glm::dvec2(0.0));
                const geom::ParamRect d = geom::domain(s);
                const auto q = geom::surface_point(s, std::clamp(p.x, d.u.lo, d.u.hi),
                                                   std::clamp(p.y, d.v.lo, d.v.hi));
                junctions.push_back(vertex(q.value_or(glm::dvec3(0.0))));
            }
            std::vector<std::string> oriented;
            for (std::size_t k = 0; k < loop.curves.size(); ++k) {
                const geom::Curve& c = loop.curves[k];
                const int c3 = curve(geom::curve_on_surface(s, c, edge_tolerance));
                const int representation =
                    d_.add("DEFINITIONAL_REPRESENTATION(''," + list({ref(curve(c, true))}) + "," +
                           ref(parameter_context()) + ")");
                const int pcurve =
                    d_.add("PCURVE(''," + ref(surface_id) + "," + ref(representation) + ")");
                const int surface_curve = d_.add("SURFACE_CURVE(''," + ref(c3) + "," +
                                                 list({ref(pcurve)}) + ",.PCURVE_S1.)");
                const int edge = d_.add("EDGE_CURVE(''," + ref(junctions[k]) + "," +
                                        ref(junctions[(k + 1) % junctions.size()]) + "," +
                                        ref(surface_curve) + ",.T.)");
                oriented.push_back(ref(d_.add("ORIENTED_EDGE('',*,*," + ref(edge) + ",.T.)")));
            }
            const int edge_loop = d_.add("EDGE_LOOP(''," + list(oriented) + ")");
            bounds.push_back(ref(d_.add(std::string(outer ? "FACE_OUTER_BOUND" : "FACE_BOUND") +
                                        "(''," + ref(edge_loop) + ",.T.)")));
        };
        loop_bound(t.trim.outer ? *t.trim.outer : geom::rectangle_loop(geom::domain(s)), true);
        for (const geom::TrimLoop& h : t.trim.holes) loop_bound(h, false);
        return d_.add("ADVANCED_FACE(''," + list(bounds) + "," + ref(surface_id) + ",.T.)");
    }

    int face(const geom::Surface& s) {
        const geom::ParamRect dom = geom::domain(s);
        // Sides in loop order: v = v0 (along u), u = u1 (along v), v = v1, u = u0.
        const geom::Curve sides[4] = {side_curve(s, Dir::v, false), side_curve(s, Dir::u, true),
                                      side_curve(s, Dir::v, true), side_curve(s, Dir::u, false)};
        const bool closed_v = same_curve(sides[0], sides[2], tolerance_);
        const bool closed_u = same_curve(sides[1], sides[3], tolerance_);
        const int surface_id = surface(s, closed_u, closed_v);
        auto corner = [&](bool u_high, bool v_high) {
            const auto p =
                geom::surface_point(s, u_high ? dom.u.hi : dom.u.lo, v_high ? dom.v.hi : dom.v.lo);
            return vertex(p ? *p : glm::dvec3(0.0)); // positive weights: the point exists
        };
        const int v00 = corner(false, false), v10 = corner(true, false), v11 = corner(true, true),
                  v01 = corner(false, true);
        // Each side's edge runs in its curve's direction; the loop uses sides 2 and 3 reversed.
        const int starts[4] = {v00, v10, v01, v00}, ends[4] = {v10, v11, v11, v01};
        // Where no side is a seam or a point, each edge also carries its exact (u, v) line:
        // without p-curves OCCT's reader projects every edge onto its surface (Extrema), a
        // quarter of the time it took to read back a 64 MB file of 140 bicubic 64 x 64 patches.
        bool plain = !closed_u && !closed_v;
        for (const geom::Curve& side : sides) plain = plain && !collapsed(side, tolerance_);
        const glm::dvec2 corners[4][2] = {{{dom.u.lo, dom.v.lo}, {dom.u.hi, dom.v.lo}},
                                          {{dom.u.hi, dom.v.lo}, {dom.u.hi, dom.v.hi}},
                                          {{dom.u.lo, dom.v.hi}, {dom.u.hi, dom.v.hi}},
                                          {{dom.u.lo, dom.v.lo}, {dom.u.lo, dom.v.hi}}};
        int edges[4] = {0, 0, 0, 0};
        std::vector<std::string> oriented;
        for (int k = 0; k < 4; ++k) {
            if (collapsed(sides[k], tolerance_)) continue;
            if (k == 2 && closed_v) edges[k] = edges[0];
            if (k == 3 && closed_u) edges[k] = edges[1];
            if (!edges[k]) {
                const int c3 = curve(sides[k]);
                const int geometry =
                    plain ? side_with_pcurve(c3, surface_id, corners[k][0], corners[k][1],
                                             k % 2 == 0 ? dom.u : dom.v)
                          : c3;
                edges[k] = d_.add("EDGE_CURVE(''," + ref(starts[k]) + "," + ref(ends[k]) + "," +
                                  ref(geometry) + ",.T.)");
            }
            oriented.push_back(
                ref(d_.add("ORIENTED_EDGE('',*,*," + ref(edges[k]) + "," + logical(k < 2) + ")")));
        }
        // A surface that is one point everywhere has no edge: its bound is a VERTEX_LOOP.
        const int loop = oriented.empty() ? d_.add("VERTEX_LOOP(''," + ref(v00) + ")")
                                          : d_.add("EDGE_LOOP(''," + list(oriented) + ")");
        const int bound = d_.add("FACE_OUTER_BOUND(''," + ref(loop) + ",.T.)");
        return d_.add("ADVANCED_FACE(''," + list({ref(bound)}) + "," + ref(surface_id) + ",.T.)");
    }

private:
    // A side of a surface's domain as a SURFACE_CURVE: its 3D curve `c3` (the master
    // representation) and the straight (u, v) line from `a` to `b` with the side's own parameter
    // `t` (degree 1 on [t.lo, t.hi]: the point at t is the side's point at t, exactly).
    int side_with_pcurve(int c3, int surface_id, glm::dvec2 a, glm::dvec2 b, geom::Interval t) {
        geom::Curve line;
        line.type = geom::SplineType::bspline;
        line.degree = 1;
        line.knots = {t.lo, t.lo, t.hi, t.hi};
        line.points = {glm::dvec3(a, 0.0), glm::dvec3(b, 0.0)};
        line.weights = {1.0, 1.0};
        const int representation =
            d_.add("DEFINITIONAL_REPRESENTATION(''," + list({ref(curve(line, true))}) + "," +
                   ref(parameter_context()) + ")");
        const int pcurve = d_.add("PCURVE(''," + ref(surface_id) + "," + ref(representation) + ")");
        return d_.add("SURFACE_CURVE(''," + ref(c3) + "," + list({ref(pcurve)}) + ",.CURVE_3D.)");
    }

    // The 2D context p-curves are defined in (made once, when the first is written).
    int parameter_context() {
        if (!parameter_context_)
            parameter_context_ = d_.add("( GEOMETRIC_REPRESENTATION_CONTEXT(2) "
                                        "PARAMETRIC_REPRESENTATION_CONTEXT() "
                                        "REPRESENTATION_CONTEXT('2D SPACE','') )");
        return parameter_context_;
    }

    step::DataSection d_;
    int parameter_context_ = 0;
    double tolerance_;
    std::vector<std::pair<glm::dvec3, int>> vertices_;
};

// 1e-7 as "1.0E-07" (the text earlier files have), others in shortest round-trip form.
std::string step_real(double x) {
    return x == 1e-7 ? "1.0E-07" : real_text(x);
}

// Millimetres, radians, steradians, and the distance uncertainty readers take as their
// precision (ISO 10303-41 units; the context every AP214 representation points to).
int representation_context(step::DataSection& d, double uncertainty_mm) {
    const int mm = d.add("( LENGTH_UNIT() NAMED_UNIT(*) SI_UNIT(.MILLI.,.METRE.) )");
    const int radian = d.add("( NAMED_UNIT(*) PLANE_ANGLE_UNIT() SI_UNIT($,.RADIAN.) )");
    const int steradian = d.add("( NAMED_UNIT(*) SI_UNIT($,.STERADIAN.) SOLID_ANGLE_UNIT() )");
    const int uncertainty =
        d.add("UNCERTAINTY_MEASURE_WITH_UNIT(LENGTH_MEASURE(" + step_real(uncertainty_mm) + ")," +
              ref(mm) + ",'distance_accuracy_value','confusion accuracy')");
    return d.add("( GEOMETRIC_REPRESENTATION_CONTEXT(3) GLOBAL_UNCERTAINTY_ASSIGNED_CONTEXT(" +
                 list({ref(uncertainty)}) + ") GLOBAL_UNIT_ASSIGNED_CONTEXT(" +
                 list({ref(mm), ref(radian), ref(steradian)}) +
                 ") REPRESENTATION_CONTEXT('','3D') )");
}

// The AP214 product structure a reader starts from: PRODUCT -> PRODUCT_DEFINITION ->
// PRODUCT_DEFINITION_SHAPE, which SHAPE_DEFINITION_REPRESENTATION ties to `representation`.
void product(step::DataSection& d, const std::string& name, int representation) {
    const int application =
        d.add("APPLICATION_CONTEXT('core data for automotive mechanical design processes')");
    d.add("APPLICATION_PROTOCOL_DEFINITION('international standard','automotive_design',2000," +
          ref(application) + ")");
    const int product_context = d.add("PRODUCT_CONTEXT(''," + ref(application) + ",'mechanical')");
    const int product = d.add("PRODUCT(" + step::quoted(name) + "," + step::quoted(name) + ",''," +
                              list({ref(product_context)}) + ")");
    d.add("PRODUCT_RELATED_PRODUCT_CATEGORY('part',$," + list({ref(product)}) + ")");
    const int formation = d.add("PRODUCT_DEFINITION_FORMATION('',''," + ref(product) + ")");
    const int definition_context =
        d.add("PRODUCT_DEFINITION_CONTEXT('part definition'," + ref(application) + ",'design')");
    const int definition = d.add("PRODUCT_DEFINITION('design',''," + ref(formation) + "," +
                                 ref(definition_context) + ")");
    const int shape =
        d.add("PRODUCT_DEFINITION_SHAPE(''," + step::quoted(name) + "," + ref(definition) + ")");
    d.add("SHAPE_DEFINITION_REPRESENTATION(" + ref(shape) + "," + ref(representation) + ")");
}

// The largest absolute coordinate, the scale of the tolerance that merges vertices and finds
// collapsed and coinciding sides (1e-12 of it: far below any modelling tolerance, far above
// the rounding of an exact construction such as a 360-degree revolution).
double model_tolerance(const std::vector<ExactShape>& shapes) {
    double size = 0;
    for (const ExactShape& shape : shapes)
        for (const glm::dvec3& p : control_points_of(shape))
            for (int a = 0; a < 3; ++a) size = std::max(size, std::abs(p[a]));
    return 1e-12 * std::max(size, 1e-300);
}

} // namespace

geom::Expected<std::string> step_text(const std::vector<ExactShape>& shapes,
                                      const std::string& name) {
    for (std::size_t k = 0; k < shapes.size(); ++k)
        if (geom::Status st = check_positive_weights(shapes[k]); !st)
            return shapes.size() == 1 ? st.error()
                                      : st.error().under("/objects/" + std::to_string(k));

    Writer w(model_tolerance(shapes));
    const double edge_tolerance = edge_curve_tolerance(shapes);
    step::DataSection& d = w.data();
    // Trimmed faces' edges follow their surfaces within edge_tolerance: the file's uncertainty
    // (what readers take as their precision) is at least ten times that.
    bool trimmed = false;
    for (const ExactShape& shape : shapes)
        trimmed |= std::holds_alternative<geom::TrimmedSurface>(shape);
    const int context =
        representation_context(d, trimmed ? std::max(1e-7, 10 * edge_tolerance) : 1e-7);
    const int origin = d.add("AXIS2_PLACEMENT_3D(''," + ref(w.point(glm::dvec3(0.0))) + "," +
                             ref(d.add("DIRECTION('',(0.0,0.0,1.0))")) + "," +
                             ref(d.add("DIRECTION('',(1.0,0.0,0.0))")) + ")");

    std::vector<std::string> shells, curves;
    for (const ExactShape& shape : shapes) {
        if (const auto* c = std::get_if<geom::Curve>(&shape)) {
            curves.push_back(ref(w.curve(*c)));
            continue;
        }
        // One open shell per surface: the surfaces need not meet.
        const auto* t = std::get_if<geom::TrimmedSurface>(&shape);
        const int face = t ? w.face(*t, edge_tolerance) : w.face(std::get<geom::Surface>(shape));
        shells.push_back(ref(d.add("OPEN_SHELL(''," + list({ref(face)}) + ")")));
    }
    std::vector<int> representations;
    if (!shells.empty()) {
        const int model = d.add("SHELL_BASED_SURFACE_MODEL(''," + list(shells) + ")");
        representations.push_back(d.add("MANIFOLD_SURFACE_SHAPE_REPRESENTATION(''," +
                                        list({ref(origin), ref(model)}) + "," + ref(context) +
                                        ")"));
    }
    if (!curves.empty()) {
        const int set = d.add("GEOMETRIC_CURVE_SET(''," + list(curves) + ")");
        representations.push_back(d.add("GEOMETRICALLY_BOUNDED_WIREFRAME_SHAPE_REPRESENTATION(''," +
                                        list({ref(origin), ref(set)}) + "," + ref(context) + ")"));
    }
    // One kind of geometry: the product's shape is that representation. Both kinds (or none):
    // a plain SHAPE_REPRESENTATION that each specialised one is related to.
    int top = representations.size() == 1 ? representations[0] : 0;
    if (!top) {
        top = d.add("SHAPE_REPRESENTATION(''," + list({ref(origin)}) + "," + ref(context) + ")");
        for (int r : representations)
            d.add("SHAPE_REPRESENTATION_RELATIONSHIP('',''," + ref(top) + "," + ref(r) + ")");
    }
    product(d, name, top);
    return d.file_text("isoparm: exact NURBS geometry (STEP AP214)", name,
                       "AUTOMOTIVE_DESIGN { 1 0 10303 214 1 1 1 1 }");
}

} // namespace isoparm::exchange
