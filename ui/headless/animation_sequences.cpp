#include "ui/headless/animation_sequences.hpp"

#include <cmath>

#include "ui/view/camera.hpp"
#include "ui/view/doc_access.hpp"
#include "ui/view/triangle_domain.hpp"

namespace isoparm::ui {

namespace {

double between(double from, double to, int k, int n) {
    return n == 1 ? from : from + (to - from) * k / (n - 1);
}

} // namespace

const doc::Object* sweep_object(const doc::Document& d) {
    if (const doc::Object* s = d.selected(); s && (s->surface() || s->curve())) return s;
    for (const doc::Object& o : d.objects)
        if (o.surface() || o.curve()) return &o;
    return nullptr;
}

std::optional<nlohmann::json> sequence_steps(const Sequence& seq, const doc::Document& d,
                                             bool deboor_on, std::string& error) {
    using nlohmann::json;
    json steps = json::array();
    if (seq.frames < 1 || seq.frames > 10000) {
        error = "a sweep or orbit needs 1..10000 pictures, not " + std::to_string(seq.frames);
        return std::nullopt;
    }
    if (seq.deboor) {
        const geom::TrianglePatch* t = selected_triangle(d);
        const geom::Surface* s = t ? nullptr : current_surface(d);
        if (!s && !t) {
            error = "de Boor's steps need a surface or a selected triangular patch";
            return std::nullopt;
        }
        const int last = t ? t->degree : s->degree_u + s->degree_v + 1;
        if (!deboor_on) steps.push_back({{"display", {{"deboor", true}}}});
        for (int k = 0; k <= last; ++k) steps.push_back({{"deboor_step", k}});
    }
    if (seq.weight) {
        const WeightSweep& w = *seq.weight;
        for (int k = 0; k < seq.frames; ++k) {
            json c = {{"command", "edit_point"},
                      {"id", w.object},
                      {"i", w.i},
                      {"weight", between(w.from, w.to, k, seq.frames)}};
            if (w.j >= 0) c["j"] = w.j;
            steps.push_back(c);
        }
    }
    if (seq.knot) {
        const KnotSweep& s = *seq.knot;
        for (int k = 0; k < seq.frames; ++k)
            steps.push_back({{"command", "move_knot"},
                             {"id", s.object},
                             {"direction", s.direction == geom::Dir::u ? "u" : "v"},
                             {"k", s.k},
                             {"value", between(s.from, s.to, k, seq.frames)}});
    }
    if (seq.orbit != 0) {
        const Camera c;
        const double yaw = seq.orbit_start ? seq.orbit_start->first : c.yaw * 180 / M_PI;
        const double pitch = seq.orbit_start ? seq.orbit_start->second : c.pitch * 180 / M_PI;
        if (std::abs(pitch) >= 90) {
            error = "the orbit's pitch must lie strictly between -90 and 90 degrees";
            return std::nullopt;
        }
        for (int k = 0; k < seq.frames; ++k)
            steps.push_back(
                {{"camera", {{"yaw", yaw + seq.orbit * k / seq.frames}, {"pitch", pitch}}}});
    }
    return steps;
}

} // namespace isoparm::ui
