// Constructions that stay linked to their inputs: an input's edit rebuilds every dependant,
// in order, in one undo step, exactly as building it afresh; cycles, direct edits of a
// constructed object and broken rebuilds are refused; deleting an input detaches.
#include <gtest/gtest.h>

#include "core/doc/associative.hpp"
#include "core/doc/command_spec.hpp"
#include "core/doc/commands.hpp"
#include "core/doc/commands_construction.hpp"
#include "core/doc/commands_curve.hpp"
#include "core/doc/curve_constructions.hpp"
#include "core/scene/command_json.hpp"
#include "core/scene/scene_io.hpp"
#include "tests/doc/doc_fixtures.hpp"

using namespace isoparm;
using namespace isoparm::doc;
using namespace isoparm::doc::testing;
using geom::Dir;
using geom::ErrorCode;

namespace {

std::uint64_t add_curve(Document& doc, const std::string& name, CurvePlane plane,
                        std::vector<glm::dvec3> points, CurveKnotMode mode) {
    auto o = new_curve_object(name, plane, std::move(points), 3, mode);
    EXPECT_TRUE(o.ok()) << o.error().message;
    o->id = doc.allocate_id();
    doc.objects.push_back(*o);
    return o->id;
}

// The paper's vase profile (Fig. 8: 11 points in the xz-plane), its copies at y = 1 and y = 2
// (skin sections) and a trajectory in the xy-plane.
std::vector<glm::dvec3> vase_profile(double y = 0, double scale = 1) {
    const double xz[11][2] = {{0.0, 0.0}, {0.9, 0.0},  {1.1, 0.25}, {0.7, 0.6},
                              {0.4, 1.0}, {0.35, 1.4}, {0.5, 1.8},  {0.9, 2.1},
                              {1.0, 2.5}, {0.8, 2.8},  {0.75, 3.0}};
    std::vector<glm::dvec3> p;
    for (const auto& q : xz) p.push_back({q[0] * scale, y, q[1]});
    return p;
}

struct Workshop {
    Document doc = default_document();
    History history;
    // Chord-length knots: a point's move changes the profile's knots too.
    std::uint64_t profile =
        add_curve(doc, "profile", CurvePlane::xz, vase_profile(), CurveKnotMode::chord);
    std::uint64_t section2 = add_curve(doc, "section 2", CurvePlane::free3d, vase_profile(1, 1.3),
                                       CurveKnotMode::clamped_uniform);
    std::uint64_t section3 = add_curve(doc, "section 3", CurvePlane::free3d, vase_profile(2, 0.8),
                                       CurveKnotMode::clamped_uniform);
    std::uint64_t trajectory =
        add_curve(doc, "path", CurvePlane::xy, {{0, 0, 0}, {1, 0.5, 0}, {2, -0.5, 0}, {3, 0, 0}},
                  CurveKnotMode::clamped_uniform);

    std::uint64_t build(Recipe r, std::string name = {}) {
        const auto st = history.execute(doc, construct(std::move(r), std::move(name)));
        EXPECT_TRUE(st.ok()) << st.error().message;
        history.seal();
        return constructed_id(*history.top());
    }
    static Recipe recipe(Construction kind, std::vector<std::uint64_t> inputs) {
        Recipe r;
        r.kind = kind;
        r.curves = std::move(inputs);
        return r;
    }
};

// The object is exactly what its recipe builds from the document now.
void expect_fresh(const Document& doc, std::uint64_t id) {
    const Object* o = doc.find(id);
    ASSERT_TRUE(o && o->construction);
    auto built = build_construction(doc, *o->construction);
    ASSERT_TRUE(built.ok()) << built.error().message;
    EXPECT_TRUE(same_shape(o->shape, built->object.shape)) << o->name << " is stale";
}

TEST(Associative, AProfileDragRebuildsItsRevolvedSweptAndSkinnedDependantsInOneUndoStep) {
    Workshop w;
    const std::uint64_t vase =
        w.build(Workshop::recipe(Construction::revolve, {w.profile}), "vase");
    const std::uint64_t swept =
        w.build(Workshop::recipe(Construction::sweep, {w.profile, w.trajectory}));
    Recipe skin = Workshop::recipe(Construction::skin, {w.profile, w.section2, w.section3});
    skin.skin_degree = 2;
    const std::uint64_t skinned = w.build(skin);
    ASSERT_NE(vase, 0u);
    ASSERT_NE(swept, 0u);
    ASSERT_NE(skinned, 0u);
    EXPECT_EQ(w.doc.find(vase)->name, "vase");
    EXPECT_EQ(w.doc.find(swept)->name, "sweep profile-path");

    const Document before = w.doc;
    const std::size_t steps = w.history.size();
    const geom::Surface vase_before = surface_of(w.doc, vase);
    // A drag: the first point moves to the axis in five steps (merged into one command).
    for (int k = 1; k <= 5; ++k) {
        const auto st = w.history.execute(
            w.doc, move_curve_point(w.profile, 1, glm::dvec3(0.9 - 0.18 * k, 0, 0.05 * k)));
        ASSERT_TRUE(st.ok()) << st.error().message;
    }
    w.history.seal();
    EXPECT_EQ(w.history.size(), steps + 1) << "the drag and its rebuilds are one undo step";
    EXPECT_NE(w.history.undo_label().find("rebuilds"), std::string::npos) << w.history.undo_label();

    // Each dependant is what building it afresh gives, bit for bit.
    for (std::uint64_t id : {vase, swept, skinned}) expect_fresh(w.doc, id);
    {
        Document fresh = w.doc;
        History h;
        Recipe r = Workshop::recipe(Construction::revolve, {w.profile});
        ASSERT_TRUE(h.execute(fresh, construct(r)).ok());
        EXPECT_TRUE(same_shape(fresh.objects.back().shape, w.doc.find(vase)->shape));
    }
    // The vase's second row is the profile's second point turned about z: it moved.
    const geom::Surface& s = surface_of(w.doc, vase);
    EXPECT_NE(s.point(1, 0), vase_before.point(1, 0));
    EXPECT_EQ(s.point(1, 0), curve_of(w.doc, w.profile).points[1]);

    const Document after = w.doc;
    ASSERT_TRUE(w.history.undo(w.doc));
    EXPECT_TRUE(same_document(w.doc, before)) << "undo takes the edit and every rebuild back";
    ASSERT_TRUE(w.history.redo(w.doc));
    EXPECT_TRUE(same_document(w.doc, after));
}

TEST(Associative, AChainIsRebuiltInDependencyOrderAndACycleIsRefused) {
    Workshop w;
    const std::uint64_t vase =
        w.build(Workshop::recipe(Construction::revolve, {w.profile}), "vase");
    Recipe rim = Workshop::recipe(Construction::isocurve, {vase});
    rim.iso_dir = Dir::u;
    rim.iso_t = 1; // the top edge: a circle
    const std::uint64_t rim_id = w.build(rim, "rim");
    // The rim is an input as well: a ruled collar between the rim and a lifted copy of it.
    const std::uint64_t collar =
        w.build(Workshop::recipe(Construction::ruled, {rim_id, w.section2}));
    EXPECT_EQ(dependants_in_order(w.doc, {w.profile}),
              (std::vector<std::uint64_t>{vase, rim_id, collar}));

    ASSERT_TRUE(w.history.execute(w.doc, move_curve_point(w.profile, 10, {1.2, 0, 3.2})).ok());
    for (std::uint64_t id : {vase, rim_id, collar}) expect_fresh(w.doc, id);
    // The rim is the top row of the vase: the circle of radius 1.2 at z = 3.2.
    EXPECT_EQ(curve_of(w.doc, rim_id).points.front(), glm::dvec3(1.2, 0, 3.2));

    // The vase cannot be revolved from its own rim.
    Recipe loop = Workshop::recipe(Construction::revolve, {rim_id});
    const Document before = w.doc;
    auto refused = w.history.execute(w.doc, edit_construction(vase, loop));
    ASSERT_FALSE(refused.ok());
    EXPECT_EQ(refused.error().path, "/construction/inputs/0");
    EXPECT_NE(refused.error().message.find("cycle"), std::string::npos) << refused.error().message;
    EXPECT_TRUE(same_document(w.doc, before));
    // Nor from itself, through a hand-written scene object.
    Object self = *w.doc.find(collar);
    self.id = 99;
    self.construction->curves = {99, w.section2};
    EXPECT_FALSE(w.history.execute(w.doc, add_object(self)).ok());
    EXPECT_TRUE(same_document(w.doc, before));
}

TEST(Associative, AConstructedSurfacesOwnPointsWaitForDetach) {
    Workshop w;
    const std::uint64_t vase =
        w.build(Workshop::recipe(Construction::revolve, {w.profile}), "vase");
    const Document before = w.doc;
    auto moved = w.history.execute(w.doc, move_control_point(vase, 2, 2, {0, 0, 5}));
    ASSERT_FALSE(moved.ok());
    EXPECT_EQ(moved.error().path, "/id");
    EXPECT_NE(moved.error().message.find("Detach"), std::string::npos) << moved.error().message;
    EXPECT_NE(moved.error().message.find("Revolve of 'profile'"), std::string::npos);
    EXPECT_TRUE(same_document(w.doc, before));
    // check() says so beforehand, for the menus.
    EXPECT_FALSE(associative(move_control_point(vase, 2, 2, {0, 0, 5}))->check(w.doc).ok());
    glm::dmat4 up(1.0);
    up[3] = glm::dvec4(0, 0, 1, 1);
    EXPECT_FALSE(w.history.execute(w.doc, transform_object(vase, up)).ok());

    ASSERT_TRUE(w.history.execute(w.doc, detach(vase)).ok());
    EXPECT_FALSE(w.doc.find(vase)->construction.has_value());
    EXPECT_TRUE(same_shape(w.doc.find(vase)->shape, before.find(vase)->shape));
    w.history.seal();
    ASSERT_TRUE(w.history.execute(w.doc, move_control_point(vase, 2, 2, {0, 0, 5})).ok());
    // A free surface no longer follows.
    const geom::Surface free = surface_of(w.doc, vase);
    ASSERT_TRUE(w.history.execute(w.doc, move_curve_point(w.profile, 4, {0.2, 0, 1})).ok());
    EXPECT_TRUE(same_shape(w.doc.find(vase)->shape, SurfaceObject{free}));
    // Detach is undone like any edit.
    w.history.seal();
    ASSERT_TRUE(w.history.undo(w.doc));
    ASSERT_TRUE(w.history.undo(w.doc));
    ASSERT_TRUE(w.history.undo(w.doc));
    EXPECT_TRUE(same_document(w.doc, before));
}

TEST(Associative, TheObjectARefusedEditWouldChangeIsNamedForTheDetachQuestion) {
    // The window asks to detach exactly the constructed object an edit was refused for, then
    // runs the edit: a point move, a knot split and a weight on the vase; not a refinement (the
    // recipe records it), not an input's edit (the vase follows), not a command refused for
    // another reason.
    Workshop w;
    const std::uint64_t vase =
        w.build(Workshop::recipe(Construction::revolve, {w.profile}), "vase");
    const auto spec_of = [](std::unique_ptr<Command> c) { return *c->spec(); };
    const auto object_of = [&](const CommandSpec& spec) -> std::optional<std::uint64_t> {
        const auto edit = constructed_object_edited(w.doc, spec);
        if (!edit) return std::nullopt;
        EXPECT_FALSE(edit->label.empty());
        return edit->object;
    };
    EXPECT_EQ(object_of(spec_of(move_control_point(vase, 2, 2, {0, 0, 5}))), vase);
    EXPECT_EQ(object_of(spec_of(set_weight(vase, 2, 2, 3.0))), vase);
    ASSERT_TRUE(w.history.execute(w.doc, insert_knot(vase, Dir::v, 0.3)).ok());
    ASSERT_TRUE(w.history.execute(w.doc, insert_knot(vase, Dir::v, 0.3)).ok());
    w.history.seal();
    const auto split_edit =
        constructed_object_edited(w.doc, spec_of(split_knot(vase, Dir::v, 0.3, std::nullopt)));
    ASSERT_TRUE(split_edit);
    EXPECT_EQ(split_edit->label.rfind("Split knot v = 0.3 (x2 becomes x1", 0), 0u)
        << split_edit->label;
    EXPECT_EQ(object_of(spec_of(split_knot(vase, Dir::v, 0.3, std::nullopt))), vase);
    EXPECT_EQ(object_of(spec_of(insert_knot(vase, Dir::u, 0.4))), std::nullopt);
    EXPECT_EQ(object_of(spec_of(move_curve_point(w.profile, 4, {0.2, 0, 1}))), std::nullopt);
    EXPECT_EQ(object_of(spec_of(move_control_point(vase, 99, 2, {0, 0, 5}))), std::nullopt);
    // After detach the same edit runs.
    const CommandSpec split = spec_of(split_knot(vase, Dir::v, 0.3, std::nullopt));
    EXPECT_FALSE(w.history.execute(w.doc, make_command(split)).ok());
    ASSERT_TRUE(w.history.execute(w.doc, detach(vase)).ok());
    EXPECT_EQ(object_of(split), std::nullopt);
    EXPECT_TRUE(w.history.execute(w.doc, make_command(split)).ok());
}

TEST(Associative, RefinementsAreRecordedAndRepeated) {
    // A 64 x 64 vase from an 11-point profile: the revolution is 11 x 9, refined in both
    // directions after building (the frame bench drags this one's profile).
    Workshop w;
    const std::uint64_t vase =
        w.build(Workshop::recipe(Construction::revolve, {w.profile}), "vase");
    const auto& U = surface_of(w.doc, vase).knots_u;
    std::vector<double> knots;
    for (int k = 0; k < 53; ++k) knots.push_back(U[3] + (U[U.size() - 4] - U[3]) * (k + 0.37) / 53);
    for (double t : knots) ASSERT_TRUE(w.history.execute(w.doc, insert_knot(vase, Dir::u, t)).ok());
    for (int k = 0; k < 55; ++k)
        ASSERT_TRUE(w.history.execute(w.doc, insert_knot(vase, Dir::v, (k + 0.37) / 55)).ok());
    const geom::Surface& s = surface_of(w.doc, vase);
    EXPECT_EQ(s.n_u, 64);
    EXPECT_EQ(s.n_v, 64);
    EXPECT_EQ(w.doc.find(vase)->construction->refinements.size(), 108u);
    expect_fresh(w.doc, vase);

    ASSERT_TRUE(w.history.execute(w.doc, move_curve_point(w.profile, 5, {0.6, 0, 1.5})).ok());
    expect_fresh(w.doc, vase);
    EXPECT_EQ(surface_of(w.doc, vase).n_u, 64);
    // Undoing an insertion takes its record back too.
    w.history.seal();
    ASSERT_TRUE(w.history.undo(w.doc));
    ASSERT_TRUE(w.history.undo(w.doc));
    EXPECT_EQ(w.doc.find(vase)->construction->refinements.size(), 107u);
    EXPECT_EQ(surface_of(w.doc, vase).n_v, 63);
}

TEST(Associative, DeletingAnInputDetachesItsDependantsInTheSameStep) {
    Workshop w;
    const std::uint64_t vase =
        w.build(Workshop::recipe(Construction::revolve, {w.profile}), "vase");
    const Document before = w.doc;
    ASSERT_TRUE(w.history.execute(w.doc, remove_object(w.profile)).ok());
    EXPECT_FALSE(w.doc.find(vase)->construction.has_value());
    EXPECT_NE(w.history.undo_label().find("detaches vase"), std::string::npos)
        << w.history.undo_label();
    ASSERT_TRUE(w.history.undo(w.doc));
    EXPECT_TRUE(same_document(w.doc, before));
}

TEST(Associative, AnEditThatADependantCannotFollowIsRefusedWhole) {
    Workshop w;
    // A swung surface needs its profile in the xz-plane; a free 3D move off it is refused.
    const std::uint64_t swung =
        w.build(Workshop::recipe(Construction::swing, {w.profile, w.trajectory}));
    ASSERT_NE(swung, 0u);
    ASSERT_TRUE(
        w.history.execute(w.doc, set_curve_plane(w.profile, CurvePlane::free3d, false)).ok());
    w.history.seal();
    const Document before = w.doc;
    auto st = w.history.execute(w.doc, move_curve_point(w.profile, 3, {0.7, 0.4, 0.6}));
    ASSERT_FALSE(st.ok());
    EXPECT_NE(st.error().message.find("cannot follow"), std::string::npos) << st.error().message;
    EXPECT_NE(st.error().message.find("xz"), std::string::npos) << st.error().message;
    EXPECT_TRUE(same_document(w.doc, before));
}

TEST(Associative, EditConstructionChangesParametersInPlaceAndMergesADrag) {
    Workshop w;
    const std::uint64_t vase =
        w.build(Workshop::recipe(Construction::revolve, {w.profile}), "vase");
    const std::size_t objects = w.doc.objects.size();
    const Document before = w.doc;
    Recipe r = *w.doc.find(vase)->construction;
    for (double angle : {300.0, 240.0, 180.0}) {
        r.angle = angle;
        ASSERT_TRUE(w.history.execute(w.doc, edit_construction(vase, r)).ok());
    }
    w.history.seal();
    EXPECT_EQ(w.doc.objects.size(), objects) << "edited, not built again";
    EXPECT_EQ(w.doc.find(vase)->construction->angle, 180);
    EXPECT_EQ(surface_of(w.doc, vase).n_v, 5) << "a half turn is two quarter arcs";
    expect_fresh(w.doc, vase);
    ASSERT_TRUE(w.history.undo(w.doc));
    EXPECT_TRUE(same_document(w.doc, before)) << "one undo step for the whole slider drag";

    r.angle = 400;
    auto bad = w.history.execute(w.doc, edit_construction(vase, r));
    ASSERT_FALSE(bad.ok());
    EXPECT_EQ(bad.error().path, "/construction/angle");
    // A free object has no construction to edit.
    EXPECT_EQ(w.history.execute(w.doc, edit_construction(w.profile, r)).error().path, "/id");
    EXPECT_EQ(w.history.execute(w.doc, detach(w.profile)).error().path, "/id");
}

TEST(Associative, ConstructRefusalsNameTheRecipesMembers) {
    Workshop w;
    Recipe r = Workshop::recipe(Construction::revolve, {w.profile, w.trajectory});
    EXPECT_EQ(w.history.execute(w.doc, construct(r)).error().path, "/construction/inputs");
    r.curves = {1}; // the default hill, a surface
    EXPECT_EQ(w.history.execute(w.doc, construct(r)).error().path, "/construction/inputs/0");
    r = Workshop::recipe(Construction::isocurve, {w.profile});
    EXPECT_EQ(w.history.execute(w.doc, construct(r)).error().path, "/construction/inputs/0");
    r.curves = {1};
    r.iso_t = 1.5;
    EXPECT_EQ(w.history.execute(w.doc, construct(r)).error().path, "/construction/param");
    EXPECT_FALSE(w.history.can_undo());
}

TEST(Associative, ConstructCommandsReplayFromJsonAndTheSceneKeepsRecipes) {
    Workshop w;
    const Document start = w.doc;
    Recipe skin = Workshop::recipe(Construction::skin, {w.profile, w.section2, w.section3});
    skin.parametrization = geom::Parametrization::centripetal;
    const std::uint64_t skinned = w.build(skin, "skin");
    const std::uint64_t vase =
        w.build(Workshop::recipe(Construction::revolve, {w.profile}), "vase");
    ASSERT_TRUE(w.history.execute(w.doc, insert_knot(vase, Dir::v, 0.3)).ok());
    Recipe rim = Workshop::recipe(Construction::isocurve, {vase});
    rim.iso_dir = Dir::v;
    rim.iso_t = 0.25;
    w.build(rim);
    ASSERT_TRUE(w.history.execute(w.doc, move_curve_point(w.profile, 2, {1.3, 0, 0.3})).ok());
    ASSERT_TRUE(w.history.execute(w.doc, detach(skinned)).ok());

    // The session as data, replayed through JSON on the starting document.
    std::vector<nlohmann::json> commands;
    History replay_history;
    Document replay = start;
    std::vector<const Command*> applied;
    while (w.history.can_undo()) w.history.undo(w.doc);
    EXPECT_TRUE(same_document(w.doc, start));
    while (w.history.can_redo()) {
        w.history.redo(w.doc);
        commands.push_back(scene::command_to_json(*w.history.top()->spec()));
    }
    for (const nlohmann::json& j : commands) {
        auto spec = scene::command_from_json(j);
        ASSERT_TRUE(spec.ok()) << j.dump() << ": " << spec.error().message;
        EXPECT_EQ(scene::command_to_json(*spec), j);
        ASSERT_TRUE(replay_history.execute(replay, make_command(*spec)).ok()) << j.dump();
    }
    EXPECT_TRUE(same_document(replay, w.doc));

    // Saved and loaded, the recipes come back (version 2), and the links still work.
    const std::string text = scene::scene_to_text(w.doc);
    EXPECT_NE(text.find("\"version\": 2"), std::string::npos);
    EXPECT_NE(text.find("\"construction\""), std::string::npos);
    auto loaded = scene::scene_from_text(text);
    ASSERT_TRUE(loaded.ok()) << loaded.error().message << " at " << loaded.error().path;
    EXPECT_TRUE(same_document(*loaded, w.doc));
    History h;
    ASSERT_TRUE(h.execute(*loaded, move_curve_point(w.profile, 6, {0.7, 0, 1.8})).ok());
    expect_fresh(*loaded, vase);
    EXPECT_FALSE(same_shape(loaded->find(vase)->shape, w.doc.find(vase)->shape));
    // A scene without constructions is still written as version 1.
    EXPECT_NE(scene::scene_to_text(start).find("\"version\": 1"), std::string::npos);
}

TEST(Associative, ScenesWithBrokenLinksAreRefusedWithTheirPath) {
    Workshop w;
    w.build(Workshop::recipe(Construction::revolve, {w.profile}), "vase");
    nlohmann::json j = scene::scene_to_json(w.doc);
    const std::size_t k = j["objects"].size() - 1;
    auto refused = [&](nlohmann::json scene, const std::string& path) {
        auto loaded = scene::scene_from_json(scene);
        ASSERT_FALSE(loaded.ok()) << path;
        EXPECT_EQ(loaded.error().path, path) << loaded.error().message;
    };
    nlohmann::json missing = j;
    missing["objects"][k]["construction"]["inputs"][0] = 77;
    refused(missing, "/objects/" + std::to_string(k) + "/construction/inputs/0");
    nlohmann::json itself = j;
    itself["objects"][k]["construction"]["inputs"][0] = itself["objects"][k]["id"];
    refused(itself, "/objects/" + std::to_string(k) + "/construction/inputs/0");
    nlohmann::json stray = j;
    stray["objects"][k]["construction"]["degree"] = 2;
    refused(stray, "/objects/" + std::to_string(k) + "/construction/degree");
    nlohmann::json old = j;
    old["version"] = 1;
    refused(old, "/objects/" + std::to_string(k) + "/construction");
}

} // namespace
