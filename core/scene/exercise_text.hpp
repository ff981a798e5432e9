// How exercise checks are said in words (exercise.hpp): the label a check gets when its file
// gives none, and the ranges and values its messages quote.
#pragma once

#include <optional>
#include <string>

#include "core/scene/exercise.hpp"

namespace isoparm::scene {

// A number in a grade's message: six significant digits (0.4, not 0.3999999999999999).
std::string short_number(double x);
// "3", "at least 2", "at most 5", "between 0.5 and 2".
std::string range_text(const std::optional<double>& equals, const std::optional<double>& min,
                       const std::optional<double>& max);
// Whether x is in the range (equals within `tolerance` absolute).
bool in_range(double x, const std::optional<double>& equals, const std::optional<double>& min,
              const std::optional<double>& max, double tolerance = 0);
// "(1, 0, 2.5)".
std::string point_text(const glm::dvec3& p);
// "'vase'", or "a surface" when the check names no object.
std::string subject_text(const Check& c, const char* any);
// The check in words: "'hill' has degree 4 in u and v".
std::string describe_check(const Check& c);

} // namespace isoparm::scene
