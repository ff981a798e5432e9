// Recovery files: a per-user state directory, names derived from the scene's path, atomic
// writes through save_scene.
#include "core/scene/autosave.hpp"

#include <algorithm>
#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <sys/stat.h>
#include <unistd.h>

#include "core/scene/scene_io.hpp"

namespace isoparm::scene {

using namespace isoparm::doc;

namespace fs = std::filesystem;

namespace {

geom::Error io_error(const std::string& what, const std::string& path, int err) {
    return geom::make_error_nopath(geom::ErrorCode::internal,
                                   "cannot " + what + " '" + path + "': " + std::strerror(err));
}

// 64-bit FNV-1a: a stable (across runs and builds, unlike std::hash) name for a path.
std::uint64_t fnv1a(const std::string& s) {
    std::uint64_t h = 14695981039346656037ull;
    for (const unsigned char c : s) {
        h ^= c;
        h *= 1099511628211ull;
    }
    return h;
}

// The scene's file name as a safe, short part of a file name: ASCII letters, digits, '-',
// '_' and '.', anything else as '_', at most 64 bytes.
std::string name_part(const fs::path& scene) {
    std::string out;
    for (const unsigned char c : scene.filename().string()) {
        if (out.size() == 64) break;
        const bool safe = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') ||
                          (c >= '0' && c <= '9') || c == '-' || c == '_' || c == '.';
        out += safe ? static_cast<char>(c) : '_';
    }
    return out.empty() || out == "." || out == ".." ? "scene" : out;
}

std::chrono::system_clock::time_point modified(const struct stat& st) {
    using namespace std::chrono;
    return system_clock::time_point(duration_cast<system_clock::duration>(
        seconds(st.st_mtim.tv_sec) + nanoseconds(st.st_mtim.tv_nsec)));
}

} // namespace

geom::Expected<std::string> recovery_directory() {
    const char* state = std::getenv("XDG_STATE_HOME");
    // The XDG specification ignores relative values.
    if (state && state[0] == '/') return (fs::path(state) / "isoparm").string();
    const char* home = std::getenv("HOME");
    if (home && home[0] != '\0') return (fs::path(home) / ".local" / "state" / "isoparm").string();
    return geom::make_error_nopath(geom::ErrorCode::internal,
                                   "cannot place the recovery file: neither XDG_STATE_HOME nor "
                                   "HOME is set");
}

std::string normalized_scene_path(const std::string& path) {
    if (path.empty()) return path;
    std::error_code ec;
    const fs::path absolute = fs::absolute(path, ec);
    return ec ? path : absolute.lexically_normal().string();
}

geom::Expected<std::string> recovery_path(const std::string& for_path) {
    auto dir = recovery_directory();
    if (!dir) return dir.error();
    if (for_path.empty()) return (fs::path(*dir) / "untitled.recovery.json").string();
    std::error_code ec;
    fs::path absolute = fs::absolute(for_path, ec);
    if (ec) return io_error("locate", for_path, ec.value());
    absolute = absolute.lexically_normal();
    char hash[17];
    std::snprintf(hash, sizeof hash, "%016llx",
                  static_cast<unsigned long long>(fnv1a(absolute.string())));
    return (fs::path(*dir) / (name_part(absolute) + "-" + hash + ".recovery.json")).string();
}

geom::Status write_recovery(const Document& doc, const std::string& for_path) {
    auto path = recovery_path(for_path);
    if (!path) return path.error();
    const fs::path dir = fs::path(*path).parent_path();
    std::error_code ec;
    if (!fs::is_directory(dir, ec)) {
        fs::create_directories(dir, ec);
        if (ec) return io_error("create the recovery directory", dir.string(), ec.value());
        // Unsaved work is private: only the user reads it (XDG: state directories are 0700).
        fs::permissions(dir, fs::perms::owner_all, fs::perm_options::replace, ec);
    }
    return save_scene(doc, *path);
}

std::optional<RecoveryInfo> find_recovery(const std::string& for_path) {
    auto path = recovery_path(for_path);
    if (!path) return std::nullopt;
    struct stat st {};
    if (::stat(path->c_str(), &st) != 0 || !S_ISREG(st.st_mode)) return std::nullopt;
    RecoveryInfo info;
    info.path = *path;
    info.origin = for_path;
    info.written = modified(st);
    struct stat scene {};
    if (!for_path.empty() && ::stat(for_path.c_str(), &scene) == 0)
        info.older_than_scene = modified(scene) > info.written;
    return info;
}

std::vector<RecoveryInfo> find_recoveries(const std::vector<std::string>& candidates) {
    std::vector<RecoveryInfo> out;
    for (const std::string& c : candidates) {
        std::optional<RecoveryInfo> r = find_recovery(c);
        if (!r) continue;
        const bool seen = std::any_of(out.begin(), out.end(),
                                      [&](const RecoveryInfo& o) { return o.path == r->path; });
        if (!seen) out.push_back(std::move(*r));
    }
    std::stable_sort(out.begin(), out.end(), [](const RecoveryInfo& a, const RecoveryInfo& b) {
        return a.written > b.written;
    });
    return out;
}

geom::Status discard_recovery(const std::string& for_path) {
    auto path = recovery_path(for_path);
    if (!path) return path.error();
    // unlink, not remove: a directory in the recovery file's place is not ours to delete.
    if (::unlink(path->c_str()) != 0 && errno != ENOENT) return io_error("remove", *path, errno);
    return geom::Ok{};
}

} // namespace isoparm::scene
