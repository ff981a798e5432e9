// Number formatting for messages.
#include "core/geom/status.hpp"

#include <charconv>
#include <cmath>

namespace isoparm::geom {

std::string format_number(double x) {
    if (std::isnan(x)) return "NaN";
    if (std::isinf(x)) return x > 0 ? "inf" : "-inf";
    char buf[64];
    auto [end, ec] = std::to_chars(buf, buf + sizeof buf, x);
    (void)ec;
    return std::string(buf, end);
}

std::string format_short(double x, int digits) {
    if (!std::isfinite(x)) return format_number(x);
    char buf[64];
    auto [end, ec] = std::to_chars(buf, buf + sizeof buf, x, std::chars_format::general, digits);
    (void)ec;
    return std::string(buf, end);
}

} // namespace isoparm::geom
