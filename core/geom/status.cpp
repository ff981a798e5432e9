// Number formatting for messages.
#include "core/geom/status.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <string>

namespace isoparm::geom {

std::string format_number(double x) {
    if (std::isnan(x)) return "NaN";
    if (std::isinf(x)) return x > 0 ? "inf" : "-inf";
    char buf[64];
    auto [end, ec] = std::to_chars(buf, buf + sizeof buf, x);
    (void)ec;
    return std::string(buf, end);
}

// The one formatter of numbers a person reads (labels, menus, undo entries, status text):
// `digits` significant digits, plain decimals for 1e-4 <= |x| < 1e6 with trailing zeros
// dropped ("0.3333", not 0.3333333333333333; "0.5"; "12346"), else scientific without a '+'
// or leading zeros in the exponent ("6.3e-16"); never "-0". No spaces, so a text wrapped at
// spaces never breaks a number. Edit fields and tooltips show format_number's full precision.
std::string format_short(double x, int digits) {
    if (!std::isfinite(x)) return format_number(x);
    digits = std::max(digits, 1);
    if (x == 0) return "0";
    char buf[64];
    const double ax = std::abs(x);
    std::string s;
    if (ax >= 1e-4 && ax < 1e6) {
        // Plain decimals with `digits` significant digits: 0.7626, 12.35, 12346, 0.0003142.
        const int lead = static_cast<int>(std::floor(std::log10(ax)));
        const int decimals = std::max(digits - 1 - lead, 0);
        auto [end, ec] =
            std::to_chars(buf, buf + sizeof buf, x, std::chars_format::fixed, decimals);
        (void)ec;
        s.assign(buf, end);
        if (s.find('.') != std::string::npos) {
            while (s.back() == '0') s.pop_back();
            if (s.back() == '.') s.pop_back();
        }
    } else {
        // Scientific with the exponent as a person writes it: 6.3e-16, 1.5e8.
        auto [end, ec] =
            std::to_chars(buf, buf + sizeof buf, x, std::chars_format::scientific, digits - 1);
        (void)ec;
        const std::string t(buf, end);
        const std::size_t e = t.find('e');
        std::string mantissa = t.substr(0, e);
        if (mantissa.find('.') != std::string::npos) {
            while (mantissa.back() == '0') mantissa.pop_back();
            if (mantissa.back() == '.') mantissa.pop_back();
        }
        const int exponent = std::stoi(t.substr(e + 1));
        s = mantissa + "e" + std::to_string(exponent);
    }
    if (s == "-0") s = "0";
    return s;
}

} // namespace isoparm::geom
