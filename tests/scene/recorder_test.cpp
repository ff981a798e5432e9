// Recording: a seeded monkey session (drags that merge, refinements, splits with continuity,
// curve edits, undo and redo, view changes) recorded and replayed on its starting scene gives
// the same scene, byte for byte.
#include <gtest/gtest.h>

#include <random>

#include "core/doc/commands.hpp"
#include "core/doc/commands_curve.hpp"
#include "core/scene/recorder.hpp"
#include "core/scene/scene_io.hpp"
#include "core/scene/script.hpp"
#include "tests/doc/doc_fixtures.hpp"

using namespace isoparm;
using namespace isoparm::doc;
using nlohmann::json;

namespace {

struct Session {
    Document doc;
    History history;
    scene::Recorder recorder;
    explicit Session(Document start) : doc(std::move(start)), recorder(doc) {}

    void run(std::unique_ptr<Command> cmd) {
        recorder.observe(doc);
        if (history.execute(doc, std::move(cmd))) recorder.executed(history, doc);
    }
};

// A random point of a random surface or curve: (id, i, j), j = -1 for curves.
std::optional<std::tuple<std::uint64_t, int, int>> random_point(const Document& d,
                                                                std::mt19937& rng) {
    std::vector<const Object*> editable;
    for (const Object& o : d.objects)
        if (o.surface() || o.curve()) editable.push_back(&o);
    if (editable.empty()) return std::nullopt;
    const Object& o = *editable[rng() % editable.size()];
    if (const geom::Surface* s = o.surface())
        return std::tuple{o.id, static_cast<int>(rng() % s->n_u), static_cast<int>(rng() % s->n_v)};
    return std::tuple{o.id, static_cast<int>(rng() % o.curve()->count()), -1};
}

double uniform(std::mt19937& rng, double lo, double hi) {
    return std::uniform_real_distribution<double>(lo, hi)(rng);
}

void monkey(Session& s, std::mt19937& rng, int actions) {
    for (int n = 0; n < actions; ++n) {
        s.history.seal();
        const int what = static_cast<int>(rng() % 14);
        const auto point = random_point(s.doc, rng);
        if (!point) break;
        const auto [id, i, j] = *point;
        switch (what) {
        case 0:
        case 1: { // a drag: several moves of one point, one undo step
            glm::dvec3 p(uniform(rng, -2, 2), uniform(rng, -2, 2), uniform(rng, -1, 2));
            const int moves = 1 + static_cast<int>(rng() % 5);
            for (int m = 0; m < moves; ++m) {
                p.z += 0.1;
                s.run(move_control_point(id, i, j, p));
                s.recorder.observe(s.doc);
            }
            break;
        }
        case 2: // a weight slider drag (refused on non-rational objects: nothing recorded)
            for (double w : {0.5, 1.5, uniform(rng, -1, 4)}) s.run(set_weight(id, i, j, w));
            break;
        case 3:
            s.run(insert_knot(id, j < 0 || rng() % 2 ? geom::Dir::u : geom::Dir::v,
                              uniform(rng, 0.05, 0.95)));
            break;
        case 4:
            if (rng() % 4 == 0) s.run(elevate_degree(id, j < 0 ? geom::Dir::u : geom::Dir::v));
            break;
        case 5:
            if (s.doc.objects.size() < 8)
                s.run(split_object(id, j < 0 || rng() % 2 ? geom::Dir::u : geom::Dir::v,
                                   uniform(rng, 0.2, 0.8)));
            break;
        case 6:
            s.recorder.observe(s.doc);
            if (s.history.undo(s.doc)) s.recorder.undone(s.doc);
            break;
        case 7:
            s.recorder.observe(s.doc);
            if (s.history.redo(s.doc)) s.recorder.redone(s.doc);
            break;
        case 8: // selected, and observed only at the next command (the same frame)
            s.doc.view.selection = {id, i, j};
            break;
        case 9: // the indicator dragged across the square: one step, its final position
            for (int m = 0; m < 4; ++m) {
                s.doc.view.indicator = {uniform(rng, 0, 1), uniform(rng, 0, 1)};
                s.recorder.observe(s.doc);
            }
            break;
        case 10: {
            s.doc.view.display.knot_curves = !s.doc.view.display.knot_curves;
            // An object's own toggle (C with it selected), recorded for that object alone.
            ObjectDisplay& own =
                s.doc.view.object_display.try_emplace(id, defaults_of(s.doc.view.display))
                    .first->second;
            own.control_points = !own.control_points;
            s.doc.continuity = static_cast<Continuity>(rng() % 3);
            s.recorder.observe(s.doc, std::pair{uniform(rng, -180, 180), uniform(rng, -80, 80)});
            break;
        }
        case 11:
            if (j < 0)
                s.run(insert_curve_point(id, i, {uniform(rng, -1, 1), uniform(rng, -1, 1), 0}));
            break;
        case 12:
            if (j < 0) s.run(delete_curve_point(id, i));
            break;
        default:
            s.run(rename_object(id, "o" + std::to_string(rng() % 100)));
            break;
        }
    }
}

TEST(Recorder, AMonkeySessionReplaysToTheSameSceneByteForByte) {
    for (unsigned seed = 1; seed <= 12; ++seed) {
        Document start = doc::testing::sample_document();
        start.objects.pop_back(); // the implicit: no points to pick
        // The curve's knot mode follows the polygon, so point edits recompute its knots.
        start.objects[1].curve_object()->knot_mode = CurveKnotMode::chord;
        Session s(start);
        std::mt19937 rng(seed);
        monkey(s, rng, 250);
        s.recorder.observe(s.doc); // the window observes once a frame
        const json recorded = s.recorder.script();
        EXPECT_GT(s.recorder.step_count(), 50u) << seed;
        EXPECT_EQ(s.recorder.left_out(), 0u);

        // Through text, as a saved recording is read back.
        auto parsed = json::parse(scene::pretty_json_text(recorded));
        auto script = scene::script_from_json(parsed, ".");
        ASSERT_TRUE(script.ok()) << seed << ": " << script.error().message << " at "
                                 << script.error().path;
        scene::ScriptState replay(script->start);
        const scene::ScriptResult r = scene::run_script(*script, replay, {});
        ASSERT_FALSE(r.stopped) << seed << ": " << r.stopped->message << " at " << r.stopped->path;
        EXPECT_EQ(scene::scene_to_text(replay.doc), scene::scene_to_text(s.doc)) << seed;

        EXPECT_EQ(replay.history.size(), s.history.size()) << seed;
    }
}

TEST(Recorder, ADragIsOneStepWithItsFinalValue) {
    Session s(default_document());
    for (double z : {1.0, 1.5, 2.0}) s.run(move_control_point(1, 2, 2, {0, 0, z}));
    s.history.seal();
    s.run(move_control_point(1, 2, 2, {0, 0, 3}));
    const json steps = s.recorder.script().at("steps");
    ASSERT_EQ(steps.size(), 2u);
    EXPECT_EQ(steps[0].at("position"), json::parse("[0.0, 0.0, 2.0]"));
    EXPECT_EQ(steps[1].at("position"), json::parse("[0.0, 0.0, 3.0]"));
}

} // namespace
