// The implicit mesh cache: synchronous coarse and headless polygonization, background jobs
// with progress and cancel-on-change for fine grids.
#include "ui/view/implicit_meshes.hpp"

#include <algorithm>
#include <cmath>

#include "core/geom/implicit/expression.hpp"
#include "core/geom/implicit/polygonize.hpp"
#include "ui/view/implicit_screen_level.hpp"

namespace isoparm::ui {

namespace {

// Grids up to this many cells polygonize on the UI thread (a few milliseconds).
constexpr double synchronous_cells = 48.0 * 48.0 * 48.0;

// Whether two keys are of the same surface (expression, parameters, bounds), whatever their cells.
bool same_surface(ImplicitKey a, const ImplicitKey& b) {
    a.cell = b.cell;
    return a == b;
}

double grid_cells(const ImplicitKey& k) {
    const glm::dvec3 e = k.hi - k.lo;
    return std::ceil(e.x / k.cell) * std::ceil(e.y / k.cell) * std::ceil(e.z / k.cell);
}

} // namespace

PolygonizeResult polygonize_key(const ImplicitKey& key,
                                const std::function<bool(double)>& progress) {
    PolygonizeResult r;
    auto program = geom::implicit::compile(key.expression, key.names);
    if (!program) {
        r.error = program.error().message;
        return r;
    }
    geom::implicit::PolygonizeOptions opt;
    opt.lo = key.lo;
    opt.hi = key.hi;
    opt.cell = key.cell;
    opt.parameters = key.values;
    opt.progress = progress;
    auto mesh = geom::implicit::polygonize(*program, opt);
    if (!mesh) {
        r.error = mesh.error().message;
        return r;
    }
    if (mesh->triangles.empty()) r.error = "the surface was not found in the bounds";
    r.seen_side = geom::implicit::side_seen_from_outside(*program, opt, *mesh);
    r.mesh = std::move(*mesh);
    return r;
}

ImplicitMeshes::~ImplicitMeshes() {
    // Ask every worker to stop before joining any of them.
    for (auto& [id, e] : entries_) {
        e.own.worker.request_stop();
        e.screen.worker.request_stop();
    }
}

void ImplicitMeshes::adopt(Slot& s, const ImplicitKey& key, std::optional<geom::Mesh> mesh,
                           std::string error, int seen_side) {
    s.shown = key;
    s.seen_side = mesh ? seen_side : 0;
    s.error = std::move(error);
    s.mesh = mesh ? std::move(*mesh) : geom::Mesh{};
    s.revision = next_revision_++;
}

// The coarse grid's mesh of the object as it is now; nothing when its full grid is no finer.
void ImplicitMeshes::update_gesture_mesh(Entry& e, const doc::ImplicitObject& im) {
    // The slider's coarse grid, and never finer than 2.5 cells: an orbit of the implicit
    // gallery on llvmpipe is bound by its triangles (2x: 42 ms a frame, over the 40 ms aimed at).
    if (!(im.cell > 0)) return;
    const double least = std::max(coarse_cell(im.lo, im.hi, im.cell), 2.5 * im.cell);
    // It stays until the object changes (a new one costs the frame that makes it): made in the
    // first gesture frame, twice as coarse as the view's mesh then when that is coarser still.
    if (e.gesture_key && e.gesture_key->cell >= least &&
        same_surface(implicit_key(im, least), *e.gesture_key))
        return;
    const double cell = std::max(least, std::ldexp(im.cell, e.level + 1));
    const ImplicitKey key = implicit_key(im, cell);
    e.gesture_key = key;
    e.gesture_mesh = {};
    e.gesture_revision = 0;
    PolygonizeResult r = polygonize_key(key);
    ++synchronous_runs_;
    if (!r.mesh || !r.error.empty()) return; // the full mesh (or its error) is shown
    e.gesture_mesh = std::move(*r.mesh);
    e.gesture_revision = next_revision_++;
}

void ImplicitMeshes::drop_stale_job(Slot& s, const ImplicitKey& key) {
    if (s.job && !(s.job->key == key)) {
        s.worker = {}; // requests stop and joins
        s.job.reset();
    }
}

void ImplicitMeshes::bring_up_to_date(Slot& s, const ImplicitKey& key, const Mode& mode) {
    // A finished job: show its mesh if it is still wanted.
    if (s.job && s.job->done.load()) {
        std::shared_ptr<Job> job = std::move(s.job);
        s.worker = {};
        if (job->key == key) {
            std::lock_guard lock(job->m);
            adopt(s, key, std::move(job->mesh), job->error, job->seen_side);
        }
    }
    if (s.shown && *s.shown == key) {
        drop_stale_job(s, key);
        return;
    }
    if (s.job && s.job->key == key) return; // still running

    s.worker = {}; // cancel a job for another key
    s.job.reset();
    if (mode.wait || grid_cells(key) <= synchronous_cells || !(key.cell > 0)) {
        PolygonizeResult r = polygonize_key(key);
        ++synchronous_runs_;
        adopt(s, key, std::move(r.mesh), std::move(r.error), r.seen_side);
        return;
    }
    auto job = std::make_shared<Job>();
    job->key = key;
    s.job = job;
    s.worker = std::jthread([job, wake = mode.wake](std::stop_token stop) {
        PolygonizeResult r = polygonize_key(job->key, [&](double p) {
            job->progress.store(p);
            return !stop.stop_requested();
        });
        {
            std::lock_guard lock(job->m);
            job->mesh = std::move(r.mesh);
            job->error = std::move(r.error);
            job->seen_side = r.seen_side;
        }
        job->done.store(true);
        if (wake && !stop.stop_requested()) wake();
    });
}

void ImplicitMeshes::update(const doc::Document& d, const Mode& mode) {
    gesture_ = mode.gesture;
    for (auto& [id, e] : entries_) e.used = false;
    for (const doc::Object& o : d.objects) {
        const doc::ImplicitObject* im = o.implicit();
        if (!im || !o.visible) continue;
        Entry& e = entries_[o.id];
        e.used = true;
        const bool sliding = o.id == mode.coarse_id;
        e.own_key = implicit_key(*im, sliding ? coarse_cell(im->lo, im->hi, im->cell) : im->cell);
        // A slider's coarse grid is drawn as it is (made anew with each step).
        e.level = sliding || !mode.screen_level || !(im->cell > 0)
                      ? 0
                      : std::clamp(mode.screen_level(*im), 0, max_screen_level);
        if (mode.gesture && !sliding) update_gesture_mesh(e, *im);
        if (e.level == 0 || o.id == mode.own_mesh_id)
            bring_up_to_date(e.own, e.own_key, mode);
        else
            drop_stale_job(e.own, e.own_key);
        e.screen_key = implicit_key(*im, std::ldexp(im->cell, e.level));
        if (e.level > 0)
            bring_up_to_date(e.screen, e.screen_key, mode);
        else
            drop_stale_job(e.screen, e.screen_key);
    }
    for (auto it = entries_.begin(); it != entries_.end();)
        it = it->second.used ? std::next(it) : entries_.erase(it);
}

ImplicitMeshes::View ImplicitMeshes::slot_view(const Slot& s) const {
    View v;
    if (s.shown) {
        v.mesh = &s.mesh;
        v.cell = s.shown->cell;
        v.seen_side = s.seen_side;
        v.lo = s.shown->lo;
        v.hi = s.shown->hi;
    }
    v.revision = s.revision;
    v.error = s.error;
    if (s.job && !s.job->done.load()) v.progress = s.job->progress.load();
    return v;
}

ImplicitMeshes::View ImplicitMeshes::view(std::uint64_t id) const {
    const auto it = entries_.find(id);
    return it == entries_.end() ? View{} : slot_view(it->second.own);
}

ImplicitMeshes::View ImplicitMeshes::drawn(std::uint64_t id) const {
    const auto it = entries_.find(id);
    if (it == entries_.end()) return View{};
    const Entry& e = it->second;
    const Slot& wanted = e.level == 0 ? e.own : e.screen;
    const Slot& other = e.level == 0 ? e.screen : e.own;
    const ImplicitKey& key = e.level == 0 ? e.own_key : e.screen_key;
    // While the level's mesh is made: the other one if it shows the object as it is (at
    // another cell), else whichever there is, older.
    const bool wanted_current = wanted.shown && *wanted.shown == key;
    const bool other_same = other.shown && same_surface(key, *other.shown);
    const Slot& chosen = !wanted_current && (other_same || !wanted.shown) ? other : wanted;
    View v = slot_view(chosen);
    // A gesture frame shows the coarse mesh when there is one, coarser than the mesh chosen
    // above and of the same object as it.
    if (gesture_ && e.gesture_revision != 0 && e.gesture_key && e.gesture_key->cell > v.cell &&
        chosen.shown && same_surface(*e.gesture_key, *chosen.shown)) {
        v.mesh = &e.gesture_mesh;
        v.cell = e.gesture_key->cell;
        v.revision = e.gesture_revision;
    }
    return v;
}

} // namespace isoparm::ui
