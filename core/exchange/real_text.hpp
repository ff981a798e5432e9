// Real numbers as CAD exchange formats write them: shortest round-trip digits, always with a
// decimal point, an upper-case exponent ("1.0E-05", "0.5", "-3.0", "1.5E+16").
#pragma once

#include <string>

namespace isoparm::exchange {

std::string real_text(double x);

} // namespace isoparm::exchange
