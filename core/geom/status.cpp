// Error code names and number formatting for messages.
#include "core/geom/status.hpp"

#include <charconv>
#include <cmath>

namespace isoparm::geom {

const char* error_code_name(ErrorCode code) {
    switch (code) {
    case ErrorCode::parse:
        return "parse";
    case ErrorCode::schema:
        return "schema";
    case ErrorCode::knots:
        return "knots";
    case ErrorCode::degree:
        return "degree";
    case ErrorCode::weights:
        return "weights";
    case ErrorCode::domain:
        return "domain";
    case ErrorCode::multiplicity:
        return "multiplicity";
    case ErrorCode::compatibility:
        return "compatibility";
    case ErrorCode::geometry:
        return "geometry";
    case ErrorCode::limit:
        return "limit";
    case ErrorCode::unknown_op:
        return "unknown_op";
    case ErrorCode::internal:
        return "internal";
    }
    return "internal";
}

std::string format_number(double x) {
    if (std::isnan(x)) return "NaN";
    if (std::isinf(x)) return x > 0 ? "inf" : "-inf";
    char buf[64];
    auto [end, ec] = std::to_chars(buf, buf + sizeof buf, x);
    (void)ec;
    return std::string(buf, end);
}

} // namespace isoparm::geom
