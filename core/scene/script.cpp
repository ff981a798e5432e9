// Scripts: strict reading of every step before anything runs, then the steps in order.
#include "core/scene/script.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "core/doc/patches.hpp"
#include "core/json/fields.hpp"
#include "core/json/input_file.hpp"
#include "core/json/reader.hpp"
#include "core/json/shapes.hpp"
#include "core/scene/command_json.hpp"
#include "core/scene/scene_io.hpp"

namespace isoparm::scene {

using namespace isoparm::json_io;
using geom::Error;
using geom::ErrorCode;
using geom::Expected;
using nlohmann::json;

namespace {

constexpr std::uintmax_t max_script_bytes = 64u << 20;
constexpr std::size_t max_steps = 100000;

// The member that says what a step is (besides "command", which makes it a command).
constexpr std::string_view step_kinds[] = {
    "undo",   "redo",        "select",     "indicator", "barycentric", "display", "continuity",
    "camera", "deboor_step", "screenshot", "caption",   "pause",       "expect"};

std::string kinds_list() {
    std::string out = "command";
    for (std::string_view k : step_kinds) out += ", " + std::string(k);
    return out;
}

Expected<bool> read_true(const json& v, const std::string& at, std::string_view what) {
    auto b = read_bool(v, at);
    if (!b) return b.error();
    if (!*b)
        return schema_error(std::string(what) + " is written true (leave the step out instead)",
                            at);
    return true;
}

Expected<ScreenshotStep> read_screenshot(const json& j, const std::string& at) {
    if (auto st = check_members(j, at, "a screenshot step", {"screenshot", "view", "size"}); !st)
        return st.error();
    ScreenshotStep shot;
    auto name = read_string(j["screenshot"], at + "/screenshot", "the screenshot's file name");
    if (!name) return name.error();
    const std::filesystem::path p(*name);
    if (name->empty() || p.has_parent_path() || p.filename() != p || p.extension() != ".png" ||
        *name == ".png")
        return schema_error("a screenshot is a file name ending in .png, without folders (the "
                            "folder is --out), got '" +
                                short_name(*name) + "'",
                            at + "/screenshot");
    shot.name = *name;
    if (const json* v = find_member(j, "view")) {
        auto view = read_string(*v, at + "/view", "view");
        if (!view) return view.error();
        if (*view != "workstation" && *view != "3d")
            return schema_error(
                "view is \"workstation\" or \"3d\", got '" + short_name(*view) + "'", at + "/view");
        shot.view = *view == "3d" ? ShotView::view3d : ShotView::workstation;
    }
    if (const json* v = find_member(j, "size")) {
        if (!v->is_array() || v->size() != 2)
            return schema_error("size is [width, height] in pixels", at + "/size");
        for (std::size_t k = 0; k < 2; ++k) {
            auto side = read_integer((*v)[k], at + "/size/" + std::to_string(k),
                                     k == 0 ? "the width" : "the height", 16, 8192);
            if (!side) return side.error();
            (k == 0 ? shot.width : shot.height) = static_cast<int>(*side);
        }
    }
    return shot;
}

Expected<CameraStep> read_camera(const json& v, const std::string& at) {
    if (auto st = expect_object(v, at, "camera"); !st) return st.error();
    if (auto st = check_members(v, at, "camera", {"yaw", "pitch", "zoom"}); !st) return st.error();
    CameraStep c;
    const json* yaw = find_member(v, "yaw");
    const json* pitch = find_member(v, "pitch");
    if (!yaw) return missing_member(at, "yaw");
    if (!pitch) return missing_member(at, "pitch");
    auto y = read_finite(*yaw, at + "/yaw", "yaw (degrees)");
    if (!y) return y.error();
    auto p = read_finite(*pitch, at + "/pitch", "pitch (degrees)");
    if (!p) return p.error();
    if (std::abs(*p) >= 90)
        return schema_error("pitch is strictly between -90 and 90 degrees, got " +
                                geom::format_number(*p),
                            at + "/pitch");
    c.yaw_degrees = *y;
    c.pitch_degrees = *p;
    if (const json* zoom = find_member(v, "zoom")) {
        auto z = read_finite(*zoom, at + "/zoom", "zoom (percent)");
        if (!z) return z.error();
        if (*z <= 0)
            return schema_error("zoom is a percentage above 0 (100 = fit to view), got " +
                                    geom::format_number(*z),
                                at + "/zoom");
        c.zoom_percent = *z;
    }
    return c;
}

Expected<Step> read_step(const json& j, const std::string& at) {
    if (auto st = expect_object(j, at, "a step"); !st) return st.error();
    if (find_member(j, "command")) {
        auto spec = command_from_json(j, at);
        if (!spec) return spec.error();
        return Step{std::move(spec).value(), at};
    }
    std::string_view kind;
    for (std::string_view k : step_kinds) {
        if (!find_member(j, k)) continue;
        if (!kind.empty())
            return schema_error("a step does one thing: it has both '" + std::string(kind) +
                                    "' and '" + std::string(k) + "'",
                                at);
        kind = k;
    }
    if (kind.empty())
        return schema_error("a step is a command {\"command\": ...} or has one of these members: " +
                                kinds_list(),
                            at);
    const std::string kat = member_path(at, kind);
    const json& v = j.at(std::string(kind));
    if (kind != "screenshot")
        if (auto st = check_members(j, at, "a " + std::string(kind) + " step", {kind}); !st)
            return st.error();
    auto step = [&](StepAction a) -> Expected<Step> { return Step{std::move(a), at}; };
    if (kind == "undo" || kind == "redo" || kind == "pause") {
        auto t = read_true(v, kat, kind);
        if (!t) return t.error();
        if (kind == "undo") return step(UndoStep{});
        if (kind == "redo") return step(RedoStep{});
        return step(PauseStep{});
    }
    if (kind == "select") {
        if (!v.is_null())
            if (auto st = expect_object(v, kat, "select (or null)"); !st) return st.error();
        return step(SelectStep{v});
    }
    if (kind == "indicator") {
        auto uv = indicator_from_json(v, kat);
        if (!uv) return uv.error();
        return step(IndicatorStep{*uv});
    }
    if (kind == "barycentric") {
        auto rst = barycentric_from_json(v, kat);
        if (!rst) return rst.error();
        return step(BarycentricStep{*rst});
    }
    if (kind == "display") {
        // Checked against the defaults now; applied to the display as it is when the step runs.
        auto d = display_from_json(v, kat, doc::DisplaySettings{});
        if (!d) return d.error();
        return step(DisplayStep{v});
    }
    if (kind == "continuity") {
        auto c = continuity_from_json(v, kat);
        if (!c) return c.error();
        return step(ContinuityStep{*c});
    }
    if (kind == "camera") {
        auto c = read_camera(v, kat);
        if (!c) return c.error();
        return step(*c);
    }
    if (kind == "deboor_step") {
        if (v.is_string() && v.get<std::string>() == "all") return step(DeBoorStep{-1});
        auto n = read_integer(v, kat, "deboor_step (or \"all\")", 0, 64);
        if (!n) return n.error();
        return step(DeBoorStep{static_cast<int>(*n)});
    }
    if (kind == "screenshot") {
        auto s = read_screenshot(j, at);
        if (!s) return s.error();
        return step(*s);
    }
    if (kind == "caption") {
        auto t = read_string(v, kat, "caption");
        if (!t) return t.error();
        return step(CaptionStep{*t});
    }
    auto e = expect_from_json(v, kat);
    if (!e) return e.error();
    return step(*e);
}

} // namespace

// ---------------------------------------------------------------------------------------

Expected<Script> script_from_json(const json& j, const std::string& script_dir) {
    if (auto st = expect_object(j, "", "a script"); !st) return st.error();
    if (auto st = check_members(j, "", "a script",
                                {"format", "version", "title", "summary", "scene", "steps"});
        !st)
        return st.error();
    const json* format = find_member(j, "format");
    if (!format) return missing_member("", "format");
    if (!format->is_string() || format->get<std::string>() != script_format_name)
        return schema_error(std::string("format must be \"") + script_format_name + "\"",
                            "/format");
    const json* version = find_member(j, "version");
    if (!version) return missing_member("", "version");
    auto v = read_integer(*version, "/version", "version", 1, script_format_version);
    if (!v) return v.error();

    Script script;
    for (auto [name, into] :
         {std::pair{"title", &script.title}, std::pair{"summary", &script.summary}})
        if (const json* m = find_member(j, name)) {
            auto text = read_string(*m, member_path("", name), name);
            if (!text) return text.error();
            *into = *text;
        }
    script.start = doc::default_document();
    script.scene_name = "(default)";
    if (const json* scene = find_member(j, "scene")) {
        if (scene->is_string()) {
            const std::filesystem::path rel(scene->get<std::string>());
            const std::string path = rel.is_absolute()
                                         ? rel.string()
                                         : (std::filesystem::path(script_dir) / rel).string();
            auto loaded = load_scene(path);
            if (!loaded) {
                Error e = loaded.error();
                e.message =
                    "the starting scene '" + path + "': " + e.message +
                    (e.has_path && !e.path.empty() ? " (at " + e.path + " in that file)" : "");
                e.path = "/scene";
                e.has_path = true;
                return e;
            }
            script.start = std::move(loaded).value();
            script.scene_name = path;
        } else if (scene->is_object()) {
            auto inline_scene = scene_from_json(*scene);
            if (!inline_scene) return inline_scene.error().under("/scene");
            script.start = std::move(inline_scene).value();
            script.scene_name = "(inline)";
        } else {
            return schema_error("scene is a path to a scene file (relative to the script) or a "
                                "scene written inline",
                                "/scene");
        }
    }
    const json* steps = find_member(j, "steps");
    if (!steps) return missing_member("", "steps");
    if (!steps->is_array()) return schema_error("steps is an array of steps", "/steps");
    if (steps->size() > max_steps)
        return make_error(ErrorCode::limit,
                          "a script has at most " + std::to_string(max_steps) + " steps, got " +
                              std::to_string(steps->size()),
                          "/steps");
    for (std::size_t k = 0; k < steps->size(); ++k) {
        auto step = read_step((*steps)[k], "/steps/" + std::to_string(k));
        if (!step) return step.error();
        step->source = (*steps)[k];
        script.steps.push_back(std::move(step).value());
    }
    return script;
}

Expected<Script> load_script(const std::string& path) {
    auto text = read_input_file(path, max_script_bytes);
    if (!text) return text.error();
    auto read = read_json(*text);
    if (!read) {
        Error e = read.error();
        e.message = "'" + path + "' is not JSON: " + e.message;
        return e;
    }
    if (!read->problems.empty()) return read->problems.front();
    const std::string dir = std::filesystem::path(path).parent_path().string();
    return script_from_json(read->value, dir.empty() ? "." : dir);
}

geom::Status run_step(const Step& step, ScriptState& state, const ScriptHooks& hooks, bool dry_run,
                      ScriptResult& result) {
    auto at_step = [&](Error e) {
        e.path = step.path + (e.has_path ? e.path : std::string());
        e.has_path = true;
        return e;
    };
    const StepAction& a = step.action;
    if (const auto* spec = std::get_if<doc::CommandSpec>(&a)) {
        state.history.seal(); // one step, one undo step
        if (auto st = state.history.execute(state.doc, doc::make_command(*spec)); !st)
            return at_step(st.error());
        state.history.seal();
    } else if (std::holds_alternative<UndoStep>(a)) {
        if (!state.history.undo(state.doc))
            return at_step(geom::make_error_nopath(ErrorCode::schema, "there is nothing to undo"));
    } else if (std::holds_alternative<RedoStep>(a)) {
        if (!state.history.redo(state.doc))
            return at_step(geom::make_error_nopath(ErrorCode::schema, "there is nothing to redo"));
    } else if (const auto* sel = std::get_if<SelectStep>(&a)) {
        auto s = selection_from_json(sel->selection, "/select", state.doc);
        if (!s) return at_step(s.error());
        state.doc.view.selection = *s;
    } else if (const auto* ind = std::get_if<IndicatorStep>(&a)) {
        state.doc.view.indicator = ind->uv;
    } else if (const auto* bary = std::get_if<BarycentricStep>(&a)) {
        state.doc.view.barycentric = bary->rst;
    } else if (const auto* disp = std::get_if<DisplayStep>(&a)) {
        auto d = display_from_json(disp->display, "/display", state.doc.view.display);
        if (!d) return at_step(d.error());
        state.doc.view.display = *d;
    } else if (const auto* cont = std::get_if<ContinuityStep>(&a)) {
        state.doc.continuity = cont->mode;
    } else if (const auto* cam = std::get_if<CameraStep>(&a)) {
        state.camera = *cam;
    } else if (const auto* db = std::get_if<DeBoorStep>(&a)) {
        state.deboor_step = db->step;
    } else if (const auto* shot = std::get_if<ScreenshotStep>(&a)) {
        if (!dry_run && hooks.screenshot) {
            if (std::string problem = hooks.screenshot(state, *shot); !problem.empty())
                return at_step(geom::make_error_nopath(
                    ErrorCode::internal, "screenshot '" + shot->name + "': " + problem));
            result.screenshots.push_back(shot->name);
        }
    } else if (const auto* cap = std::get_if<CaptionStep>(&a)) {
        state.caption = cap->text;
        if (!dry_run && hooks.caption) hooks.caption(state, step);
    } else if (std::holds_alternative<PauseStep>(a)) {
        if (!dry_run && hooks.pause) hooks.pause(state, step);
    } else if (const auto* e = std::get_if<ExpectStep>(&a)) {
        for (const std::string& problem : unmet_expectations(*e, state.doc))
            result.failed_expects.push_back(step.path + ": " + problem);
    }
    return geom::Ok{};
}

ScriptResult run_script(const Script& script, ScriptState& state, const ScriptHooks& hooks,
                        bool dry_run) {
    ScriptResult result;
    for (const Step& step : script.steps) {
        if (auto st = run_step(step, state, hooks, dry_run, result); !st) {
            result.stopped = st.error();
            break;
        }
    }
    return result;
}

} // namespace isoparm::scene
