// Hostile requests against the geom protocol: every error code and path rule of the spec.
#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

#include "core/protocol/protocol.hpp"

namespace {

using nlohmann::json;

struct Answer {
    int status = -1;
    std::string out, err;
    json response;
};

Answer run(const std::string& text) {
    std::istringstream in(text);
    std::ostringstream out, err;
    Answer a;
    a.status = isoparm::protocol::run_protocol(in, out, err);
    a.out = out.str();
    a.err = err.str();
    if (!a.out.empty()) a.response = json::parse(a.out);
    return a;
}

// Reusable valid pieces.
const std::string kCurve =
    R"({"degree": 2, "knots": [0, 0, 0, 1, 1, 1], "points": [[0, 0], [1, 1], [2, 0]]})";
const std::string kNurbs =
    R"({"type": "nurbs", "degree": 2, "knots": [0, 0, 0, 1, 1, 1], "points": [[0, 0], [1, 1], [2, 0]], "weights": [1, 2, 1]})";
const std::string kSurface =
    R"({"degree": [1, 2], "knots": [[0, 0, 1, 1], [0, 0, 0, 1, 1, 1]], "points": [[[0, 0, 0], [0, 1, 1], [0, 2, 0]], [[1, 0, 0], [1, 1, 1], [1, 2, 0]]]})";

std::string with_curve(const std::string& op, const std::string& rest,
                       const std::string& c = kCurve) {
    return R"({"op": ")" + op + R"(", "curve": )" + c + (rest.empty() ? "" : ", " + rest) + "}";
}
std::string with_surface(const std::string& op, const std::string& rest,
                         const std::string& s = kSurface) {
    return R"({"op": ")" + op + R"(", "surface": )" + s + (rest.empty() ? "" : ", " + rest) + "}";
}

struct Case {
    const char* name;
    std::string request;
    const char* code;
    const char* path; // nullptr: no path member
};

void PrintTo(const Case& c, std::ostream* os) {
    *os << c.name;
}

std::vector<Case> cases() {
    std::vector<Case> v;
    auto add = [&](const char* name, std::string req, const char* code, const char* path) {
        v.push_back({name, std::move(req), code, path});
    };
    // ---- the request itself
    add("not_an_object", "42", "schema", "");
    add("missing_op", R"({"curve": {}})", "schema", "/op");
    add("op_not_a_string", R"({"op": 3})", "schema", "/op");
    add("unknown_op", R"({"op": "evaluat"})", "unknown_op", "/op");
    add("empty_op_name", R"({"op": ""})", "unknown_op", "/op");
    add("op_name_case_matters", R"({"op": "Evaluate"})", "unknown_op", "/op");
    add("unknown_field_evaluate", with_curve("evaluate", R"("params": [0.5], "colour": 1)"),
        "schema", "/colour");
    add("unknown_field_escaped", with_curve("evaluate", R"("params": [0.5], "a/b~c": 1)"), "schema",
        "/a~1b~0c");
    add("direction_not_taken_by_evaluate",
        with_surface("evaluate", R"("params": [[0.5, 0.5]], "direction": "u")"), "schema",
        "/direction");
    // ---- duplicate keys and overflowing numbers (conventions 1 and 9)
    add("duplicate_top_level_key", with_curve("evaluate", R"("params": [0.5], "params": [1])"),
        "schema", "/params");
    add("duplicate_key_in_curve",
        R"({"op": "evaluate", "curve": {"degree": 2, "degree": 2, "knots": [0, 0, 0, 1, 1, 1], "points": [[0, 0], [1, 1], [2, 0]]}, "params": [0.5]})",
        "schema", "/curve/degree");
    add("duplicate_op", R"({"op": "evaluate", "op": "basis"})", "schema", "/op");
    add("overflow_in_weights",
        with_curve(
            "evaluate", R"("params": [0.5])",
            R"({"type": "nurbs", "degree": 2, "knots": [0, 0, 0, 1, 1, 1], "points": [[0, 0], [1, 1], [2, 0]], "weights": [1, 1e999, 1]})"),
        "weights", "/curve/weights/1");
    add("negative_overflow_in_surface_weights",
        with_surface(
            "evaluate", R"("params": [[0.5, 0.5]])",
            R"({"degree": [1, 1], "knots": [[0, 0, 1, 1], [0, 0, 1, 1]], "points": [[[0, 0], [0, 1]], [[1, 0], [1, 1]]], "weights": [[1, 1], [-1e999, 1]]})"),
        "weights", "/surface/weights/1/0");
    add("overflow_in_points",
        with_curve(
            "evaluate", R"("params": [0.5])",
            R"({"degree": 2, "knots": [0, 0, 0, 1, 1, 1], "points": [[0, 0], [1, 1e999], [2, 0]]})"),
        "schema", "/curve/points/1/1");
    add("overflow_in_knots",
        with_curve(
            "evaluate", R"("params": [0.5])",
            R"({"degree": 2, "knots": [0, 0, 0, 1e999, 1e999, 1e999], "points": [[0, 0], [1, 1], [2, 0]]})"),
        "schema", "/curve/knots/3");
    add("overflow_in_params", with_curve("evaluate", R"("params": [0.5, 1e999])"), "schema",
        "/params/1");
    add("overflow_in_derivatives",
        with_curve("evaluate", R"("params": [0.5], "derivatives": 1e999)"), "schema",
        "/derivatives");
    add("overflow_huge_integer_literal",
        with_curve("evaluate", R"("params": [)" + std::string(400, '9') + "]"), "schema",
        "/params/0");
    add("overflow_in_basis_weights",
        R"({"op": "basis", "degree": 1, "knots": [0, 0, 1, 1], "param": 0.5, "weights": [1, 1E+999]})",
        "weights", "/weights/1");
    // ---- geometry structure
    add("curve_not_an_object", R"({"op": "evaluate", "curve": [1, 2], "params": [0]})", "schema",
        "/curve");
    add("unknown_field_in_curve",
        with_curve(
            "evaluate", R"("params": [0.5])",
            R"({"degree": 2, "knots": [0, 0, 0, 1, 1, 1], "points": [[0, 0], [1, 1], [2, 0]], "colour": "red"})"),
        "schema", "/curve/colour");
    add("unknown_field_in_surface",
        with_surface(
            "evaluate", R"("params": [[0, 0]])",
            R"({"degree": [1, 1], "knots": [[0, 0, 1, 1], [0, 0, 1, 1]], "points": [[[0, 0], [0, 1]], [[1, 0], [1, 1]]], "knot": 1})"),
        "schema", "/surface/knot");
    add("bad_type",
        with_curve(
            "evaluate", R"("params": [0.5])",
            R"({"type": "spline", "degree": 1, "knots": [0, 0, 1, 1], "points": [[0, 0], [1, 1]]})"),
        "schema", "/curve/type");
    add("missing_degree",
        with_curve("evaluate", R"("params": [0.5])",
                   R"({"knots": [0, 0, 1, 1], "points": [[0, 0], [1, 1]]})"),
        "schema", "/curve/degree");
    add("degree_string",
        with_curve("evaluate", R"("params": [0.5])",
                   R"({"degree": "1", "knots": [0, 0, 1, 1], "points": [[0, 0], [1, 1]]})"),
        "schema", "/curve/degree");
    add("degree_fraction",
        with_curve("evaluate", R"("params": [0.5])",
                   R"({"degree": 1.5, "knots": [0, 0, 1, 1], "points": [[0, 0], [1, 1]]})"),
        "schema", "/curve/degree");
    add("degree_zero",
        with_curve("evaluate", R"("params": [0.5])",
                   R"({"degree": 0, "knots": [0, 1], "points": [[0, 0]]})"),
        "degree", "/curve/degree");
    add("degree_negative",
        with_curve("evaluate", R"("params": [0.5])",
                   R"({"degree": -3, "knots": [0, 1], "points": [[0, 0]]})"),
        "degree", "/curve/degree");
    add("degree_huge",
        with_curve("evaluate", R"("params": [0.5])",
                   R"({"degree": 1e300, "knots": [0, 0, 1, 1], "points": [[0, 0], [1, 1]]})"),
        "degree", "/curve/degree");
    add("too_few_points",
        with_curve(
            "evaluate", R"("params": [0.5])",
            R"({"degree": 3, "knots": [0, 0, 0, 0, 1, 1, 1], "points": [[0, 0], [1, 1], [2, 0]]})"),
        "degree", "/curve/degree");
    add("surface_degree_not_pair",
        with_surface(
            "evaluate", R"("params": [[0, 0]])",
            R"({"degree": 1, "knots": [[0, 0, 1, 1], [0, 0, 1, 1]], "points": [[[0, 0], [0, 1]], [[1, 0], [1, 1]]]})"),
        "schema", "/surface/degree");
    add("surface_degree_v_zero",
        with_surface(
            "evaluate", R"("params": [[0, 0]])",
            R"({"degree": [1, 0], "knots": [[0, 0, 1, 1], [0, 0, 1, 1]], "points": [[[0, 0], [0, 1]], [[1, 0], [1, 1]]]})"),
        "degree", "/surface/degree/1");
    add("surface_degree_u_mistyped",
        with_surface(
            "evaluate", R"("params": [[0, 0]])",
            R"({"degree": [null, 1], "knots": [[0, 0, 1, 1], [0, 0, 1, 1]], "points": [[[0, 0], [0, 1]], [[1, 0], [1, 1]]]})"),
        "schema", "/surface/degree/0");
    add("missing_points",
        with_curve("evaluate", R"("params": [0.5])", R"({"degree": 1, "knots": [0, 0, 1, 1]})"),
        "schema", "/curve/points");
    add("point_with_four_coordinates",
        with_curve("evaluate", R"("params": [0.5])",
                   R"({"degree": 1, "knots": [0, 0, 1, 1], "points": [[0, 0], [1, 1, 1, 1]]})"),
        "schema", "/curve/points/1");
    add("coordinate_not_a_number",
        with_curve("evaluate", R"("params": [0.5])",
                   R"({"degree": 1, "knots": [0, 0, 1, 1], "points": [[0, 0], ["1", 1]]})"),
        "schema", "/curve/points/1/0");
    add("coordinate_boolean",
        with_curve("evaluate", R"("params": [0.5])",
                   R"({"degree": 1, "knots": [0, 0, 1, 1], "points": [[0, true], [1, 1]]})"),
        "schema", "/curve/points/0/1");
    add("surface_row_lengths_differ",
        with_surface(
            "evaluate", R"("params": [[0, 0]])",
            R"({"degree": [1, 1], "knots": [[0, 0, 1, 1], [0, 0, 1, 1]], "points": [[[0, 0], [0, 1]], [[1, 0]]]})"),
        "schema", "/surface/points/1");
    add("surface_row_not_an_array",
        with_surface(
            "evaluate", R"("params": [[0, 0]])",
            R"({"degree": [1, 1], "knots": [[0, 0, 1, 1], [0, 0, 1, 1]], "points": [[0, 0], [[1, 0], [1, 1]]]})"),
        "schema", "/surface/points/0/0");
    add("missing_knots_bspline",
        with_curve("evaluate", R"("params": [0.5])",
                   R"({"type": "bspline", "degree": 1, "points": [[0, 0], [1, 1]]})"),
        "schema", "/curve/knots");
    add("knot_not_a_number",
        with_curve("evaluate", R"("params": [0.5])",
                   R"({"degree": 1, "knots": [0, 0, "1", 1], "points": [[0, 0], [1, 1]]})"),
        "schema", "/curve/knots/2");
    add("knot_count",
        with_curve("evaluate", R"("params": [0.5])",
                   R"({"degree": 1, "knots": [0, 0, 1, 1, 1], "points": [[0, 0], [1, 1]]})"),
        "knots", "/curve/knots");
    add("knots_decreasing",
        with_curve(
            "evaluate", R"("params": [0.5])",
            R"({"degree": 1, "knots": [0, 0, 2, 1, 3], "points": [[0, 0], [1, 1], [2, 2]]})"),
        "knots", "/curve/knots/3");
    add("knot_multiplicity_above_p_plus_1",
        with_curve(
            "evaluate", R"("params": [0.5])",
            R"({"degree": 1, "knots": [0, 0, 0.5, 0.5, 0.5, 1, 1], "points": [[0, 0], [1, 1], [2, 2], [3, 3], [4, 4]]})"),
        "knots", "/curve/knots/4");
    add("empty_domain",
        with_curve("evaluate", R"("params": [0.5])",
                   R"({"degree": 1, "knots": [0, 1, 1, 2], "points": [[0, 0], [1, 1]]})"),
        "knots", "/curve/knots");
    add("surface_knots_not_pair",
        with_surface(
            "evaluate", R"("params": [[0, 0]])",
            R"({"degree": [1, 1], "knots": [0, 0, 1, 1], "points": [[[0, 0], [0, 1]], [[1, 0], [1, 1]]]})"),
        "schema", "/surface/knots");
    add("surface_v_knot_count",
        with_surface(
            "evaluate", R"("params": [[0, 0]])",
            R"({"degree": [1, 1], "knots": [[0, 0, 1, 1], [0, 0, 1, 1, 1]], "points": [[[0, 0], [0, 1]], [[1, 0], [1, 1]]]})"),
        "knots", "/surface/knots/1");
    add("surface_v_knots_decreasing",
        with_surface(
            "evaluate", R"("params": [[0, 0]])",
            R"({"degree": [1, 1], "knots": [[0, 0, 1, 1], [0, 2, 1, 1]], "points": [[[0, 0], [0, 1]], [[1, 0], [1, 1]]]})"),
        "knots", "/surface/knots/1/2");
    add("weights_on_bspline",
        with_curve(
            "evaluate", R"("params": [0.5])",
            R"({"type": "bspline", "degree": 1, "knots": [0, 0, 1, 1], "points": [[0, 0], [1, 1]], "weights": [1, 1]})"),
        "schema", "/curve/weights");
    add("weights_on_bezier",
        with_curve(
            "evaluate", R"("params": [0.5])",
            R"({"type": "bezier", "degree": 1, "points": [[0, 0], [1, 1]], "weights": [1, 1]})"),
        "schema", "/curve/weights");
    add("weights_count",
        with_curve(
            "evaluate", R"("params": [0.5])",
            R"({"degree": 1, "knots": [0, 0, 1, 1], "points": [[0, 0], [1, 1]], "weights": [1]})"),
        "weights", "/curve/weights");
    add("weights_not_array",
        with_curve(
            "evaluate", R"("params": [0.5])",
            R"({"degree": 1, "knots": [0, 0, 1, 1], "points": [[0, 0], [1, 1]], "weights": 1})"),
        "weights", "/curve/weights");
    add("weight_not_a_number",
        with_curve(
            "evaluate", R"("params": [0.5])",
            R"({"degree": 1, "knots": [0, 0, 1, 1], "points": [[0, 0], [1, 1]], "weights": [1, null]})"),
        "weights", "/curve/weights/1");
    add("surface_weights_rows",
        with_surface(
            "evaluate", R"("params": [[0, 0]])",
            R"({"degree": [1, 1], "knots": [[0, 0, 1, 1], [0, 0, 1, 1]], "points": [[[0, 0], [0, 1]], [[1, 0], [1, 1]]], "weights": [[1, 1]]})"),
        "weights", "/surface/weights");
    add("surface_weights_row_length",
        with_surface(
            "evaluate", R"("params": [[0, 0]])",
            R"({"degree": [1, 1], "knots": [[0, 0, 1, 1], [0, 0, 1, 1]], "points": [[[0, 0], [0, 1]], [[1, 0], [1, 1]]], "weights": [[1, 1], [1]]})"),
        "weights", "/surface/weights/1");
    add("bezier_two_spans",
        with_curve(
            "evaluate", R"("params": [0.75])",
            R"({"type": "bezier", "degree": 2, "knots": [0, 0, 0.5, 1, 1, 1], "points": [[0, 0], [1, 1], [2, 0]]})"),
        "knots", "/curve/knots");
    // Knots that make a second span (so more than p + 1 points) blame the knots, not the
    // degree: docs/protocol.md, for every Bezier type and for surfaces too.
    add("bezier_knots_with_a_second_span_and_more_points",
        with_curve(
            "evaluate", R"("params": [0.5])",
            R"({"type": "bezier", "degree": 2, "knots": [0, 0, 0, 0.5, 1, 1, 1], "points": [[0, 0], [1, 1], [2, 0], [3, 1]]})"),
        "knots", "/curve/knots");
    add("rational_bezier_knots_with_a_second_span_and_more_points",
        with_curve(
            "evaluate", R"("params": [0.5])",
            R"({"type": "rational_bezier", "degree": 2, "knots": [0, 0, 0, 0.5, 1, 1, 1], "points": [[0, 0], [1, 1], [2, 0], [3, 1]]})"),
        "knots", "/curve/knots");
    add("bezier_surface_knots_with_a_second_span_and_more_points_in_u",
        with_surface(
            "evaluate", R"("params": [[0, 0]])",
            R"({"type": "bezier", "degree": [1, 1], "knots": [[0, 0, 0.5, 1, 1], [0, 0, 1, 1]], "points": [[[0, 0], [0, 1]], [[1, 0], [1, 1]], [[2, 0], [2, 1]]]})"),
        "knots", "/surface/knots/0");
    add("bezier_too_many_points_without_knots",
        with_curve(
            "evaluate", R"("params": [0.5])",
            R"({"type": "bezier", "degree": 2, "points": [[0, 0], [1, 1], [2, 0], [3, 1]]})"),
        "degree", "/curve/degree");
    add("rational_bezier_surface_two_spans_in_v",
        with_surface(
            "evaluate", R"("params": [[0, 0]])",
            R"({"type": "rational_bezier", "degree": [1, 2], "knots": [[0, 0, 1, 1], [0, 0, 0.5, 1, 1, 1]], "points": [[[0, 0], [0, 1], [0, 2]], [[1, 0], [1, 1], [1, 2]]]})"),
        "knots", "/surface/knots/1");
    // ---- subject rules
    add("curve_and_surface",
        R"({"op": "evaluate", "curve": )" + kCurve + R"(, "surface": )" + kSurface +
            R"(, "params": [0.5]})",
        "schema", "/surface");
    add("neither_curve_nor_surface", R"({"op": "evaluate", "params": [0.5]})", "schema", "/curve");
    // ---- evaluate
    add("params_missing", with_curve("evaluate", ""), "schema", "/params");
    add("params_not_array", with_curve("evaluate", R"("params": 0.5)"), "schema", "/params");
    add("param_not_a_number", with_curve("evaluate", R"("params": [0.5, "x"])"), "schema",
        "/params/1");
    add("param_outside_domain", with_curve("evaluate", R"("params": [0.5, 1.0000001])"), "domain",
        "/params/1");
    add("param_below_domain", with_curve("evaluate", R"("params": [-0.1])"), "domain", "/params/0");
    add("surface_param_not_pair", with_surface("evaluate", R"("params": [0.5])"), "schema",
        "/params/0");
    add("surface_u_outside", with_surface("evaluate", R"("params": [[0, 0], [2, 0.5]])"), "domain",
        "/params/1/0");
    add("surface_v_outside", with_surface("evaluate", R"("params": [[0.5, -1]])"), "domain",
        "/params/0/1");
    add("surface_v_not_number", with_surface("evaluate", R"("params": [[0.5, null]])"), "schema",
        "/params/0/1");
    add("derivatives_4", with_curve("evaluate", R"("params": [0.5], "derivatives": 4)"), "schema",
        "/derivatives");
    add("derivatives_negative",
        with_surface("evaluate", R"("params": [[0.5, 0.5]], "derivatives": -1)"), "schema",
        "/derivatives");
    add("derivatives_fraction", with_curve("evaluate", R"("params": [0.5], "derivatives": 1.5)"),
        "schema", "/derivatives");
    add("derivatives_string", with_curve("evaluate", R"("params": [0.5], "derivatives": "2")"),
        "schema", "/derivatives");
    add("normals_with_curve", with_curve("evaluate", R"("params": [0.5], "normals": true)"),
        "schema", "/normals");
    add("normals_not_bool", with_surface("evaluate", R"("params": [[0.5, 0.5]], "normals": 1)"),
        "schema", "/normals");
    // ---- basis
    add("basis_degree_zero", R"({"op": "basis", "degree": 0, "knots": [0, 0.5, 1], "param": 0.25})",
        "degree", "/degree");
    add("basis_degree_missing", R"({"op": "basis", "knots": [0, 0, 1, 1], "param": 0.25})",
        "schema", "/degree");
    add("basis_knots_missing", R"({"op": "basis", "degree": 1, "param": 0.25})", "schema",
        "/knots");
    add("basis_too_few_knots",
        R"({"op": "basis", "degree": 2, "knots": [0, 0, 1, 1], "param": 0.5})", "knots", "/knots");
    add("basis_knots_decreasing",
        R"({"op": "basis", "degree": 1, "knots": [0, 0, 1, 0.5, 2, 2], "param": 0.5})", "knots",
        "/knots/3");
    add("basis_param_missing", R"({"op": "basis", "degree": 1, "knots": [0, 0, 1, 1]})", "schema",
        "/param");
    add("basis_param_outside",
        R"({"op": "basis", "degree": 2, "knots": [0, 1, 2, 3, 4, 5, 6], "param": 1})", "domain",
        "/param");
    add("basis_derivatives_out_of_range",
        R"({"op": "basis", "degree": 1, "knots": [0, 0, 1, 1], "param": 0.5, "derivatives": 7})",
        "schema", "/derivatives");
    add("basis_weights_count",
        R"({"op": "basis", "degree": 1, "knots": [0, 0, 1, 1], "param": 0.5, "weights": [1, 1, 1]})",
        "weights", "/weights");
    add("basis_weights_vanishing_denominator",
        R"({"op": "basis", "degree": 1, "knots": [0, 0, 1, 1], "param": 0.5, "weights": [1, -1]})",
        "weights", "/weights");
    add("basis_unknown_field",
        R"({"op": "basis", "degree": 1, "knots": [0, 0, 1, 1], "param": 0.5, "curve": {}})",
        "schema", "/curve");
    // ---- deboor
    add("deboor_curve_with_u", with_curve("deboor", R"("param": 0.5, "u": 0.5)"), "schema", "/u");
    add("deboor_surface_with_param", with_surface("deboor", R"("u": 0.5, "v": 0.5, "param": 0.5)"),
        "schema", "/param");
    add("deboor_missing_param", with_curve("deboor", ""), "schema", "/param");
    add("deboor_missing_v", with_surface("deboor", R"("u": 0.5)"), "schema", "/v");
    add("deboor_u_outside", with_surface("deboor", R"("u": 1.5, "v": 0.5)"), "domain", "/u");
    add("deboor_param_outside", with_curve("deboor", R"("param": -2)"), "domain", "/param");
    // ---- insert_knot
    add("insert_missing_knot", with_curve("insert_knot", ""), "schema", "/knot");
    add("insert_knot_outside", with_curve("insert_knot", R"("knot": 2)"), "domain", "/knot");
    add("insert_times_zero", with_curve("insert_knot", R"("knot": 0.5, "times": 0)"), "schema",
        "/times");
    add("insert_times_fraction", with_curve("insert_knot", R"("knot": 0.5, "times": 1.5)"),
        "schema", "/times");
    add("insert_multiplicity", with_curve("insert_knot", R"("knot": 0.5, "times": 3)"),
        "multiplicity", "/times");
    add("insert_multiplicity_huge_times",
        with_curve("insert_knot", R"("knot": 0.5, "times": 1e15)"), "multiplicity", "/times");
    add("insert_at_clamped_end", with_curve("insert_knot", R"("knot": 1)"), "multiplicity",
        "/times");
    add("insert_surface_without_direction", with_surface("insert_knot", R"("knot": 0.5)"), "schema",
        "/direction");
    add("insert_curve_with_direction",
        with_curve("insert_knot", R"("knot": 0.5, "direction": "u")"), "schema", "/direction");
    add("insert_bad_direction", with_surface("insert_knot", R"("knot": 0.5, "direction": "w")"),
        "schema", "/direction");
    add("insert_unknown_field_param", with_curve("insert_knot", R"("knot": 0.5, "param": 0.5)"),
        "schema", "/param");
    add("insert_point_at_infinity",
        with_curve(
            "insert_knot", R"("knot": 0.5)",
            R"({"degree": 1, "knots": [0, 0, 1, 1], "points": [[0, 0], [1, 0]], "weights": [1, -1]})"),
        "weights", "/curve/weights");
    // ---- elevate_degree
    add("elevate_times_zero", with_curve("elevate_degree", R"("times": 0)"), "schema", "/times");
    add("elevate_times_negative",
        with_surface("elevate_degree", R"("direction": "v", "times": -2)"), "schema", "/times");
    add("elevate_times_huge", with_curve("elevate_degree", R"("times": 1e12)"), "limit", "/times");
    add("elevate_times_over_cap", with_curve("elevate_degree", R"("times": 5000)"), "limit",
        "/times");
    add("elevate_surface_without_direction", with_surface("elevate_degree", R"("times": 1)"),
        "schema", "/direction");
    // ---- split
    add("split_at_domain_start", with_curve("split", R"("param": 0)"), "domain", "/param");
    add("split_at_domain_end", with_surface("split", R"("direction": "v", "param": 1)"), "domain",
        "/param");
    add("split_missing_param", with_curve("split", ""), "schema", "/param");
    add("split_curve_with_direction", with_curve("split", R"("param": 0.5, "direction": "v")"),
        "schema", "/direction");
    // ---- tessellate
    add("tessellate_curve", with_curve("tessellate", R"("samples": [4, 4])"), "schema", "/curve");
    add("tessellate_missing_surface", R"({"op": "tessellate", "samples": [4, 4]})", "schema",
        "/surface");
    add("tessellate_missing_samples", with_surface("tessellate", ""), "schema", "/samples");
    add("tessellate_samples_not_pair", with_surface("tessellate", R"("samples": [4])"), "schema",
        "/samples");
    add("tessellate_samples_below_2", with_surface("tessellate", R"("samples": [4, 1])"), "schema",
        "/samples/1");
    add("tessellate_samples_over_cap", with_surface("tessellate", R"("samples": [5000, 2001])"),
        "limit", "/samples");
    add("tessellate_samples_enormous", with_surface("tessellate", R"("samples": [1e300, 1e300])"),
        "limit", "/samples");
    // ---- polygonize
    add("polygonize_parse",
        R"({"op": "polygonize", "implicit": "x^2 + (y", "bounds": [[-1, -1, -1], [1, 1, 1]], "cell": 0.5})",
        "parse", "/implicit");
    add("polygonize_unknown_name",
        R"({"op": "polygonize", "implicit": "x + w", "bounds": [[-1, -1, -1], [1, 1, 1]], "cell": 0.5})",
        "parse", "/implicit");
    add("polygonize_implicit_missing",
        R"({"op": "polygonize", "bounds": [[-1, -1, -1], [1, 1, 1]], "cell": 0.5})", "schema",
        "/implicit");
    add("polygonize_cell_zero",
        R"({"op": "polygonize", "implicit": "x", "bounds": [[-1, -1, -1], [1, 1, 1]], "cell": 0})",
        "schema", "/cell");
    add("polygonize_cell_negative",
        R"({"op": "polygonize", "implicit": "x", "bounds": [[-1, -1, -1], [1, 1, 1]], "cell": -0.1})",
        "schema", "/cell");
    add("polygonize_bounds_reversed",
        R"({"op": "polygonize", "implicit": "x", "bounds": [[1, -1, -1], [-1, 1, 1]], "cell": 0.5})",
        "schema", "/bounds");
    add("polygonize_bounds_shape",
        R"({"op": "polygonize", "implicit": "x", "bounds": [[-1, -1], [1, 1, 1]], "cell": 0.5})",
        "schema", "/bounds/0");
    add("polygonize_grid_over_cap",
        R"({"op": "polygonize", "implicit": "x", "bounds": [[-1, -1, -1], [1, 1, 1]], "cell": 0.001})",
        "limit", "/cell");
    return v;
}

class HostileRequest : public ::testing::TestWithParam<Case> {};

TEST_P(HostileRequest, FailsWithTheSpecifiedCodeAndPath) {
    const Case& c = GetParam();
    const Answer a = run(c.request);
    ASSERT_EQ(a.status, 1) << c.request << "\nstderr: " << a.err;
    EXPECT_TRUE(a.err.empty()) << a.err;
    ASSERT_TRUE(a.response.is_object()) << a.out;
    EXPECT_EQ(a.response["ok"], false);
    const json& e = a.response["error"];
    EXPECT_EQ(e["code"], c.code) << e.dump();
    if (c.path) {
        EXPECT_EQ(e.value("path", "<none>"), c.path) << e.dump();
    } else {
        EXPECT_FALSE(e.contains("path")) << e.dump();
    }
    ASSERT_TRUE(e["message"].is_string());
    const std::string message = e["message"].get<std::string>();
    EXPECT_FALSE(message.empty());
    EXPECT_EQ(message.find('\n'), std::string::npos);
    // The same request inside a batch: the same error, path relative to the element.
    const Answer b =
        run("[" + c.request + ", " + with_curve("evaluate", R"("params": [0.5])") + "]");
    ASSERT_EQ(b.status, 1);
    ASSERT_TRUE(b.response.is_array() && b.response.size() == 2) << b.out;
    EXPECT_EQ(b.response[0], a.response);
    EXPECT_EQ(b.response[1]["ok"], true);
}

INSTANTIATE_TEST_SUITE_P(Protocol, HostileRequest, ::testing::ValuesIn(cases()),
                         [](const ::testing::TestParamInfo<Case>& info) {
                             return std::string(info.param.name);
                         });

// ---- size caps that need big inputs -------------------------------------------------------

std::string grid_surface(int n_u, int n_v) {
    std::string s = R"({"degree": [1, 1], "knots": [[0, 0)";
    for (int i = 1; i < n_u - 1; ++i) s += ", " + std::to_string(i);
    s += ", " + std::to_string(n_u - 1) + ", " + std::to_string(n_u - 1) + "], [0, 0";
    for (int j = 1; j < n_v - 1; ++j) s += ", " + std::to_string(j);
    s += ", " + std::to_string(n_v - 1) + ", " + std::to_string(n_v - 1) + R"(]], "points": [)";
    for (int i = 0; i < n_u; ++i) {
        s += i ? ", [" : "[";
        for (int j = 0; j < n_v; ++j) s += j ? ", [0, 0]" : "[0, 0]";
        s += "]";
    }
    return s + "]}";
}

TEST(ProtocolLimits, TooManyPointsAlongACurve) {
    std::string pts;
    for (int i = 0; i < 4097; ++i) pts += i ? ", [0, 0]" : "[0, 0]";
    const Answer a = run(R"({"op": "evaluate", "curve": {"degree": 1, "knots": [], "points": [)" +
                         pts + R"(]}, "params": [0]})");
    EXPECT_EQ(a.status, 1);
    EXPECT_EQ(a.response["error"]["code"], "limit");
    EXPECT_EQ(a.response["error"]["path"], "/curve/points");
}

TEST(ProtocolLimits, TooManyPointsAlongV) {
    const Answer a = run(with_surface("evaluate", R"("params": [[0, 0]])", grid_surface(2, 4097)));
    EXPECT_EQ(a.status, 1);
    EXPECT_EQ(a.response["error"]["code"], "limit");
    EXPECT_EQ(a.response["error"]["path"], "/surface/points");
}

TEST(ProtocolLimits, TooManyPointsInASurface) {
    // 1001 x 1000 > 1,000,000 while each direction is within 4096.
    const Answer a =
        run(with_surface("evaluate", R"("params": [[0, 0]])", grid_surface(1001, 1000)));
    EXPECT_EQ(a.status, 1);
    EXPECT_EQ(a.response["error"]["code"], "limit");
    EXPECT_EQ(a.response["error"]["path"], "/surface/points");
}

TEST(ProtocolLimits, ALargeButLegalSurfaceIsAccepted) {
    const Answer a =
        run(with_surface("evaluate", R"("params": [[0, 0], [3.5, 2.25]])", grid_surface(100, 50)));
    EXPECT_EQ(a.status, 0) << a.out.substr(0, 300);
    EXPECT_EQ(a.response["ok"], true);
}

TEST(ProtocolLimits, TooManyParameters) {
    // 10,000,001 parameters: refused with `limit` before anything is evaluated. Built as a
    // value (parsing 10 M numbers would dominate the test's time under the sanitizers).
    json request = json::parse(with_curve("evaluate", R"("params": [])"));
    request["params"] = json::array_t(10000001, json(0.5));
    const json r = isoparm::protocol::handle_request(request);
    EXPECT_EQ(r["ok"], false);
    EXPECT_EQ(r["error"]["code"], "limit");
    EXPECT_EQ(r["error"]["path"], "/params");
}

TEST(ProtocolLimits, DeepNestingIsALimitErrorNotACrash) {
    const int depth = 100000;
    const std::string text = R"({"op": "evaluate", "params": )" + std::string(depth, '[') +
                             std::string(depth, ']') + "}";
    const Answer a = run(text);
    EXPECT_EQ(a.status, 1);
    EXPECT_EQ(a.response["error"]["code"], "limit");
    const std::string path = a.response["error"]["path"].get<std::string>();
    EXPECT_EQ(path.rfind("/params/0/0", 0), 0u) << path.substr(0, 40);
}

TEST(ProtocolLimits, NestingWithinTheLimitIsFine) {
    // 200 levels inside an unknown field: the unknown field is what is reported.
    const std::string text = with_curve(
        "evaluate", R"("params": [0.5], "deep": )" + std::string(200, '[') + std::string(200, ']'));
    const Answer a = run(text);
    EXPECT_EQ(a.response["error"]["code"], "schema");
    EXPECT_EQ(a.response["error"]["path"], "/deep");
}

// ---- text, batches and exit statuses ------------------------------------------------------

TEST(ProtocolText, NotJsonExitsTwoWithLineAndColumn) {
    for (const std::string text :
         {"nope", "", "{\"op\": \"evaluate\",\n  \"params\": [1,]}", "{\"a\": 1}}", "[1e999"}) {
        const Answer a = run(text);
        EXPECT_EQ(a.status, 2) << text;
        EXPECT_TRUE(a.out.empty()) << text;
        EXPECT_NE(a.err.find("line"), std::string::npos) << a.err;
        EXPECT_NE(a.err.find("column"), std::string::npos) << a.err;
        ASSERT_FALSE(a.err.empty());
        EXPECT_EQ(a.err.find('\n'), a.err.size() - 1) << "one line: " << a.err;
    }
    const Answer multi = run("{\"op\": \"evaluate\",\n  \"params\": [1,]}");
    EXPECT_NE(multi.err.find("line 2"), std::string::npos) << multi.err;
}

TEST(ProtocolText, EmptyBatchAnswersEmptyArray) {
    const Answer a = run(" [ ] ");
    EXPECT_EQ(a.status, 0);
    EXPECT_EQ(a.response, json::array());
}

TEST(ProtocolText, MixedBatchAnswersEachElementInOrder) {
    const std::string batch = "[" + with_curve("evaluate", R"("params": [0.5])") + ", " +
                              R"({"op": "nope"})" + ", 7, " +
                              with_curve("evaluate", R"("params": [0.5], "x": {"k": 1, "k": 2})") +
                              ", " + with_curve("evaluate", R"("params": [2])") + "]";
    const Answer a = run(batch);
    EXPECT_EQ(a.status, 1);
    ASSERT_EQ(a.response.size(), 5u);
    EXPECT_EQ(a.response[0]["ok"], true);
    EXPECT_EQ(a.response[1]["error"]["code"], "unknown_op");
    EXPECT_EQ(a.response[2]["error"]["code"], "schema");
    EXPECT_EQ(a.response[2]["error"]["path"], "");
    EXPECT_EQ(a.response[3]["error"]["path"], "/x/k");
    EXPECT_EQ(a.response[4]["error"]["code"], "domain");
    EXPECT_EQ(a.response[4]["error"]["path"], "/params/0");
}

TEST(ProtocolText, ReaderProblemsLandInTheirOwnBatchElement) {
    // Elements 1 and 11 repeat a key; element 10 must not inherit element 1's problem.
    std::string batch = "[";
    for (int i = 0; i < 12; ++i) {
        if (i) batch += ", ";
        batch += (i == 1 || i == 11) ? with_curve("evaluate", R"("params": [0.5], "params": [0])")
                                     : with_curve("evaluate", R"("params": [0.5])");
    }
    const Answer a = run(batch + "]");
    EXPECT_EQ(a.status, 1);
    ASSERT_EQ(a.response.size(), 12u);
    for (int i = 0; i < 12; ++i) {
        if (i == 1 || i == 11) {
            EXPECT_EQ(a.response[i]["error"]["path"], "/params") << i;
        } else {
            EXPECT_EQ(a.response[i]["ok"], true) << i;
        }
    }
}

TEST(ProtocolText, AllSucceedingBatchExitsZero) {
    const Answer a =
        run("[" + with_curve("evaluate", R"("params": [0])") + ", " +
            R"({"op": "basis", "degree": 1, "knots": [0, 0, 1, 1], "param": 1})" + "]");
    EXPECT_EQ(a.status, 0);
    EXPECT_EQ(a.response[1]["values"], json::parse("[0.0, 1.0]"));
}

// ---- accepted variants --------------------------------------------------------------------

TEST(ProtocolAccepts, IntegralFloatsForIntegers) {
    const Answer a = run(with_curve(
        "evaluate", R"("params": [0.5], "derivatives": 2.0)",
        R"({"degree": 2.0, "knots": [0, 0, 0, 1, 1, 1], "points": [[0, 0], [1, 1], [2, 0]]})"));
    EXPECT_EQ(a.status, 0) << a.out;
    EXPECT_EQ(a.response["derivatives"][0].size(), 3u);
}

TEST(ProtocolAccepts, RationalTypeWithoutWeightsHasUnitWeights) {
    const Answer a = run(with_curve(
        "insert_knot", R"("knot": 0.5)",
        R"({"type": "rational_bezier", "degree": 2, "points": [[0, 0], [1, 1], [2, 0]]})"));
    ASSERT_EQ(a.status, 0) << a.out;
    EXPECT_EQ(a.response["curve"]["type"], "nurbs");
    EXPECT_EQ(a.response["curve"]["weights"], json::parse("[1.0, 1.0, 1.0, 1.0]"));
}

TEST(ProtocolAccepts, TypeDefaultsFromWeights) {
    const Answer a = run(with_curve(
        "elevate_degree", "",
        R"({"degree": 1, "knots": [0, 0, 1, 1], "points": [[0, 0], [1, 1]], "weights": [1, 2]})"));
    ASSERT_EQ(a.status, 0) << a.out;
    EXPECT_EQ(a.response["curve"]["type"], "nurbs");
    const Answer b = run(with_curve("elevate_degree", ""));
    EXPECT_EQ(b.response["curve"]["type"], "bspline");
    EXPECT_FALSE(b.response["curve"].contains("weights"));
}

TEST(ProtocolAccepts, NormalsFalseAndEmptyParams) {
    const Answer a = run(with_surface("evaluate", R"("params": [], "normals": false)"));
    EXPECT_EQ(a.status, 0) << a.out;
    EXPECT_EQ(a.response["points"], json::array());
    EXPECT_FALSE(a.response.contains("normals"));
}

TEST(ProtocolAccepts, InsertAtTheEndOfAnUnclampedVector) {
    // Convention 20: inserting at a domain end of an unclamped vector is valid.
    const Answer a = run(with_curve(
        "insert_knot", R"("knot": 2)",
        R"({"degree": 2, "knots": [0, 1, 2, 3, 4, 5], "points": [[0, 0], [1, 1], [2, 0]]})"));
    EXPECT_EQ(a.status, 0) << a.out;
}

TEST(ProtocolAccepts, BasisReturnsLenKnotsMinusDegreeMinusOneValues) {
    const Answer a = run(
        R"({"op": "basis", "degree": 2, "knots": [0, 0, 0, 1, 2, 3, 3, 3], "param": 1.5, "derivatives": 3})");
    ASSERT_EQ(a.status, 0) << a.out;
    EXPECT_EQ(a.response["values"].size(), 5u);
    ASSERT_EQ(a.response["derivatives"].size(), 3u);
    double sum = 0;
    for (const json& x : a.response["values"]) sum += x.get<double>();
    EXPECT_NEAR(sum, 1.0, 1e-15);
    for (const json& x : a.response["derivatives"][2]) EXPECT_EQ(x.get<double>(), 0.0);
}

TEST(ProtocolAccepts, SurfaceDerivativeTableHasNullsAboveTheOrder) {
    const Answer a = run(
        with_surface("evaluate", R"("params": [[0.5, 0.5]], "derivatives": 2, "normals": true)"));
    ASSERT_EQ(a.status, 0) << a.out;
    const json& D = a.response["derivatives"][0];
    ASSERT_EQ(D.size(), 3u);
    EXPECT_TRUE(D[1][2].is_null());
    EXPECT_TRUE(D[2][1].is_null());
    EXPECT_TRUE(D[2][2].is_null());
    EXPECT_FALSE(D[1][1].is_null());
    EXPECT_EQ(a.response["normals"].size(), 1u);
}

TEST(ProtocolAccepts, SplitKeepsBezierTypeAndOriginalParameters) {
    const Answer a =
        run(with_curve("split", R"("param": 0.25)",
                       R"({"type": "bezier", "degree": 2, "points": [[0, 0], [1, 1], [2, 0]]})"));
    ASSERT_EQ(a.status, 0) << a.out;
    EXPECT_EQ(a.response["pieces"][0]["type"], "bezier");
    EXPECT_EQ(a.response["pieces"][0]["knots"], json::parse("[0.0, 0.0, 0.0, 0.25, 0.25, 0.25]"));
    EXPECT_EQ(a.response["pieces"][1]["knots"], json::parse("[0.25, 0.25, 0.25, 1.0, 1.0, 1.0]"));
}

TEST(ProtocolAccepts, TessellateGridAndTriangleOrder) {
    const Answer a = run(with_surface("tessellate", R"("samples": [3, 4])"));
    ASSERT_EQ(a.status, 0) << a.out;
    EXPECT_EQ(a.response["positions"].size(), 12u);
    EXPECT_EQ(a.response["normals"].size(), 12u);
    ASSERT_EQ(a.response["triangles"].size(), 12u);
    EXPECT_EQ(a.response["triangles"][0], json::parse("[0, 4, 5]"));
    EXPECT_EQ(a.response["triangles"][1], json::parse("[0, 5, 1]"));
}

TEST(ProtocolAccepts, PolygonizeASphere) {
    const Answer a = run(
        R"({"op": "polygonize", "implicit": "x^2 + y^2 + z^2 - 1", "bounds": [[-1.5, -1.5, -1.5], [1.5, 1.5, 1.5]], "cell": 0.25})");
    ASSERT_EQ(a.status, 0) << a.out.substr(0, 300);
    ASSERT_GT(a.response["triangles"].size(), 0u);
    for (const json& p : a.response["positions"]) {
        const double r = std::sqrt(p[0].get<double>() * p[0].get<double>() +
                                   p[1].get<double>() * p[1].get<double>() +
                                   p[2].get<double>() * p[2].get<double>());
        EXPECT_NEAR(r, 1.0, 0.05);
    }
}

TEST(ProtocolAccepts, HandleRequestOnAParsedValue) {
    const json r =
        isoparm::protocol::handle_request(json::parse(with_curve("evaluate", R"("params": [1])")));
    EXPECT_EQ(r["ok"], true);
    EXPECT_EQ(r["points"], json::parse("[[2.0, 0.0, 0.0]]"));
}

} // namespace
