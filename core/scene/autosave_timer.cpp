// The autosave policy: one check per interval, writes only of changed unsaved documents,
// discards once the work is safe.
#include "core/scene/autosave_timer.hpp"

#include "core/scene/scene_io.hpp"

namespace isoparm::scene {

using namespace isoparm::doc;

std::uint64_t document_fingerprint(const Document& doc) {
    // 64-bit FNV-1a (Fowler, Noll, Vo): stable across runs, unlike std::hash.
    std::uint64_t h = 14695981039346656037ull;
    for (const unsigned char c : scene_to_text(doc)) {
        h ^= c;
        h *= 1099511628211ull;
    }
    return h;
}

AutosaveTimer::AutosaveTimer(Clock::time_point start, Clock::duration interval)
    : next_check_(start + interval), interval_(interval) {}

AutosaveTimer::Step AutosaveTimer::poll(Clock::time_point now, bool dirty, const std::string& path,
                                        const std::function<std::uint64_t()>& fingerprint) {
    if (written_path_ && (!dirty || *written_path_ != path)) {
        Step s{Step::Kind::discard, *written_path_, 0};
        written_path_.reset();
        return s;
    }
    if (now < next_check_) return {};
    next_check_ = now + interval_;
    if (!dirty || held(path)) return {};
    const std::uint64_t fp = fingerprint();
    if (written_path_ && *written_path_ == path && written_fingerprint_ == fp) return {};
    return {Step::Kind::write, path, fp};
}

void AutosaveTimer::wrote(const std::string& path, std::uint64_t fingerprint) {
    written_path_ = path;
    written_fingerprint_ = fingerprint;
}

void AutosaveTimer::hold(const std::string& path) {
    held_.insert(path);
    if (written_path_ == path) written_path_.reset();
}

} // namespace isoparm::scene
