// Internal to the constructions: result types, size caps and error re-homing.
#pragma once

#include <string>

#include "core/geom/status.hpp"
#include "core/geom/types.hpp"
#include "core/geom/validate.hpp"

namespace isoparm::geom::construct_detail {

// The type of a result: rational when any input is, Bezier when the inputs are Bezier types and
// every direction of the result is one span.
inline SplineType result_type(bool rational, bool single_span) {
    if (single_span) return rational ? SplineType::rational_bezier : SplineType::bezier;
    return rational ? SplineType::nurbs : SplineType::bspline;
}

// The size caps of the protocol for a result of n_u x n_v control points (`limit`, no single
// value at fault).
inline Status check_result_size(long n_u, long n_v) {
    if (n_u > max_points_per_direction || n_v > max_points_per_direction ||
        n_u * n_v > max_points_per_surface) {
        return make_error_nopath(
            ErrorCode::limit, "the result would have " + std::to_string(n_u) + " x " +
                                  std::to_string(n_v) + " control points, above the caps of " +
                                  std::to_string(max_points_per_direction) + " per direction and " +
                                  std::to_string(max_points_per_surface) + " per surface");
    }
    return Ok{};
}

// An error of an operation on one input curve, re-homed at that curve ("/curves/1"): a
// path-less error (a weight problem of the result) points at the curve itself.
inline Error at_curve(const Error& e, const std::string& curve_path, const std::string& name) {
    Error out = e;
    out.message = name + ": " + e.message;
    out.path = e.has_path ? curve_path + e.path : curve_path;
    out.has_path = true;
    return out;
}

} // namespace isoparm::geom::construct_detail
