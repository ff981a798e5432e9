// The polygonized meshes of the document's implicit objects, cached per object by
// ImplicitKey: re-polygonized only when the expression, parameters, bounds or cell change.
// Fine grids run on a background std::jthread (cancelled when the object changes again);
// headless runs polygonize synchronously so renders are deterministic.
// Two meshes per object at most: its own (the panel shows it) and the one the 3D view draws
// when the view is far enough for a coarser grid (implicit_screen_level.hpp). An object the
// view draws coarser and nobody selected is never polygonized at its own cell.
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <unordered_map>

#include "core/doc/document.hpp"
#include "core/geom/tessellate.hpp"
#include "ui/view/implicit_support.hpp"

namespace isoparm::ui {

class ImplicitMeshes {
public:
    struct Mode {
        bool wait = false;           // polygonize synchronously (headless)
        std::uint64_t coarse_id = 0; // this object's parameter slider is moving: coarse grid
        // A gesture frame (an orbit, a drag on a CPU rasteriser): every object shows a mesh of
        // a coarse grid, made once beside the full one and kept until the object changes.
        bool gesture = false;
        std::function<void()> wake; // called from the worker when a mesh is ready
        // The level (implicit_screen_level.hpp) at which the 3D view draws each object; empty:
        // level 0, the object's own mesh, for all.
        std::function<int(const doc::ImplicitObject&)> screen_level;
        // This object's own mesh is made whatever the view needs (the selected one: its panel
        // tells its triangles).
        std::uint64_t own_mesh_id = 0;
    };
    // What the renderer and the panel see of one object.
    struct View {
        const geom::Mesh* mesh = nullptr; // the mesh shown (possibly of an older key)
        std::uint64_t revision = 0;       // changes whenever *mesh changes
        double progress = -1;             // of the running background job; < 0 none
        double cell = 0;                  // cell of the mesh shown
        std::string error;                // polygonization error of the current key
        // The mesh's side seen from outside its box (geom::implicit::side_seen_from_outside):
        // +1 / -1 for a closed mesh, 0 otherwise; and that box, the shown mesh's own (the
        // object's bounds may have changed while a new mesh is made).
        int seen_side = 0;
        glm::dvec3 lo{0.0}, hi{0.0};
    };

    ImplicitMeshes() = default;
    ~ImplicitMeshes();
    ImplicitMeshes(const ImplicitMeshes&) = delete;
    ImplicitMeshes& operator=(const ImplicitMeshes&) = delete;

    // Brings every visible implicit object up to date and drops objects no longer present.
    void update(const doc::Document& d, const Mode& mode);
    // The object's own mesh, of its own cell (or the slider's coarse one): what the panel tells.
    View view(std::uint64_t id) const;
    // The mesh the 3D view draws: of the level the last update was given (or the nearest there
    // is while that one is made), or of the coarse grid in a gesture frame.
    View drawn(std::uint64_t id) const;
    // After the gesture frame's scene is built: view() shows the full meshes again (panels).
    void end_gesture_frame() { gesture_ = false; }

    // Polygonizations run on the calling thread so far (coarse and headless ones).
    int synchronous_runs() const { return synchronous_runs_; }

private:
    struct Job {
        ImplicitKey key;
        std::atomic<double> progress{0};
        std::atomic<bool> done{false};
        std::mutex m;
        std::optional<geom::Mesh> mesh; // set when done without error
        std::string error;
        int seen_side = 0;
    };
    // One mesh of an object and the job making its next one.
    struct Slot {
        std::optional<ImplicitKey> shown; // key of `mesh` (or of `error`)
        geom::Mesh mesh;
        int seen_side = 0;
        std::uint64_t revision = 0;
        std::string error;
        std::shared_ptr<Job> job;
        std::jthread worker; // declared last: joined first on destruction
    };
    struct Entry {
        Slot own;    // the object's cell (the slider's coarse cell while it moves)
        Slot screen; // the cell the 3D view asked for, when coarser than the own one
        ImplicitKey own_key, screen_key; // what the last update wanted
        int level = 0;                   // the 3D view's level in the last update
        // The gesture frames' coarse mesh, of the key `gesture_key` (made on the first gesture).
        std::optional<ImplicitKey> gesture_key;
        geom::Mesh gesture_mesh;
        std::uint64_t gesture_revision = 0;
        bool used = false;
    };
    void update_gesture_mesh(Entry& e, const doc::ImplicitObject& im);
    // Shows `key`'s mesh in the slot: at once (synchronous), or from a finished job, or by
    // starting one (the slot keeps showing its older mesh meanwhile).
    void bring_up_to_date(Slot& s, const ImplicitKey& key, const Mode& mode);
    // Stops the slot's job when it works for another key than `key` (nobody waits for it).
    static void drop_stale_job(Slot& s, const ImplicitKey& key);
    void adopt(Slot& s, const ImplicitKey& key, std::optional<geom::Mesh> mesh, std::string error,
               int seen_side);
    View slot_view(const Slot& s) const;
    std::unordered_map<std::uint64_t, Entry> entries_;
    std::uint64_t next_revision_ = 1;
    int synchronous_runs_ = 0;
    bool gesture_ = false; // the last update's Mode::gesture
};

// Polygonizes one key; progress gets [0, 1] and returns false to cancel.
struct PolygonizeResult {
    std::optional<geom::Mesh> mesh;
    std::string error;
    int seen_side = 0; // geom::implicit::side_seen_from_outside
};
PolygonizeResult polygonize_key(const ImplicitKey& key,
                                const std::function<bool(double)>& progress = {});

} // namespace isoparm::ui
