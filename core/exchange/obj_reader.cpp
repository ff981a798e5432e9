#include "core/exchange/obj_reader.hpp"

#include <charconv>
#include <cmath>
#include <cstdint>
#include <glm/vec4.hpp>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "core/geom/knots.hpp"
#include "core/geom/validate.hpp"

namespace isoparm::exchange {

namespace {

using geom::ErrorCode;

// One statement: its keyword and arguments, and the line it starts on (a line ending in a
// backslash continues on the next, as the OBJ specification allows).
struct Statement {
    long line = 0;
    std::size_t offset = 0; // where its first line starts in the text
    std::vector<std::string_view> words;
};

bool is_space(char c) {
    return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v';
}

void split_words(std::string_view l, std::vector<std::string_view>& words) {
    words.clear();
    std::size_t k = 0;
    while (k < l.size()) {
        while (k < l.size() && is_space(l[k])) ++k;
        const std::size_t b = k;
        while (k < l.size() && !is_space(l[k])) ++k;
        if (k > b) words.push_back(l.substr(b, k - b));
    }
}

// The text's statements one at a time: nothing is kept but the one being read, so a file of
// any length is read in the memory of its text and its vertices (a whole-file token list took
// 3.3 GB for a 160 MB file). Words are views of the text, or of `joined_` for a statement
// continued over several lines (valid until the next statement).
class StatementReader {
public:
    StatementReader(std::string_view text, std::size_t from = 0, long line = 0)
        : text_(text), pos_(from), line_(line) {}

    // The next statement with words, or false at the end of the text.
    bool next(Statement& s) {
        while (pos_ < text_.size()) {
            const std::size_t start = pos_;
            const long first_line = ++line_;
            std::string_view l = line_at();
            if (!continues(l)) {
                split_words(l, s.words);
                if (s.words.empty()) continue;
                s.line = first_line;
                s.offset = start;
                return true;
            }
            joined_.clear();
            while (true) {
                const bool more = continues(l);
                if (more) l.remove_suffix(1);
                joined_.append(l).push_back(' ');
                if (!more || pos_ >= text_.size()) break;
                ++line_;
                l = line_at();
            }
            split_words(joined_, s.words);
            if (s.words.empty()) continue;
            s.line = first_line;
            s.offset = start;
            return true;
        }
        return false;
    }

private:
    // The line at pos_ without its comment and trailing blanks; pos_ moves past it.
    std::string_view line_at() {
        std::size_t end = text_.find('\n', pos_);
        if (end == std::string_view::npos) end = text_.size();
        std::string_view l = text_.substr(pos_, end - pos_);
        pos_ = end + 1;
        if (const auto hash = l.find('#'); hash != std::string_view::npos) l = l.substr(0, hash);
        while (!l.empty() && is_space(l.back())) l.remove_suffix(1);
        return l;
    }
    static bool continues(std::string_view l) { return !l.empty() && l.back() == '\\'; }

    std::string_view text_;
    std::size_t pos_ = 0;
    long line_ = 0;
    std::string joined_;
};

geom::Error at_line(long line, const std::string& message, ErrorCode code = ErrorCode::parse) {
    return geom::make_error(code, "line " + std::to_string(line) + ": " + message);
}

std::string quoted(std::string_view word) {
    std::string s = "'";
    for (char c : word.substr(0, 40))
        s.push_back(static_cast<unsigned char>(c) < 0x20 || c == 0x7f ? '?' : c);
    return s + (word.size() > 40 ? "...'" : "'");
}

geom::Expected<double> real_of(const Statement& s, std::size_t k, const char* what) {
    if (k >= s.words.size())
        return at_line(s.line, std::string(s.words[0]) + " is missing " + what);
    const std::string_view w = s.words[k];
    double x = 0;
    const char* first = w.data();
    if (!w.empty() && w[0] == '+') ++first; // from_chars does not take a leading '+'
    const auto [ptr, ec] = std::from_chars(first, w.data() + w.size(), x);
    if (ec != std::errc() || ptr != w.data() + w.size() || !std::isfinite(x))
        return at_line(s.line, std::string(what) + " " + quoted(w) + " is not a finite number");
    return x;
}

geom::Expected<long> integer_of(const Statement& s, std::size_t k, const char* what) {
    if (k >= s.words.size())
        return at_line(s.line, std::string(s.words[0]) + " is missing " + what);
    const std::string_view w = s.words[k];
    long x = 0;
    const auto [ptr, ec] = std::from_chars(w.data(), w.data() + w.size(), x);
    if (ec != std::errc() || ptr != w.data() + w.size())
        return at_line(s.line, std::string(what) + " " + quoted(w) + " is not an integer");
    return x;
}

// A curv/surf element being read, from its first statement to its `end`.
struct Element {
    bool surface = false;
    long line = 0;
    std::string type; // cstype when it began
    bool rational = false;
    int degree_u = 0, degree_v = 0;
    double range[4] = {0, 0, 0, 0}; // u0 u1 (and v0 v1 for a surface)
    std::vector<long> vertices;     // 0-based
    std::optional<geom::Knots> parm_u, parm_v;
    std::vector<std::string> trims; // trim/hole/scrv lines inside, for the skipped list
};

class Reader {
public:
    geom::Expected<ImportResult> run(std::string_view text) {
        if (text.size() > std::numeric_limits<std::uint32_t>::max())
            return geom::make_error(ErrorCode::limit, "the text is longer than 4 GiB");
        text_ = text;
        // One offset per vertex, reserved at once (counting is a fast scan; growing would
        // hold the old and the new array together).
        std::size_t v_lines = 0;
        for (std::size_t at = 0; at < text.size();) {
            const std::size_t first = text.find_first_not_of(" \t", at);
            if (first != std::string_view::npos && first + 1 < text.size() && text[first] == 'v' &&
                is_space(text[first + 1]))
                ++v_lines;
            const std::size_t end = text.find('\n', at);
            if (end == std::string_view::npos) break;
            at = end + 1;
        }
        vertex_offsets_.reserve(v_lines);
        StatementReader statements(text);
        Statement s;
        while (statements.next(s))
            if (geom::Status st = statement(s); !st) return st.error();
        if (element_)
            return at_line(element_->line, std::string(element_->surface ? "surf" : "curv") +
                                               " has no 'end' before the file ends");
        for (const auto& [word, first, count] : ignored_)
            result_.skipped.push_back({std::to_string(count) + " '" + word + "' statement" +
                                           (count > 1 ? "s" : "") + " (first at line " +
                                           std::to_string(first) + ")",
                                       reason_for(word)});
        return std::move(result_);
    }

private:
    static std::string reason_for(const std::string& word) {
        if (word == "f" || word == "fo" || word == "l" || word == "p")
            return "polygonal data: only free-form curves and surfaces are imported";
        if (word == "curv2") return "a curve in a surface's parameter space (trimming)";
        return "not imported";
    }

    void note(std::string_view word, long line) {
        for (auto& [w, first, count] : ignored_)
            if (w == word) {
                ++count;
                return;
            }
        ignored_.push_back({std::string(word), line, 1});
    }

    geom::Status statement(const Statement& s) {
        const std::string_view kw = s.words[0];
        if (kw == "v") return vertex(s);
        if (kw == "cstype") return cstype(s);
        if (kw == "deg") return degree(s);
        if (kw == "curv" || kw == "surf") return begin(s, kw == "surf");
        if (kw == "parm") return parm(s);
        if (kw == "end") return end(s);
        if (kw == "o" || kw == "g") {
            std::string name;
            for (std::size_t k = 1; k < s.words.size(); ++k)
                name += (k > 1 ? " " : "") + std::string(s.words[k]);
            (kw == "o" ? object_name_ : group_name_) = name;
            return geom::Ok{};
        }
        if (kw == "trim" || kw == "hole" || kw == "scrv" || kw == "sp") {
            if (!element_ || !element_->surface)
                return at_line(s.line, std::string(kw) + " outside a surf ... end element");
            element_->trims.push_back(std::string(kw) + " (line " + std::to_string(s.line) + ")");
            return geom::Ok{};
        }
        if (kw == "f" || kw == "fo" || kw == "l" || kw == "p" || kw == "curv2" || kw == "con") {
            note(kw, s.line);
            return geom::Ok{};
        }
        // Attributes that change how a renderer draws or names things, not the geometry.
        static constexpr std::string_view display[] = {
            "vt",       "vn",     "vp",     "bmat",       "step",      "s",     "mg",
            "usemtl",   "mtllib", "ctech",  "stech",      "lod",       "bevel", "c_interp",
            "d_interp", "maplib", "usemap", "shadow_obj", "trace_obj", "res",
        };
        for (std::string_view d : display)
            if (kw == d) return geom::Ok{};
        return at_line(s.line, quoted(kw) + " is not an OBJ statement");
    }

    // x y z [w] of a `v` statement (checked), or the reason.
    static geom::Expected<glm::dvec4> vertex_values(const Statement& s) {
        glm::dvec4 v{0, 0, 0, 1};
        static const char* const names[] = {"x", "y", "z", "weight"};
        if (s.words.size() < 4 || s.words.size() > 5)
            return at_line(s.line, "v takes x y z and an optional weight, got " +
                                       std::to_string(s.words.size() - 1) + " values");
        for (std::size_t k = 1; k < s.words.size(); ++k) {
            auto x = real_of(s, k, names[k - 1]);
            if (!x) return x.error();
            v[static_cast<int>(k - 1)] = *x;
        }
        return v;
    }

    // A vertex is checked when read and kept as where its statement starts (4 bytes where its
    // values would take 32: a file of 20 million `v` lines keeps 80 MB beside its text); the
    // vertices an element names are read again when it ends.
    geom::Status vertex(const Statement& s) {
        auto v = vertex_values(s);
        if (!v) return v.error();
        vertex_offsets_.push_back(static_cast<std::uint32_t>(s.offset));
        return geom::Ok{};
    }

    glm::dvec4 vertex_at(long k) const {
        StatementReader again(text_, vertex_offsets_[static_cast<std::size_t>(k)]);
        Statement s;
        again.next(s);
        return *vertex_values(s); // checked when first read
    }

    geom::Status cstype(const Statement& s) {
        std::size_t k = 1;
        rational_ = k < s.words.size() && s.words[k] == "rat";
        if (rational_) ++k;
        if (k + 1 != s.words.size())
            return at_line(s.line, "cstype takes [rat] and one of bmatrix, bezier, bspline, "
                                   "cardinal, taylor");
        const std::string_view t = s.words[k];
        if (t != "bspline" && t != "bezier" && t != "bmatrix" && t != "cardinal" && t != "taylor")
            return at_line(s.line, "cstype " + quoted(t) +
                                       " is not bmatrix, bezier, bspline, cardinal or taylor");
        type_ = std::string(t);
        return geom::Ok{};
    }

    geom::Status degree(const Statement& s) {
        if (s.words.size() < 2 || s.words.size() > 3)
            return at_line(s.line, "deg takes one degree (curves) or two (surfaces)");
        for (std::size_t k = 1; k < s.words.size(); ++k) {
            auto d = integer_of(s, k, k == 1 ? "degree u" : "degree v");
            if (!d) return d.error();
            if (*d < 1 || *d > 64)
                return at_line(s.line, "degree " + std::string(s.words[k]) + " is not in 1..64",
                               ErrorCode::degree);
            (k == 1 ? degree_u_ : degree_v_) = static_cast<int>(*d);
        }
        if (s.words.size() == 2) degree_v_ = 0;
        return geom::Ok{};
    }

    geom::Status begin(const Statement& s, bool surface) {
        const char* kw = surface ? "surf" : "curv";
        if (element_)
            return at_line(s.line, std::string(kw) + " begins before the " +
                                       (element_->surface ? "surf" : "curv") + " of line " +
                                       std::to_string(element_->line) + " has its 'end'");
        if (type_.empty()) return at_line(s.line, std::string(kw) + " comes before any cstype");
        if (degree_u_ == 0) return at_line(s.line, std::string(kw) + " comes before any deg");
        if (surface && degree_v_ == 0)
            return at_line(s.line, "surf needs 'deg' with two degrees (u and v), the last deg "
                                   "has one");
        Element e;
        e.surface = surface;
        e.line = s.line;
        e.type = type_;
        e.rational = rational_;
        e.degree_u = degree_u_;
        e.degree_v = degree_v_;
        const std::size_t ranges = surface ? 4 : 2;
        static const char* const names[] = {"u0", "u1", "v0", "v1"};
        for (std::size_t k = 0; k < ranges; ++k) {
            auto x = real_of(s, k + 1, names[k]);
            if (!x) return x.error();
            e.range[k] = *x;
        }
        for (std::size_t k = ranges + 1; k < s.words.size(); ++k) {
            // Surface vertices may carry texture and normal indices (v/vt/vn): the first counts.
            std::string_view w = s.words[k];
            w = w.substr(0, w.find('/'));
            long index = 0;
            const auto [ptr, ec] = std::from_chars(w.data(), w.data() + w.size(), index);
            if (ec != std::errc() || ptr != w.data() + w.size() || w.empty())
                return at_line(s.line,
                               "control vertex " + quoted(s.words[k]) + " is not a vertex index");
            const long count = static_cast<long>(vertex_offsets_.size());
            // Negative indices count back from the last vertex read (-1 is the last).
            const long zero_based = index < 0 ? count + index : index - 1;
            if (index == 0 || zero_based < 0 || zero_based >= count)
                return at_line(s.line, "control vertex " + quoted(s.words[k]) +
                                           " names no vertex (" + std::to_string(count) +
                                           " read so far)");
            e.vertices.push_back(zero_based);
        }
        if (e.vertices.empty())
            return at_line(s.line, std::string(kw) + " lists no control vertices");
        element_vertices_ += e.vertices.size();
        if (element_vertices_ > max_import_control_points)
            return at_line(s.line,
                           "the file's curves and surfaces have more than " +
                               std::to_string(max_import_control_points) +
                               " control points in all, the most one import takes",
                           ErrorCode::limit);
        element_ = std::move(e);
        return geom::Ok{};
    }

    geom::Status parm(const Statement& s) {
        if (!element_) return at_line(s.line, "parm outside a curv or surf element");
        if (s.words.size() < 2 || (s.words[1] != "u" && s.words[1] != "v"))
            return at_line(s.line, "parm must be followed by u or v");
        const bool u = s.words[1] == "u";
        if (!u && !element_->surface) return at_line(s.line, "a curve has no parm v");
        auto& target = u ? element_->parm_u : element_->parm_v;
        if (target)
            return at_line(s.line, std::string("a second parm ") + (u ? "u" : "v") +
                                       " in the element of line " + std::to_string(element_->line));
        geom::Knots knots;
        for (std::size_t k = 2; k < s.words.size(); ++k) {
            auto x = real_of(s, k, "knot");
            if (!x) return x.error();
            knots.push_back(*x);
        }
        target = std::move(knots);
        return geom::Ok{};
    }

    // The element's range must be its knots' whole domain: isoparm's splines have no
    // separate trim range (a narrower one would need a split first).
    static bool whole_domain(double lo, double hi, const geom::Knots& knots, int p) {
        const auto n = knots.size() - static_cast<std::size_t>(p) - 1;
        return lo == knots[p] && hi == knots[n];
    }

    std::string name() const { return object_name_.empty() ? group_name_ : object_name_; }

    geom::Status end(const Statement& s) {
        if (!element_) return at_line(s.line, "end without a curv or surf element");
        Element e = std::move(*element_);
        element_.reset();
        const std::string what =
            std::string(e.surface ? "surf" : "curv") + " of line " + std::to_string(e.line);
        const std::string entity = "line " + std::to_string(e.line) + ": " +
                                   (e.surface ? "surf" : "curv") + " (cstype " +
                                   (e.rational ? "rat " : "") + e.type + ")";
        if (e.type != "bspline") {
            result_.skipped.push_back({entity, "only bspline curves and surfaces are imported"});
            return geom::Ok{};
        }
        if (!e.parm_u) return at_line(s.line, what + " has no 'parm u' before its end");
        if (e.surface && !e.parm_v)
            return at_line(s.line, what + " has no 'parm v' before its end");
        const long count = static_cast<long>(e.vertices.size());
        // The element's vertices, read again from the text once each.
        std::vector<glm::dvec4> values(e.vertices.size());
        for (std::size_t k = 0; k < e.vertices.size(); ++k) values[k] = vertex_at(e.vertices[k]);
        auto point = [&](long k) { return glm::dvec3(values[static_cast<std::size_t>(k)]); };
        auto weight = [&](long k) {
            return e.rational ? values[static_cast<std::size_t>(k)].w : 1.0;
        };
        auto knot_count_error = [&](char dir, std::size_t got, long points, int p) {
            return at_line(e.line,
                           what + ": parm " + dir + " has " + std::to_string(got) + " knots; " +
                               std::to_string(points) + " control vertices of degree " +
                               std::to_string(p) + " need " + std::to_string(points + p + 1),
                           ErrorCode::knots);
        };
        auto refused = [&](const geom::Error& err) {
            return at_line(e.line,
                           what + ": " + err.message +
                               (err.has_path && !err.path.empty() ? " (at " + err.path + ")" : ""),
                           err.code);
        };
        if (!e.surface) {
            geom::Curve c;
            c.type = e.rational ? geom::SplineType::nurbs : geom::SplineType::bspline;
            c.degree = e.degree_u;
            c.knots = *e.parm_u;
            if (c.knots.size() != static_cast<std::size_t>(count + c.degree + 1))
                return knot_count_error('u', c.knots.size(), count, c.degree);
            if (count > geom::max_points_per_surface)
                return at_line(e.line,
                               what + " has " + std::to_string(count) +
                                   " control vertices, more than " +
                                   std::to_string(geom::max_points_per_surface),
                               ErrorCode::limit);
            for (long k = 0; k < count; ++k) {
                c.points.push_back(point(k));
                c.weights.push_back(weight(k));
            }
            if (geom::Status st = geom::validate_curve(c); !st) return refused(st.error());
            if (!whole_domain(e.range[0], e.range[1], c.knots, c.degree)) {
                result_.skipped.push_back(
                    {entity, "its range [" + geom::format_number(e.range[0]) + ", " +
                                 geom::format_number(e.range[1]) +
                                 "] is not its knots' whole domain (trimmed curves are not "
                                 "imported)"});
                return geom::Ok{};
            }
            result_.objects.push_back({name(), std::move(c)});
            return geom::Ok{};
        }
        geom::Surface f;
        f.type = e.rational ? geom::SplineType::nurbs : geom::SplineType::bspline;
        f.degree_u = e.degree_u;
        f.degree_v = e.degree_v;
        f.knots_u = *e.parm_u;
        f.knots_v = *e.parm_v;
        const long n_u = static_cast<long>(f.knots_u.size()) - f.degree_u - 1;
        const long n_v = static_cast<long>(f.knots_v.size()) - f.degree_v - 1;
        if (n_u < 1) return knot_count_error('u', f.knots_u.size(), 1, f.degree_u);
        if (n_v < 1) return knot_count_error('v', f.knots_v.size(), 1, f.degree_v);
        if (n_u > geom::max_points_per_direction || n_v > geom::max_points_per_direction ||
            n_u * n_v > geom::max_points_per_surface)
            return at_line(e.line,
                           what + " has " + std::to_string(n_u) + " x " + std::to_string(n_v) +
                               " control vertices, more than " + "isoparm's limits",
                           ErrorCode::limit);
        if (n_u * n_v != count)
            return at_line(e.line,
                           what + " lists " + std::to_string(count) +
                               " control vertices; its knots ask for " + std::to_string(n_u) +
                               " x " + std::to_string(n_v) + " = " + std::to_string(n_u * n_v),
                           ErrorCode::knots);
        f.n_u = static_cast<int>(n_u);
        f.n_v = static_cast<int>(n_v);
        f.points.resize(static_cast<std::size_t>(count));
        f.weights.resize(static_cast<std::size_t>(count));
        // OBJ lists a surface's control vertices with u varying fastest.
        for (int j = 0; j < f.n_v; ++j)
            for (int i = 0; i < f.n_u; ++i) {
                const long k = static_cast<long>(j) * n_u + i;
                f.point(i, j) = point(k);
                f.weight(i, j) = weight(k);
            }
        if (geom::Status st = geom::validate_surface(f); !st) return refused(st.error());
        if (!whole_domain(e.range[0], e.range[1], f.knots_u, f.degree_u) ||
            !whole_domain(e.range[2], e.range[3], f.knots_v, f.degree_v)) {
            result_.skipped.push_back(
                {entity, "its range is not its knots' whole domain (trimmed surfaces are not "
                         "imported)"});
            return geom::Ok{};
        }
        for (const std::string& t : e.trims)
            result_.skipped.push_back({"line " + std::to_string(e.line) + ": surf's " + t,
                                       "trimming: the surface is imported untrimmed"});
        result_.objects.push_back({name(), std::move(f)});
        return geom::Ok{};
    }

    struct Ignored {
        std::string word;
        long first = 0;
        long count = 0;
    };

    std::string_view text_;
    std::vector<std::uint32_t> vertex_offsets_;
    // Control vertices named by all elements so far (the import's budget).
    std::size_t element_vertices_ = 0;
    std::string type_;
    bool rational_ = false;
    int degree_u_ = 0, degree_v_ = 0;
    std::string object_name_, group_name_;
    std::optional<Element> element_;
    std::vector<Ignored> ignored_;
    ImportResult result_;
};

} // namespace

geom::Expected<ImportResult> read_obj_freeform(std::string_view text) {
    return Reader().run(text);
}

} // namespace isoparm::exchange
