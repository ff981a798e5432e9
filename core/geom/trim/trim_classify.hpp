// Where a parameter point lies in a trimmed domain: kept, cut away, or on a loop.
#pragma once

#include <glm/vec2.hpp>
#include <vector>

#include "core/geom/enum_names.hpp"
#include "core/geom/trim/trim.hpp"
#include "core/geom/trim/trim_flatten.hpp"
#include "core/geom/types.hpp"

namespace isoparm::geom {

// Kept: on the trimmed surface. Cut away: in the domain but trimmed off, or outside the domain.
// Boundary: on a loop (or the domain's edge where there is no outer loop), within the
// classifier's boundary tolerance.
enum class TrimSide { kept, cut, boundary };
inline constexpr EnumName<TrimSide> trim_side_names[] = {
    {TrimSide::kept, "kept"}, {TrimSide::cut, "cut", "cut away"}, {TrimSide::boundary, "boundary"}};
static_assert(in_declaration_order(trim_side_names));
constexpr std::span<const EnumName<TrimSide>> enum_names(TrimSide) {
    return trim_side_names;
}

// Classifies points against a valid trim (validate_trim). The loops are cut into chords within
// 1e-6 of the domain's size once; a point farther than that from every chord is decided by the
// parity of the chords it sees along a ray, which equals the curves' (the curves stay within
// the tolerance band of their chords). A point inside the band is measured against the curves
// themselves (Newton's method for the nearest point, Piegl & Tiller 6.1): on a loop within
// `boundary_tolerance` (default 1e-9 of the domain's size), else decided by chords refined below
// its distance.
class TrimClassifier {
public:
    TrimClassifier(const Trim& trim, const ParamRect& domain, double boundary_tolerance = -1);

    TrimSide classify(glm::dvec2 p) const;
    // Distance in (u, v) from p to the nearest loop (or domain edge without an outer loop).
    double distance_to_boundary(glm::dvec2 p) const;
    double boundary_tolerance() const { return boundary_tolerance_; }

private:
    struct Chord {
        int loop, index;
    };
    bool kept_by_parity(glm::dvec2 p, const std::vector<FlatLoop>& flats) const;
    bool kept_by_rows(glm::dvec2 p) const;
    double chord_distance(glm::dvec2 p) const;
    double near_chord_distance(glm::dvec2 p) const; // exact within the band, else > band
    double curve_distance(glm::dvec2 p, double band) const;
    glm::dvec2 chord_start(const Chord& c) const;
    glm::dvec2 chord_end(const Chord& c) const;
    int bucket(double t, double lo, double hi) const;

    Trim trim_;
    ParamRect domain_;
    double boundary_tolerance_ = 0, flatness_ = 0;
    std::vector<FlatLoop> flats_;
    // The chords bucketed on a g x g grid over the domain (each in every cell its box, widened
    // by the band, touches) and in g rows (each in every row its v range touches).
    int g_ = 1;
    std::vector<std::vector<Chord>> cells_, rows_;
};

} // namespace isoparm::geom
