// The recording journal: steps in the script format, built as the session goes.
#include "core/scene/recorder.hpp"

#include "core/scene/command_json.hpp"
#include "core/scene/scene_io.hpp"
#include "core/scene/script.hpp"

namespace isoparm::scene {

using nlohmann::json;

Recorder::Recorder(const doc::Document& start) : start_(scene_to_json(start)) {
    remember_view(start);
}

void Recorder::remember_view(const doc::Document& doc) {
    view_ = doc.view;
    continuity_ = doc.continuity;
}

void Recorder::append_or_replace(json step, const char* kind) {
    if (last_kind_ == kind && !steps_.empty())
        steps_.back() = std::move(step);
    else
        steps_.push_back(std::move(step));
    last_kind_ = kind;
}

void Recorder::executed(const doc::History& history, const doc::Document& doc) {
    const doc::Command* top = history.top();
    const std::optional<doc::CommandSpec> spec = top ? top->spec() : std::nullopt;
    if (!spec) {
        ++left_out_;
    } else if (history.last_merged() && last_kind_ == "command") {
        steps_.back() = command_to_json(*spec); // the drag so far, as one step
    } else {
        steps_.push_back(command_to_json(*spec));
        last_kind_ = "command";
    }
    // What the command did to the view (a new curve point selected) replays with it.
    remember_view(doc);
}

void Recorder::undone(const doc::Document& doc) {
    steps_.push_back({{"undo", true}});
    last_kind_ = "undo";
    remember_view(doc);
}

void Recorder::redone(const doc::Document& doc) {
    steps_.push_back({{"redo", true}});
    last_kind_ = "redo";
    remember_view(doc);
}

void Recorder::observe(const doc::Document& doc,
                       std::optional<std::pair<double, double>> camera_degrees) {
    if (doc.view.selection != view_.selection)
        append_or_replace({{"select", selection_to_json(doc.view.selection)}}, "select");
    if (doc.view.indicator != view_.indicator)
        append_or_replace({{"indicator", {doc.view.indicator.x, doc.view.indicator.y}}},
                          "indicator");
    if (doc.view.barycentric != view_.barycentric)
        append_or_replace(
            {{"barycentric",
              {doc.view.barycentric[0], doc.view.barycentric[1], doc.view.barycentric[2]}}},
            "barycentric");
    if (doc.view.display != view_.display)
        append_or_replace({{"display", display_to_json(doc.view.display)}}, "display");
    // An object's own toggles, one step per object changed.
    for (const auto& [id, d] : doc.view.object_display) {
        const auto was = view_.object_display.find(id);
        if (was != view_.object_display.end() && was->second == d) continue;
        json step = object_display_to_json(d);
        step["object"] = id;
        append_or_replace({{"object_display", std::move(step)}},
                          ("object_display " + std::to_string(id)).c_str());
    }
    if (doc.continuity != continuity_)
        append_or_replace({{"continuity", doc::continuity_name(doc.continuity)}}, "continuity");
    if (camera_degrees && camera_degrees != camera_) {
        append_or_replace(
            {{"camera", {{"yaw", camera_degrees->first}, {"pitch", camera_degrees->second}}}},
            "camera");
        camera_ = camera_degrees;
    }
    remember_view(doc);
}

void Recorder::add_steps(const json& steps) {
    for (const json& step : steps) steps_.push_back(step);
    last_kind_ = "authored"; // a later view change is a step of its own
}

std::size_t Recorder::stop_count() const {
    std::size_t n = 0;
    for (const json& step : steps_) n += step.contains("pause") ? 1 : 0;
    return n;
}

json Recorder::script() const {
    return {{"format", script_format_name},
            {"version", script_format_version},
            {"scene", start_},
            {"steps", steps_}};
}

} // namespace isoparm::scene
