// Scripts: strict reading of every step before anything runs, then the steps in order.
#include "core/scene/script.hpp"

#include <algorithm>
#include <chrono>
#include <climits>
#include <cmath>
#include <filesystem>

#include "core/doc/patches.hpp"
#include "core/geom/work_budget.hpp"
#include "core/json/fields.hpp"
#include "core/json/json_file.hpp"
#include "core/json/reader.hpp"
#include "core/json/shapes.hpp"
#include "core/scene/command_json.hpp"
#include "core/scene/scene_io.hpp"
#include "core/scene/starting_scene.hpp"

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
    "undo",    "redo",       "select", "indicator",   "barycentric",
    "display", "continuity", "camera", "deboor_step", "screenshot",
    "caption", "pause",      "expect", "animate",     "object_display"};

std::string kinds_list() {
    std::string out = "command";
    for (std::string_view k : step_kinds) out += ", " + std::string(k);
    return out;
}

// A name is checked byte by byte, as the system will take it: a C string ends at a NUL, so
// ".bashrc\0.png" would write .bashrc; a separator or ".." would leave the folder; a control
// character or a leading dot (a hidden file) has no place in a picture's name.
std::string screenshot_name_problem(const std::string& name) {
    std::string printable = short_name(name);
    for (char& c : printable)
        if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) c = '?';
    const std::string shown = "'" + printable + "'";
    for (std::size_t k = 0; k < name.size(); ++k) {
        const auto c = static_cast<unsigned char>(name[k]);
        if (c == 0) return shown + " holds a NUL byte at " + std::to_string(k);
        if (c < 0x20 || c == 0x7f)
            return shown + " holds the control character " + std::to_string(c) + " at " +
                   std::to_string(k);
        if (c == '/' || c == '\\') return shown + " holds a folder separator";
    }
    if (name.size() <= 4 || name.compare(name.size() - 4, 4, ".png") != 0)
        return shown + " does not end in .png after a name";
    if (name.front() == '.') return shown + " begins with a dot (a hidden file)";
    if (name.size() > 200) return shown + " is longer than 200 bytes";
    return "";
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
    if (const std::string why = screenshot_name_problem(*name); !why.empty())
        return schema_error("a screenshot is a file name ending in .png, without folders (the "
                            "folder is --out): " +
                                why,
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
        // An 8192 x 8192 picture takes about 2.9 GB to render (colour, depth and multisampled
        // buffers): the area is capped as well as the sides.
        const double pixels = static_cast<double>(shot.width) * shot.height;
        if (pixels > max_screenshot_pixels)
            return make_error(ErrorCode::limit,
                              "a screenshot of " + std::to_string(shot.width) + "x" +
                                  std::to_string(shot.height) + " is " +
                                  geom::with_thousands(pixels) + " pixels, more than " +
                                  geom::with_thousands(max_screenshot_pixels) +
                                  " (4096x4096, about 0.7 GB to render)",
                              at + "/size");
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

// A number member of an animate step, left as it is when absent.
geom::Status optional_number(const json& v, const std::string& at, std::string_view name,
                             double& out) {
    const json* x = find_member(v, name);
    if (!x) return geom::Ok{};
    auto r = read_finite(*x, member_path(at, name), name);
    if (!r) return r.error();
    out = *r;
    return geom::Ok{};
}

// A point [u, v] of the domain square, left as it is when absent.
geom::Status optional_uv(const json& v, const std::string& at, std::string_view name,
                         glm::dvec2& out) {
    const json* x = find_member(v, name);
    if (!x) return geom::Ok{};
    auto r = indicator_from_json(*x, member_path(at, name));
    if (!r) return r.error();
    out = *r;
    return geom::Ok{};
}

// What an animation moves, as named ("weight", "knot", ...) with its JSON `k` at `kat`.
struct AnimatedMember {
    std::string_view kind;
    const json& k;
    std::string kat;
};

// The object an animation moves ({"object": id, ...}), its members checked.
geom::Status read_animated_object(const AnimatedMember& m,
                                  std::initializer_list<std::string_view> members,
                                  doc::AnimationTarget& t) {
    if (auto st = expect_object(m.k, m.kat, std::string(m.kind)); !st) return st;
    if (auto st = check_members(m.k, m.kat, std::string(m.kind), members); !st) return st;
    const json* id = find_member(m.k, "object");
    if (!id) return missing_member(m.kat, "object");
    auto n = read_integer(*id, member_path(m.kat, "object"), "an object id", 1,
                          static_cast<std::int64_t>(max_object_id));
    if (!n) return n.error();
    t.object = static_cast<std::uint64_t>(*n);
    return geom::Ok{};
}

// {"object": 1, "point": [i, j] or [i]}: a control point's weight, 0 to 5 unless told.
geom::Status read_weight_target(const AnimatedMember& m, doc::AnimationTarget& t) {
    t.kind = doc::AnimatedKind::weight;
    if (auto st = read_animated_object(m, {"object", "point"}, t); !st) return st;
    const json* point = find_member(m.k, "point");
    if (!point) return missing_member(m.kat, "point");
    const std::string pat = member_path(m.kat, "point");
    if (!point->is_array() || point->empty() || point->size() > 2)
        return schema_error("point is [i, j] (a surface's or triangle's) or [i] (a curve's)", pat);
    for (std::size_t c = 0; c < point->size(); ++c) {
        auto x = read_integer((*point)[c], pat + "/" + std::to_string(c), "a control point index",
                              0, INT_MAX);
        if (!x) return x.error();
        (c == 0 ? t.i : t.j) = static_cast<int>(*x);
    }
    t.from = 0;
    t.to = 5;
    return geom::Ok{};
}

// A knot and a parameter have no natural range: the step says from and to.
geom::Status need_range(const json& v, const std::string& at) {
    if (!find_member(v, "from")) return missing_member(at, "from");
    if (!find_member(v, "to")) return missing_member(at, "to");
    return geom::Ok{};
}

// {"object": 1, "direction": "u", "k": 4}: knot k along a direction.
geom::Status read_knot_target(const AnimatedMember& m, doc::AnimationTarget& t) {
    t.kind = doc::AnimatedKind::knot;
    if (auto st = read_animated_object(m, {"object", "direction", "k"}, t); !st) return st;
    if (const json* d = find_member(m.k, "direction")) {
        const auto dir = enum_value<geom::Dir>(*d);
        if (!dir) return schema_error("direction must be u or v", member_path(m.kat, "direction"));
        t.dir = *dir;
    }
    const json* idx = find_member(m.k, "k");
    if (!idx) return missing_member(m.kat, "k");
    auto x = read_integer(*idx, member_path(m.kat, "k"), "a knot index", 0, INT_MAX);
    if (!x) return x.error();
    t.k = static_cast<int>(*x);
    return geom::Ok{};
}

// {"object": 1, "name": "a"}: an implicit surface's parameter.
geom::Status read_parameter_target(const AnimatedMember& m, doc::AnimationTarget& t) {
    t.kind = doc::AnimatedKind::implicit_parameter;
    if (auto st = read_animated_object(m, {"object", "name"}, t); !st) return st;
    const json* name = find_member(m.k, "name");
    if (!name) return missing_member(m.kat, "name");
    auto n = read_string(*name, member_path(m.kat, "name"), "name");
    if (!n) return n.error();
    t.parameter = *n;
    return geom::Ok{};
}

// "line" from [u, v] to [u, v], or "circle" about a centre with a radius.
geom::Status read_indicator_target(const json& v, const std::string& at, bool circle,
                                   doc::AnimationTarget& t) {
    t.kind = circle ? doc::AnimatedKind::indicator_circle : doc::AnimatedKind::indicator_line;
    if (auto st = optional_uv(v, at, "from", t.uv_from); !st) return st;
    if (auto st = optional_uv(v, at, "to", t.uv_to); !st) return st;
    if (auto st = optional_uv(v, at, "centre", t.centre); !st) return st;
    if (auto st = optional_number(v, at, "radius", t.radius); !st) return st;
    if (!(t.radius > 0 && t.radius <= 1))
        return schema_error("radius is in (0, 1] (the domain square's sides are 1)",
                            member_path(at, "radius"));
    return geom::Ok{};
}

// What the step animates, by its member; then its range where the kind takes one.
geom::Status read_animated_target(const json& v, const std::string& at, std::string_view kind,
                                  bool circle, doc::AnimationTarget& t) {
    const AnimatedMember m{kind, v.at(std::string(kind)), member_path(at, kind)};
    geom::Status st = geom::Ok{};
    if (kind == "weight") {
        st = read_weight_target(m, t);
    } else if (kind == "knot") {
        st = read_knot_target(m, t);
        if (st) st = need_range(v, at);
    } else if (kind == "parameter") {
        st = read_parameter_target(m, t);
        if (st) st = need_range(v, at);
    } else if (kind == "indicator") {
        return read_indicator_target(v, at, circle, t);
    } else {
        t.kind = doc::AnimatedKind::deboor_step;
        if (auto r = read_true(m.k, m.kat, "deboor_step"); !r) return r.error();
        t.from = 0;
        t.to = 6;
    }
    if (!st) return st;
    if (auto r = optional_number(v, at, "from", t.from); !r) return r;
    return optional_number(v, at, "to", t.to);
}

// How long one pass takes, how fast it plays, the phase screenshots show, how it repeats and
// whether it plays.
geom::Status read_animation_timing(const json& v, const std::string& at, AnimateStep& a) {
    if (auto st = optional_number(v, at, "seconds", a.seconds); !st) return st;
    if (!(a.seconds > 0 && a.seconds <= 3600))
        return schema_error("seconds (one pass) is in (0, 3600]", member_path(at, "seconds"));
    if (auto st = optional_number(v, at, "speed", a.speed); !st) return st;
    if (!(a.speed > 0 && a.speed <= 100))
        return schema_error("speed is in (0, 100]", member_path(at, "speed"));
    if (auto st = optional_number(v, at, "at", a.at); !st) return st;
    if (a.at < 0 || a.at > 1)
        return schema_error("at is the phase shown in screenshots, in [0, 1]",
                            member_path(at, "at"));
    if (const json* r = find_member(v, "repeat")) {
        const auto rep = enum_value<doc::Repeat>(*r);
        if (!rep) return schema_error("repeat is once, loop or bounce", member_path(at, "repeat"));
        a.repeat = *rep;
    }
    if (const json* p = find_member(v, "play")) {
        auto b = read_bool(*p, member_path(at, "play"));
        if (!b) return b.error();
        a.play = *b;
    }
    return geom::Ok{};
}

// {"weight": {"object": 1, "point": [2, 2]}, "from": 0, "to": 5, "seconds": 4, "repeat":
// "bounce", "speed": 1, "at": 0.5, "play": true}, {"knot": {"object", "direction", "k"}, ...},
// {"parameter": {"object", "name"}, ...}, {"indicator": "line", "from": [u, v], "to": [u, v]},
// {"indicator": "circle", "centre": [u, v], "radius": r}, {"deboor_step": true, "from": 0,
// "to": 6}, or "stop".
Expected<AnimateStep> read_animate(const json& v, const std::string& at) {
    AnimateStep a;
    if (v.is_string() && v.get<std::string>() == "stop") {
        a.stop = true;
        return a;
    }
    if (auto st = expect_object(v, at, "animate (or \"stop\")"); !st) return st.error();
    const char* what[] = {"weight", "knot", "parameter", "indicator", "deboor_step"};
    std::string_view kind;
    for (std::string_view k : what)
        if (find_member(v, k)) {
            if (!kind.empty())
                return schema_error("an animation moves one thing: it has both '" +
                                        std::string(kind) + "' and '" + std::string(k) + "'",
                                    at);
            kind = k;
        }
    if (kind.empty())
        return schema_error("an animation names what moves: weight, knot, parameter, indicator or "
                            "deboor_step",
                            at);
    const bool indicator = kind == "indicator";
    std::vector<std::string_view> allowed{kind, "seconds", "speed", "repeat", "at", "play"};
    const json* shape = find_member(v, "indicator");
    const bool circle = indicator && shape->is_string() && shape->get<std::string>() == "circle";
    if (indicator && !(shape->is_string() && (shape->get<std::string>() == "line" || circle)))
        return schema_error("indicator is \"line\" or \"circle\"", member_path(at, "indicator"));
    if (circle) {
        allowed.insert(allowed.end(), {"centre", "radius"});
    } else {
        allowed.insert(allowed.end(), {"from", "to"});
    }
    if (auto st = check_members(v, at, "an animate step", allowed); !st) return st.error();
    if (auto st = read_animated_target(v, at, kind, circle, a.target); !st) return st.error();
    if (auto st = read_animation_timing(v, at, a); !st) return st.error();
    return a;
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
    if (kind == "object_display") {
        if (auto st = expect_object(v, kat, "object_display"); !st) return st.error();
        const auto id = v.find("object");
        if (id == v.end()) return missing_member(kat, "object");
        auto n = read_integer(*id, kat + "/object", "object", 1,
                              static_cast<std::int64_t>(max_object_id));
        if (!n) return n.error();
        json flags = v;
        flags.erase("object");
        auto d = object_display_from_json(flags, kat, doc::ObjectDisplay{});
        if (!d) return d.error();
        return step(ObjectDisplayStep{static_cast<std::uint64_t>(*n), std::move(flags)});
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
    if (kind == "animate") {
        auto a = read_animate(v, kat);
        if (!a) return a.error();
        return step(*a);
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
        auto start = read_starting_scene(*scene, script_dir, "the script");
        if (!start) return start.error();
        script.start = std::move(start->document);
        script.scene_name = std::move(start->name);
    }
    const json* steps = find_member(j, "steps");
    if (!steps) return missing_member("", "steps");
    if (!steps->is_array()) return schema_error("steps is an array of steps", "/steps");
    if (steps->size() > max_steps)
        return make_error(ErrorCode::limit,
                          "a script has at most " + std::to_string(max_steps) + " steps, got " +
                              std::to_string(steps->size()),
                          "/steps");
    double pixels = 0;
    for (std::size_t k = 0; k < steps->size(); ++k) {
        auto step = read_step((*steps)[k], "/steps/" + std::to_string(k));
        if (!step) return step.error();
        step->source = (*steps)[k];
        if (const auto* shot = std::get_if<ScreenshotStep>(&step->action)) {
            // Every screenshot is a render: the script's pictures together have a budget.
            pixels += static_cast<double>(shot->width) * shot->height;
            if (pixels > max_script_pixels)
                return make_error(ErrorCode::limit,
                                  "the script's screenshots up to this one are " +
                                      geom::with_thousands(pixels) + " pixels, more than " +
                                      geom::with_thousands(max_script_pixels) +
                                      " (about 300 pictures of 1280x800)",
                                  step->path + "/screenshot");
        }
        script.steps.push_back(std::move(step).value());
    }
    return script;
}

Expected<Script> load_script(const std::string& path) {
    auto value = read_json_file(path, max_script_bytes);
    if (!value) return value.error();
    const std::string dir = std::filesystem::path(path).parent_path().string();
    return script_from_json(*value, dir.empty() ? "." : dir);
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
    } else if (const auto* od = std::get_if<ObjectDisplayStep>(&a)) {
        if (!state.doc.find(od->object))
            return at_step(geom::make_error(
                ErrorCode::schema, "there is no object with id " + std::to_string(od->object),
                "/object_display/object"));
        auto d = object_display_from_json(od->display, "/object_display",
                                          doc::display_of(state.doc.view, od->object));
        if (!d) return at_step(d.error());
        state.doc.view.object_display[od->object] = *d;
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
    } else if (const auto* anim = std::get_if<AnimateStep>(&a)) {
        if (anim->stop) {
            state.animation.reset();
        } else {
            // Checked against the document as it is now; paths as the step writes them.
            if (auto st = doc::check_target(state.doc, anim->target); !st) {
                Error e = st.error();
                const char* kind = anim->target.kind == doc::AnimatedKind::weight ? "/weight"
                                   : anim->target.kind == doc::AnimatedKind::knot ? "/knot"
                                   : anim->target.kind == doc::AnimatedKind::implicit_parameter
                                       ? "/parameter"
                                       : "";
                if (e.path == "/parameter") e.path = "/name";
                if (e.path != "/from" && e.path != "/to" && e.path != "/centre")
                    e.path = kind + e.path;
                return at_step(e.under("/animate"));
            }
            state.animation = *anim;
        }
    } else if (const auto* e = std::get_if<ExpectStep>(&a)) {
        for (const std::string& problem : unmet_expectations(*e, state.doc))
            result.failed_expects.push_back(step.path + ": " + problem);
    }
    return geom::Ok{};
}

ScriptResult run_script(const Script& script, ScriptState& state, const ScriptHooks& hooks,
                        bool dry_run, double trial_seconds) {
    ScriptResult result;
    using clock = std::chrono::steady_clock;
    const auto deadline = clock::now() + std::chrono::duration_cast<clock::duration>(
                                             std::chrono::duration<double>(trial_seconds));
    for (const Step& step : script.steps) {
        // The trial run does every command's work: a script whose commands take longer than
        // that stops there, before anything is written.
        if (dry_run && clock::now() >= deadline) {
            result.stopped = make_error(ErrorCode::limit,
                                        "the script's steps up to this one took more than " +
                                            geom::format_number(trial_seconds) +
                                            " s to try (the work budget of a script)",
                                        step.path);
            break;
        }
        if (auto st = run_step(step, state, hooks, dry_run, result); !st) {
            result.stopped = st.error();
            break;
        }
    }
    return result;
}

} // namespace isoparm::scene
