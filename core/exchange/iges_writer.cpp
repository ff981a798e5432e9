#include "core/exchange/iges_writer.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/exchange/real_text.hpp"
#include "core/geom/knots.hpp"
#include "core/geom/trim/curve_on_surface.hpp"

namespace isoparm::exchange {

namespace {

constexpr int data_columns = 64; // Parameter Data: columns 1-64 data, 65-72 the DE pointer

// One 80-column record: `text` padded to 72 columns, the section letter, the sequence number.
std::string record(const std::string& text, char section, int sequence) {
    char tail[16];
    std::snprintf(tail, sizeof tail, "%c%7d", section, sequence);
    std::string line = text;
    line.resize(72, ' ');
    return line + tail + "\n";
}

// IGES strings are Hollerith constants: "5Hhello".
std::string hollerith(const std::string& s) {
    return std::to_string(s.size()) + "H" + s;
}

// Free-format parameter records: tokens joined by commas, ended by ';', broken between tokens
// so that no line passes column 64; each line carries the entity's DE pointer in 65-72.
void parameter_records(const std::vector<std::string>& tokens, int de_pointer, int& sequence,
                       std::string& out) {
    std::string line;
    for (std::size_t k = 0; k < tokens.size(); ++k) {
        const std::string token = tokens[k] + (k + 1 == tokens.size() ? ";" : ",");
        if (!line.empty() && line.size() + token.size() > data_columns) {
            line.resize(data_columns, ' ');
            char pointer[16];
            std::snprintf(pointer, sizeof pointer, "%8d", de_pointer);
            out += record(line + pointer, 'P', sequence++);
            line.clear();
        }
        line += token;
    }
    line.resize(data_columns, ' ');
    char pointer[16];
    std::snprintf(pointer, sizeof pointer, "%8d", de_pointer);
    out += record(line + pointer, 'P', sequence++);
}

// The two Directory Entry records of an entity (fields of 8 columns).
std::string directory_entry(int type, int parameter_start, int parameter_lines, int form,
                            const char* status, int& sequence) {
    char first[80], second[80];
    // type, parameter data, structure, line font, level, view, transformation, label display,
    // status (visible, independent, geometry, top down).
    std::snprintf(first, sizeof first, "%8d%8d%8d%8d%8d%8d%8d%8d%8s", type, parameter_start, 0, 0,
                  0, 0, 0, 0, status);
    // type, line weight, colour, parameter line count, form, reserved x2, label, subscript.
    std::snprintf(second, sizeof second, "%8d%8d%8d%8d%8d%8s%8s%8s%8d", type, 0, 0, parameter_lines,
                  form, "", "", "", 0);
    std::string out = record(first, 'D', sequence++);
    out += record(second, 'D', sequence++);
    return out;
}

// planar: a curve in the (u, v) plane (z = 0), as a 142's parameter-space curve is.
std::vector<std::string> curve_tokens(const geom::Curve& c, bool planar = false) {
    const int K = c.count() - 1, M = c.degree;
    const bool polynomial = !geom::is_rational(c.type);
    std::vector<std::string> t = {"126",
                                  std::to_string(K),
                                  std::to_string(M),
                                  planar ? "1" : "0",
                                  "0",
                                  polynomial ? "1" : "0",
                                  "0"};
    for (double u : c.knots) t.push_back(real_text(u));
    for (double w : c.weights) t.push_back(real_text(w));
    for (const glm::dvec3& p : c.points)
        for (int a = 0; a < 3; ++a) t.push_back(real_text(p[a]));
    const geom::Interval d = geom::domain(c);
    t.push_back(real_text(d.lo));
    t.push_back(real_text(d.hi));
    for (const char* n : {"0.0", "0.0", "1.0"}) t.push_back(n); // normal, used when planar
    return t;
}

std::vector<std::string> surface_tokens(const geom::Surface& s) {
    const bool polynomial = !geom::is_rational(s.type);
    std::vector<std::string> t = {"128",
                                  std::to_string(s.n_u - 1),
                                  std::to_string(s.n_v - 1),
                                  std::to_string(s.degree_u),
                                  std::to_string(s.degree_v),
                                  "0",
                                  "0",
                                  polynomial ? "1" : "0",
                                  "0",
                                  "0"};
    for (double u : s.knots_u) t.push_back(real_text(u));
    for (double v : s.knots_v) t.push_back(real_text(v));
    // Weights and points with the first index (u) varying fastest: W(0,0), W(1,0), ...
    for (int j = 0; j < s.n_v; ++j)
        for (int i = 0; i < s.n_u; ++i) t.push_back(real_text(s.weight(i, j)));
    for (int j = 0; j < s.n_v; ++j)
        for (int i = 0; i < s.n_u; ++i)
            for (int a = 0; a < 3; ++a) t.push_back(real_text(s.point(i, j)[a]));
    const geom::Interval du = geom::domain(s, geom::Dir::u);
    const geom::Interval dv = geom::domain(s, geom::Dir::v);
    for (double x : {du.lo, du.hi, dv.lo, dv.hi}) t.push_back(real_text(x));
    return t;
}

// Directory Entry status fields (blank, subordinate, use, hierarchy): an independent entity;
// one that exists for its parent (the surface and curves of a 144, read as part of it, never on
// their own); the same in parameter space (use flag 05).
constexpr const char* independent = "00000000";
constexpr const char* dependent = "00010000";
constexpr const char* dependent_parametric = "00010500";

// Entities in file order; each refers only to entities added before it, by DE pointer.
class Entities {
public:
    struct Entity {
        int type, form;
        std::vector<std::string> tokens;
        const char* status;
    };
    int add(int type, std::vector<std::string> tokens, const char* status, int form = 0) {
        list_.push_back({type, form, std::move(tokens), status});
        return 2 * static_cast<int>(list_.size()) - 1;
    }
    const std::vector<Entity>& list() const { return list_; }

private:
    std::vector<Entity> list_;
};

// One loop as a 142: its (u, v) curves and their model-space traces, each chained by a 102
// where there are several.
int loop_entity(Entities& e, int surface, const geom::Surface& s, const geom::TrimLoop& loop,
                double tolerance) {
    std::vector<int> uv, xyz;
    for (const geom::Curve& c : loop.curves) {
        uv.push_back(e.add(126, curve_tokens(c, true), dependent_parametric));
        xyz.push_back(e.add(126, curve_tokens(geom::curve_on_surface(s, c, tolerance)), dependent));
    }
    auto chain = [&](const std::vector<int>& pieces, const char* status) {
        if (pieces.size() == 1) return pieces[0];
        std::vector<std::string> t = {"102", std::to_string(pieces.size())};
        for (int p : pieces) t.push_back(std::to_string(p));
        return e.add(102, std::move(t), status);
    };
    const int b = chain(uv, dependent_parametric), c = chain(xyz, dependent);
    // CRTN 0 (unspecified), the surface, B, C, PREF 1 (S o B, the (u, v) curve, is preferred).
    return e.add(142,
                 {"142", "0", std::to_string(surface), std::to_string(b), std::to_string(c), "1"},
                 dependent);
}

} // namespace

geom::Status check_positive_weights(const ExactShape& shape) {
    if (const auto* c = std::get_if<geom::Curve>(&shape)) {
        for (std::size_t k = 0; k < c->weights.size(); ++k)
            if (!(c->weights[k] > 0))
                return geom::make_error(geom::ErrorCode::weights,
                                        "weight " + geom::format_number(c->weights[k]) +
                                            " of control point " + std::to_string(k) +
                                            " is not positive: IGES and STEP readers accept "
                                            "only positive weights; export a mesh (obj_mesh, "
                                            "stl_ascii, ply) instead",
                                        "/weights/" + std::to_string(k));
        return geom::Ok{};
    }
    const geom::Surface& s = *surface_of(shape);
    for (int i = 0; i < s.n_u; ++i)
        for (int j = 0; j < s.n_v; ++j)
            if (!(s.weight(i, j) > 0))
                return geom::make_error(geom::ErrorCode::weights,
                                        "weight " + geom::format_number(s.weight(i, j)) +
                                            " of control point (" + std::to_string(i) + ", " +
                                            std::to_string(j) +
                                            ") is not positive: IGES and STEP readers accept "
                                            "only positive weights; export a mesh (obj_mesh, "
                                            "stl_ascii, ply) instead",
                                        "/weights/" + std::to_string(i) + "/" + std::to_string(j));
    return geom::Ok{};
}

const geom::Surface* surface_of(const ExactShape& shape) {
    if (const auto* s = std::get_if<geom::Surface>(&shape)) return s;
    if (const auto* t = std::get_if<geom::TrimmedSurface>(&shape)) return &t->surface;
    return nullptr;
}

const std::vector<glm::dvec3>& control_points_of(const ExactShape& shape) {
    if (const auto* c = std::get_if<geom::Curve>(&shape)) return c->points;
    return surface_of(shape)->points;
}

double edge_curve_tolerance(const std::vector<ExactShape>& shapes) {
    double size = 0;
    for (const ExactShape& shape : shapes)
        for (const glm::dvec3& p : control_points_of(shape))
            for (int a = 0; a < 3; ++a) size = std::max(size, std::abs(p[a]));
    return std::max(1e-9 * size, 1e-12);
}

geom::Expected<std::string> iges_text(const std::vector<ExactShape>& shapes,
                                      const std::string& name) {
    for (std::size_t k = 0; k < shapes.size(); ++k)
        if (geom::Status st = check_positive_weights(shapes[k]); !st)
            return shapes.size() == 1 ? st.error()
                                      : st.error().under("/objects/" + std::to_string(k));

    std::string start, global, directory, parameters;
    int s_seq = 1, g_seq = 1, d_seq = 1, p_seq = 1;
    start += record("isoparm: exact NURBS geometry (IGES 5.3, entities 126 and 128)", 'S', s_seq++);

    double max_coordinate = 0;
    for (const ExactShape& shape : shapes)
        for (const glm::dvec3& p : control_points_of(shape))
            for (int a = 0; a < 3; ++a) max_coordinate = std::max(max_coordinate, std::abs(p[a]));
    // The Global parameters 1-25 (the 26th, an application protocol, defaults): delimiters,
    // product and file names, system, number formats, scale, units (2 = millimetres), line
    // weights, date, resolution, size, author, version 11 (= 5.3), drafting standard, last change.
    const std::string date = hollerith("20261124.000000");
    const std::vector<std::string> globals = {"1H,",
                                              "1H;",
                                              hollerith(name),
                                              hollerith(name),
                                              hollerith("isoparm"),
                                              hollerith("isoparm"),
                                              "32",
                                              "38",
                                              "6",
                                              "308",
                                              "15",
                                              hollerith(name),
                                              "1.0",
                                              "2",
                                              hollerith("MM"),
                                              "1",
                                              "1.0",
                                              date,
                                              "1.0E-9",
                                              real_text(max_coordinate),
                                              hollerith("isoparm user"),
                                              hollerith("isoparm"),
                                              "11",
                                              "0",
                                              date};
    {
        std::string line;
        for (std::size_t k = 0; k < globals.size(); ++k) {
            const std::string token = globals[k] + (k + 1 == globals.size() ? ";" : ",");
            if (!line.empty() && line.size() + token.size() > 72) {
                global += record(line, 'G', g_seq++);
                line.clear();
            }
            line += token;
        }
        global += record(line, 'G', g_seq++);
    }

    Entities entities;
    const double tolerance = edge_curve_tolerance(shapes);
    for (const ExactShape& shape : shapes) {
        if (const auto* c = std::get_if<geom::Curve>(&shape)) {
            entities.add(126, curve_tokens(*c), independent);
        } else if (const auto* s = std::get_if<geom::Surface>(&shape)) {
            entities.add(128, surface_tokens(*s), independent);
        } else {
            const auto& t = std::get<geom::TrimmedSurface>(shape);
            const int surface = entities.add(128, surface_tokens(t.surface), dependent);
            const int outer =
                t.trim.outer ? loop_entity(entities, surface, t.surface, *t.trim.outer, tolerance)
                             : 0;
            std::vector<int> holes;
            for (const geom::TrimLoop& h : t.trim.holes)
                holes.push_back(loop_entity(entities, surface, t.surface, h, tolerance));
            // N1: 0 when the outer boundary is the surface's own (its domain), 1 otherwise.
            std::vector<std::string> tokens = {"144", std::to_string(surface),
                                               t.trim.outer ? "1" : "0",
                                               std::to_string(holes.size()), std::to_string(outer)};
            for (int h : holes) tokens.push_back(std::to_string(h));
            entities.add(144, std::move(tokens), independent);
        }
    }
    for (const Entities::Entity& e : entities.list()) {
        const int de_pointer = d_seq, parameter_start = p_seq;
        std::string records;
        parameter_records(e.tokens, de_pointer, p_seq, records);
        parameters += records;
        directory += directory_entry(e.type, parameter_start, p_seq - parameter_start, e.form,
                                     e.status, d_seq);
    }
    char terminate[80];
    std::snprintf(terminate, sizeof terminate, "S%07dG%07dD%07dP%07d", s_seq - 1, g_seq - 1,
                  d_seq - 1, p_seq - 1);
    return start + global + directory + parameters + record(terminate, 'T', 1);
}

} // namespace isoparm::exchange
