// Scene files: indented text with exact numbers, reading with limits, atomic saving.
#include <algorithm>
#include <array>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <csignal>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <limits>
#include <string_view>
#include <sys/stat.h>
#include <sys/types.h>
#include <unistd.h>

#include "core/doc/json_read.hpp"
#include "core/doc/scene_io.hpp"

namespace isoparm::doc {

using nlohmann::json;

namespace {

// ---------------------------------------------------------------------------------------
// Writing.

// Shortest round-trip text of a double that still reads back as a float and keeps the sign
// of zero: "0.5", "1.0", "-0.0", "1e-05", "1.5e+300".
void write_double(std::string& out, double x) {
    if (!std::isfinite(x)) {
        out += "null"; // never happens for a valid document; never write invalid JSON
        return;
    }
    std::array<char, 64> buf{};
    const auto res = std::to_chars(buf.data(), buf.data() + buf.size(), x);
    const std::string_view s(buf.data(), static_cast<std::size_t>(res.ptr - buf.data()));
    out += s;
    if (s.find_first_of(".e") == std::string_view::npos) out += ".0";
}

void write_string(std::string& out, const std::string& s) {
    // Invalid UTF-8 cannot come from a loaded scene (the parser rejects it); anything else
    // is replaced rather than thrown on.
    out += json(s).dump(-1, ' ', false, json::error_handler_t::replace);
}

// Members in the order a reader looks for them; the rest alphabetically after.
constexpr std::array<std::string_view, 25> key_order = {
    "format",    "version",   "id",         "name",       "kind",  "visible", "plane",
    "knot_mode", "surface",   "curve",      "implicit",   "type",  "degree",  "knots",
    "points",    "weights",   "expression", "parameters", "value", "bounds",  "cell",
    "objects",   "selection", "indicator",  "display"};

int key_rank(const std::string& k) {
    for (std::size_t r = 0; r < key_order.size(); ++r)
        if (k == key_order[r]) return static_cast<int>(r);
    return static_cast<int>(key_order.size());
}

std::vector<std::pair<const std::string*, const json*>> ordered_members(const json& o) {
    std::vector<std::pair<const std::string*, const json*>> members;
    for (auto it = o.begin(); it != o.end(); ++it) members.emplace_back(&it.key(), &it.value());
    // Only scenes, objects and geometry get the reading order; colours and display settings
    // (whose names overlap it: "surface", "indicator") stay alphabetical.
    if (!o.contains("format") && !o.contains("kind") && !o.contains("type") &&
        !o.contains("expression") && !o.contains("name"))
        return members;
    std::stable_sort(members.begin(), members.end(), [](const auto& a, const auto& b) {
        return key_rank(*a.first) < key_rank(*b.first); // std::map order breaks ties
    });
    return members;
}

// Appends v on one line. With a `limit`, stops as soon as `out` is longer than that and
// returns false: write_pretty only asks whether a container fits on a line, and must not
// format a 100 MB surface in full at every level of nesting to find out it does not.
bool write_compact(std::string& out, const json& v,
                   std::size_t limit = std::numeric_limits<std::size_t>::max()) {
    switch (v.type()) {
    case json::value_t::object: {
        out += '{';
        bool first = true;
        for (const auto& [k, m] : ordered_members(v)) {
            if (!first) out += ", ";
            first = false;
            write_string(out, *k);
            out += ": ";
            if (!write_compact(out, *m, limit)) return false;
        }
        out += '}';
        break;
    }
    case json::value_t::array: {
        out += '[';
        for (std::size_t k = 0; k < v.size(); ++k) {
            if (k) out += ", ";
            if (!write_compact(out, v[k], limit)) return false;
        }
        out += ']';
        break;
    }
    case json::value_t::number_float:
        write_double(out, v.get<double>());
        break;
    case json::value_t::string:
        write_string(out, v.get_ref<const std::string&>());
        break;
    default:
        out += v.dump();
        break; // null, booleans, integers
    }
    return out.size() <= limit;
}

// Containers that fit on a line stay on one line; others get one member per line, so a
// surface reads row by row.
void write_pretty(std::string& out, const json& v, int indent) {
    constexpr std::size_t line_budget = 96;
    if (!v.is_structured() || v.empty()) {
        write_compact(out, v);
        return;
    }
    const auto used = static_cast<std::size_t>(indent);
    if (indent > 0 && used <= line_budget) {
        std::string compact;
        if (write_compact(compact, v, line_budget - used)) {
            out += compact;
            return;
        }
    }
    const std::string pad(static_cast<std::size_t>(indent + 2), ' ');
    if (v.is_object()) {
        out += "{\n";
        bool first = true;
        for (const auto& [k, m] : ordered_members(v)) {
            if (!first) out += ",\n";
            first = false;
            out += pad;
            write_string(out, *k);
            out += ": ";
            write_pretty(out, *m, indent + 2);
        }
        out += '\n' + std::string(static_cast<std::size_t>(indent), ' ') + '}';
    } else {
        out += "[\n";
        for (std::size_t k = 0; k < v.size(); ++k) {
            if (k) out += ",\n";
            out += pad;
            write_pretty(out, v[k], indent + 2);
        }
        out += '\n' + std::string(static_cast<std::size_t>(indent), ' ') + ']';
    }
}

// ---------------------------------------------------------------------------------------
// Files.

constexpr std::uintmax_t max_scene_bytes = 256u << 20;

geom::Error io_error(const std::string& what, const std::string& path, int err) {
    return geom::make_error_nopath(geom::ErrorCode::internal,
                                   "cannot " + what + " '" + path + "': " + std::strerror(err));
}

bool write_all(int fd, const std::string& text) {
    const char* p = text.data();
    std::size_t left = text.size();
    while (left > 0) {
        const ssize_t n = ::write(fd, p, left);
        if (n < 0) {
            if (errno == EINTR) continue;
            return false;
        }
        p += n;
        left -= static_cast<std::size_t>(n);
    }
    return true;
}

// Temporary files of saves that never finished ("<target>.tmp-<pid>" whose process no longer
// exists: it was killed, crashed or lost power mid-save) are removed before a new save, so
// they do not pile up beside the scene (each can be tens of MB). A temporary file whose
// process still runs, or might (kill says anything but ESRCH), is left alone: it may be a
// save in progress.
void remove_stale_temporaries(const std::string& target) {
    const std::filesystem::path t(target);
    const std::filesystem::path dir = t.parent_path().empty() ? "." : t.parent_path();
    const std::string prefix = t.filename().string() + ".tmp-";
    std::error_code ec;
    for (std::filesystem::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
        const std::string name = it->path().filename().string();
        if (name.size() <= prefix.size() || name.compare(0, prefix.size(), prefix) != 0) continue;
        long pid = 0;
        const char* first = name.data() + prefix.size();
        const char* last = name.data() + name.size();
        const auto res = std::from_chars(first, last, pid);
        if (res.ec != std::errc() || res.ptr != last || pid <= 0 || pid == ::getpid() ||
            pid != static_cast<pid_t>(pid))
            continue;
        if (::kill(static_cast<pid_t>(pid), 0) == 0 || errno != ESRCH) continue;
        (void)::unlink(it->path().c_str());
    }
}

} // namespace

std::string scene_to_text(const Document& doc) {
    std::string out;
    write_pretty(out, scene_to_json(doc), 0);
    out += '\n';
    return out;
}

geom::Expected<Document> load_scene(const std::string& path) {
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) return io_error("open", path, errno);
    struct stat st {};
    if (::fstat(fd, &st) != 0) {
        const int err = errno;
        ::close(fd);
        return io_error("read", path, err);
    }
    if (!S_ISREG(st.st_mode)) {
        ::close(fd);
        return io_error("read", path, S_ISDIR(st.st_mode) ? EISDIR : EINVAL);
    }
    if (static_cast<std::uintmax_t>(st.st_size) > max_scene_bytes) {
        ::close(fd);
        return geom::make_error_nopath(geom::ErrorCode::limit,
                                       "'" + path + "' is " + std::to_string(st.st_size >> 20) +
                                           " MiB; scenes may be at most 256 MiB");
    }
    std::string text;
    text.reserve(static_cast<std::size_t>(st.st_size));
    char buf[1 << 16];
    for (;;) {
        const ssize_t n = ::read(fd, buf, sizeof buf);
        if (n < 0) {
            if (errno == EINTR) continue;
            const int err = errno;
            ::close(fd);
            return io_error("read", path, err);
        }
        if (n == 0) break;
        text.append(buf, static_cast<std::size_t>(n));
        if (text.size() > max_scene_bytes) { // the file grew while we read it
            ::close(fd);
            return geom::make_error_nopath(geom::ErrorCode::limit,
                                           "'" + path + "' is larger than 256 MiB");
        }
    }
    ::close(fd);
    auto doc = scene_from_text(text);
    if (!doc && !doc.error().has_path && doc.error().code == geom::ErrorCode::parse) {
        geom::Error e = doc.error();
        e.message = "'" + path + "' is not JSON: " + e.message;
        return e;
    }
    return doc;
}

geom::Status save_scene(const Document& doc, const std::string& path) {
    // Replace the file a symbolic link points to, not the link.
    std::string target = path;
    std::error_code ec;
    if (std::filesystem::is_symlink(path, ec)) {
        const auto resolved = std::filesystem::weakly_canonical(path, ec);
        if (ec) return io_error("resolve", path, ec.value());
        target = resolved.string();
    }
    const std::string tmp = target + ".tmp-" + std::to_string(::getpid());
    // Before the (possibly long) formatting, so a save killed early leaves nothing behind.
    remove_stale_temporaries(target);
    const std::string text = scene_to_text(doc);

    const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
    if (fd < 0) return io_error("create", tmp, errno);
    auto fail = [&](const char* what, const std::string& name, int err) -> geom::Status {
        ::unlink(tmp.c_str());
        return io_error(what, name, err);
    };
    // Keep the permissions of the file being replaced.
    struct stat old_stat {};
    if (::stat(target.c_str(), &old_stat) == 0 && S_ISREG(old_stat.st_mode))
        (void)::fchmod(fd, old_stat.st_mode & 07777);
    if (!write_all(fd, text)) {
        const int err = errno;
        ::close(fd);
        return fail("write", tmp, err);
    }
    // The data must be on disk before the rename makes it the scene.
    if (::fsync(fd) != 0) {
        const int err = errno;
        ::close(fd);
        return fail("flush", tmp, err);
    }
    if (::close(fd) != 0) return fail("close", tmp, errno);
    if (::rename(tmp.c_str(), target.c_str()) != 0) return fail("replace", target, errno);
    // Make the rename itself durable (best effort: some file systems refuse to sync a
    // directory, and the scene is already complete either way).
    const std::string dir = std::filesystem::path(target).parent_path().string();
    const int dfd = ::open(dir.empty() ? "." : dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (dfd >= 0) {
        (void)::fsync(dfd);
        ::close(dfd);
    }
    return geom::Ok{};
}

} // namespace isoparm::doc
