#include "core/exchange/real_text.hpp"

#include <charconv>
#include <string_view>

namespace isoparm::exchange {

std::string real_text(double x) {
    if (x == 0) return "0.0"; // -0.0 too: CAD readers do not all take a signed zero
    char buffer[32];
    const auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, x);
    std::string s(buffer, end);
    const auto e = s.find('e');
    std::string mantissa = e == std::string::npos ? s : s.substr(0, e);
    if (mantissa.find('.') == std::string::npos) mantissa += ".0";
    if (e == std::string::npos) return mantissa;
    // to_chars writes "e-05" or "e+16": keep the sign, at least two digits.
    const std::string_view exponent = std::string_view(s).substr(e + 1);
    const char sign = exponent[0] == '-' ? '-' : '+';
    const std::string_view digits = exponent.substr(exponent[0] == '-' || exponent[0] == '+');
    return mantissa + "E" + sign + (digits.size() < 2 ? "0" : "") + std::string(digits);
}

} // namespace isoparm::exchange
