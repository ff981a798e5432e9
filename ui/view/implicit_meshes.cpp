// The implicit mesh cache: synchronous coarse and headless polygonization, background jobs
// with progress and cancel-on-change for fine grids.
#include "ui/view/implicit_meshes.hpp"

#include <algorithm>
#include <cmath>

#include "core/geom/implicit/expression.hpp"
#include "core/geom/implicit/polygonize.hpp"

namespace isoparm::ui {

namespace {

// Grids up to this many cells polygonize on the UI thread (a few milliseconds).
constexpr double synchronous_cells = 48.0 * 48.0 * 48.0;

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
    for (auto& [id, e] : entries_) e.worker.request_stop();
}

void ImplicitMeshes::adopt(Entry& e, const ImplicitKey& key, std::optional<geom::Mesh> mesh,
                           std::string error, int seen_side) {
    e.shown = key;
    e.seen_side = mesh ? seen_side : 0;
    e.error = std::move(error);
    e.mesh = mesh ? std::move(*mesh) : geom::Mesh{};
    e.revision = next_revision_++;
}

// The coarse grid's mesh of the object as it is now; nothing when its full grid is no finer.
void ImplicitMeshes::update_gesture_mesh(Entry& e, const doc::ImplicitObject& im) {
    // The slider's coarse grid, and never finer than 2.5 cells: an orbit of the implicit
    // gallery on llvmpipe is bound by its triangles (2x: 42 ms a frame, over the 40 ms aimed at).
    const double cell =
        im.cell > 0 ? std::max(coarse_cell(im.lo, im.hi, im.cell), 2.5 * im.cell) : im.cell;
    const ImplicitKey key = implicit_key(im, cell);
    if (e.gesture_key && *e.gesture_key == key) return;
    e.gesture_key = key;
    e.gesture_mesh = {};
    e.gesture_revision = 0;
    if (!(cell > im.cell)) return; // the full mesh is as coarse
    PolygonizeResult r = polygonize_key(key);
    ++synchronous_runs_;
    if (!r.mesh || !r.error.empty()) return; // the full mesh (or its error) is shown
    e.gesture_mesh = std::move(*r.mesh);
    e.gesture_revision = next_revision_++;
}

void ImplicitMeshes::update(const doc::Document& d, const Mode& mode) {
    gesture_ = mode.gesture;
    for (auto& [id, e] : entries_) e.used = false;
    for (const doc::Object& o : d.objects) {
        const doc::ImplicitObject* im = o.implicit();
        if (!im || !o.visible) continue;
        Entry& e = entries_[o.id];
        e.used = true;
        const double cell =
            o.id == mode.coarse_id ? coarse_cell(im->lo, im->hi, im->cell) : im->cell;
        const ImplicitKey key = implicit_key(*im, cell);
        if (mode.gesture && o.id != mode.coarse_id) update_gesture_mesh(e, *im);

        // A finished job: show its mesh if it is still wanted.
        if (e.job && e.job->done.load()) {
            std::shared_ptr<Job> job = std::move(e.job);
            e.worker = {};
            if (job->key == key) {
                std::lock_guard lock(job->m);
                adopt(e, key, std::move(job->mesh), job->error, job->seen_side);
            }
        }
        if (e.shown && *e.shown == key) {
            if (e.job) {       // a job for an older key: no longer wanted
                e.worker = {}; // requests stop and joins
                e.job.reset();
            }
            continue;
        }
        if (e.job && e.job->key == key) continue; // still running

        e.worker = {}; // cancel a job for another key
        e.job.reset();
        if (mode.wait || grid_cells(key) <= synchronous_cells || !(key.cell > 0)) {
            PolygonizeResult r = polygonize_key(key);
            ++synchronous_runs_;
            adopt(e, key, std::move(r.mesh), std::move(r.error), r.seen_side);
            continue;
        }
        auto job = std::make_shared<Job>();
        job->key = key;
        e.job = job;
        e.worker = std::jthread([job, wake = mode.wake](std::stop_token stop) {
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
    for (auto it = entries_.begin(); it != entries_.end();)
        it = it->second.used ? std::next(it) : entries_.erase(it);
}

ImplicitMeshes::View ImplicitMeshes::view(std::uint64_t id) const {
    View v;
    const auto it = entries_.find(id);
    if (it == entries_.end()) return v;
    const Entry& e = it->second;
    if (e.shown) {
        v.mesh = &e.mesh;
        v.cell = e.shown->cell;
        v.seen_side = e.seen_side;
        v.lo = e.shown->lo;
        v.hi = e.shown->hi;
    }
    v.revision = e.revision;
    v.error = e.error;
    // A gesture frame shows the coarse mesh when there is one and the full one is current.
    const auto same_object = [&] {
        ImplicitKey k = *e.gesture_key;
        k.cell = e.shown->cell;
        return k == *e.shown;
    };
    if (gesture_ && e.gesture_revision != 0 && e.shown && e.gesture_key && same_object()) {
        v.mesh = &e.gesture_mesh;
        v.cell = e.gesture_key->cell;
        v.revision = e.gesture_revision;
    }
    if (e.job && !e.job->done.load()) v.progress = e.job->progress.load();
    return v;
}

} // namespace isoparm::ui
