// The sequences an animation can be made of besides a script: de Boor's steps at the
// indicator, a weight or knot swept between two values, an orbit of the camera. Each is a
// list of script steps (docs/script-format.md), read by the one strict script reader, so an
// animation is always a script run (animation_job.hpp). `isoparm animate` and File > Export
// animation both build them here.
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "core/doc/document.hpp"

namespace isoparm::ui {

struct WeightSweep {
    std::uint64_t object = 0;
    int i = 0, j = -1; // j = -1: a curve's point
    double from = 1, to = 1;
};

struct KnotSweep {
    std::uint64_t object = 0;
    geom::Dir direction = geom::Dir::u;
    int k = 0;
    double from = 0, to = 1;
};

struct Sequence {
    bool deboor = false; // de Boor's (or de Casteljau's on a triangle) steps, one a picture
    double orbit = 0;    // degrees the camera turns about the vertical
    std::optional<std::pair<double, double>> orbit_start; // yaw, pitch in degrees
    std::optional<WeightSweep> weight;
    std::optional<KnotSweep> knot;
    int frames = 40; // pictures of a sweep or an orbit
    bool empty() const { return !deboor && orbit == 0 && !weight && !knot; }
};

// The steps of `seq` for the document `d` as a JSON array; nothing, with `error` naming what
// the document lacks. `deboor_on`: the document already shows de Boor's construction (no step
// switches it on, which would make a picture of every level at once).
std::optional<nlohmann::json> sequence_steps(const Sequence& seq, const doc::Document& d,
                                             bool deboor_on, std::string& error);

// The object a sweep acts on by default: the selected surface or curve, else the first.
const doc::Object* sweep_object(const doc::Document& d);

} // namespace isoparm::ui
