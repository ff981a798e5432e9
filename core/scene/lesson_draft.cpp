// Lessons as stops: a script's steps cut at its pauses, and joined again.
#include "core/scene/lesson_draft.hpp"

#include <algorithm>

#include "core/json/fields.hpp"
#include "core/scene/script.hpp"

namespace isoparm::scene {

using nlohmann::json;

namespace {

bool is_caption(const json& step) {
    return step.is_object() && step.contains("caption");
}
bool is_pause(const json& step) {
    return step.is_object() && step.contains("pause");
}

} // namespace

std::string LessonDraft::caption(std::size_t k) const {
    if (k >= stops.size()) return {};
    const auto& steps = stops[k].steps;
    for (auto it = steps.rbegin(); it != steps.rend(); ++it)
        if (is_caption(*it) && (*it)["caption"].is_string()) return (*it)["caption"];
    return {};
}

void LessonDraft::set_caption(std::size_t k, const std::string& text) {
    if (k >= stops.size()) return;
    auto& steps = stops[k].steps;
    if (text.empty()) {
        std::erase_if(steps, is_caption);
        return;
    }
    for (auto it = steps.rbegin(); it != steps.rend(); ++it)
        if (is_caption(*it)) {
            (*it)["caption"] = text;
            return;
        }
    steps.insert(steps.begin(), json{{"caption", text}});
}

bool LessonDraft::move(std::size_t k, bool up) {
    if (k >= stops.size() || (up && k == 0) || (!up && k + 1 >= stops.size())) return false;
    const std::size_t other = up ? k - 1 : k + 1;
    std::swap(stops[k].steps, stops[other].steps);
    return true;
}

void LessonDraft::remove(std::size_t k) {
    if (k >= stops.size()) return;
    const bool last_unpaused = k + 1 == stops.size() && !stops[k].paused;
    stops.erase(stops.begin() + static_cast<long>(k));
    // The stop before the lesson's end takes over as the end.
    if (last_unpaused && !stops.empty()) stops.back().paused = false;
}

std::size_t LessonDraft::actions(std::size_t k) const {
    if (k >= stops.size()) return 0;
    return static_cast<std::size_t>(std::count_if(stops[k].steps.begin(), stops[k].steps.end(),
                                                  [](const json& s) { return !is_caption(s); }));
}

std::size_t LessonDraft::first_step(std::size_t k) const {
    std::size_t at = 0;
    for (std::size_t s = 0; s < k && s < stops.size(); ++s)
        at += stops[s].steps.size() + (stops[s].paused ? 1 : 0);
    return at;
}

std::size_t LessonDraft::pause_step(std::size_t k) const {
    return first_step(k) + (k < stops.size() ? stops[k].steps.size() : 0);
}

json LessonDraft::to_json() const {
    json j = {{"format", script_format_name}, {"version", script_format_version}};
    if (!title.empty()) j["title"] = title;
    if (!summary.empty()) j["summary"] = summary;
    if (!scene.is_null()) j["scene"] = scene;
    json steps = json::array();
    for (const LessonStop& stop : stops) {
        for (const json& s : stop.steps) steps.push_back(s);
        if (stop.paused) steps.push_back({{"pause", true}});
    }
    j["steps"] = std::move(steps);
    return j;
}

geom::Expected<LessonDraft> lesson_draft_from_json(const json& script) {
    using json_io::schema_error;
    if (!script.is_object()) return schema_error("a script is a JSON object", "");
    if (script.value("format", json()) != script_format_name)
        return schema_error(std::string("format must be \"") + script_format_name + "\"",
                            "/format");
    if (!script.contains("version") || script["version"] != script_format_version)
        return schema_error("version must be " + std::to_string(script_format_version), "/version");
    if (!script.contains("steps") || !script["steps"].is_array())
        return schema_error("steps is an array of steps", "/steps");
    LessonDraft d;
    if (script.contains("title") && script["title"].is_string()) d.title = script["title"];
    if (script.contains("summary") && script["summary"].is_string()) d.summary = script["summary"];
    if (script.contains("scene")) d.scene = script["scene"];
    LessonStop current;
    for (const json& step : script["steps"]) {
        if (is_pause(step)) {
            current.paused = true;
            d.stops.push_back(std::move(current));
            current = {};
            continue;
        }
        current.steps.push_back(step);
    }
    // What follows the last pause is the lesson's end: a stop of its own when it does anything.
    if (!current.steps.empty() || d.stops.empty()) {
        current.paused = false;
        d.stops.push_back(std::move(current));
    }
    return d;
}

void add_stop(json& steps, const std::string& caption) {
    if (!caption.empty()) steps.push_back({{"caption", caption}});
    steps.push_back({{"pause", true}});
}

} // namespace isoparm::scene
