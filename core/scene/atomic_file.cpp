// Atomic, checked file output (see atomic_file.hpp for the rules and why).
#include "core/scene/atomic_file.hpp"
#include "core/json/input_file.hpp"

#include <cerrno>
#include <charconv>
#include <climits>
#include <csignal>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <optional>
#include <sys/stat.h>
#include <sys/types.h>
#include <unistd.h>

namespace isoparm::scene {

using namespace isoparm::json_io;

namespace {

namespace fs = std::filesystem;

geom::Error io_error(const std::string& what, const std::string& path, int err) {
    return geom::make_error_nopath(geom::ErrorCode::internal,
                                   "cannot " + what + " '" + path + "': " + std::strerror(err));
}

geom::Error not_regular(const std::string& path, mode_t mode) {
    return geom::make_error_nopath(geom::ErrorCode::internal,
                                   "cannot write '" + path + "': it is " + file_kind_name(mode) +
                                       "; only regular files (or '-' for standard output) "
                                       "are written");
}

// Closes a descriptor when it goes out of scope.
class Fd {
public:
    explicit Fd(int fd = -1) : fd_(fd) {}
    Fd(const Fd&) = delete;
    Fd& operator=(const Fd&) = delete;
    ~Fd() {
        if (fd_ >= 0) ::close(fd_);
    }
    int get() const { return fd_; }
    // Closes now and reports the result (close can report a failed delayed write).
    int close_checked() {
        const int r = ::close(fd_);
        fd_ = -1;
        return r;
    }

private:
    int fd_;
};

// Where the bytes finally go: the path to rename over, and the file it replaces (if any).
struct Target {
    std::string path;
    std::optional<struct stat> existing;
};

// The real name of the file behind an open descriptor, as the kernel resolved it.
geom::Expected<std::string> name_of_open_file(int fd, const std::string& shown) {
    const std::string link = "/proc/self/fd/" + std::to_string(fd);
    std::string buf(PATH_MAX, '\0');
    const ssize_t n = ::readlink(link.c_str(), buf.data(), buf.size());
    if (n < 0 || static_cast<std::size_t>(n) >= buf.size())
        return io_error("find the file behind the link", shown, n < 0 ? errno : ENAMETOOLONG);
    buf.resize(static_cast<std::size_t>(n));
    return buf;
}

// Decides what writing `path` replaces, without following any link itself.
geom::Expected<Target> resolve_target(const std::string& path) {
    if (path.empty()) return io_error("write", path, ENOENT);
    struct stat st {};
    if (::lstat(path.c_str(), &st) != 0) {
        if (errno == ENOENT) return Target{path, std::nullopt};
        return io_error("write", path, errno);
    }
    if (S_ISREG(st.st_mode)) return Target{path, st};
    if (!S_ISLNK(st.st_mode)) return not_regular(path, st.st_mode);

    // A symbolic link: let the kernel follow it (O_PATH needs no permission on the file, but
    // the kernel's link rules apply), then replace the file it actually opened.
    Fd fd(::open(path.c_str(), O_PATH | O_CLOEXEC));
    if (fd.get() < 0) {
        if (errno == ENOENT)
            return geom::make_error_nopath(geom::ErrorCode::internal,
                                           "cannot write '" + path +
                                               "': it is a symbolic link to a file that does "
                                               "not exist");
        return io_error("follow the symbolic link", path, errno);
    }
    struct stat opened {};
    if (::fstat(fd.get(), &opened) != 0) return io_error("write", path, errno);
    if (!S_ISREG(opened.st_mode)) return not_regular(path, opened.st_mode);
    auto real = name_of_open_file(fd.get(), path);
    if (!real) return real.error();
    // The name must still be that file (it could have been renamed since the open).
    struct stat named {};
    if (::stat(real->c_str(), &named) != 0 || named.st_dev != opened.st_dev ||
        named.st_ino != opened.st_ino)
        return geom::make_error_nopath(geom::ErrorCode::internal,
                                       "cannot write '" + path +
                                           "': the file it links to changed while saving");
    return Target{*real, opened};
}

// "<name>.tmp-<pid>" in the target's directory, the name cut (never inside a UTF-8 character)
// so the whole fits in NAME_MAX: a target whose own name is near the limit can still be saved.
struct TempName {
    std::string dir;    // "" = the current directory
    std::string prefix; // "<name cut>.tmp-"
    std::string path;   // dir/prefix<pid>
};

TempName temp_name_for(const std::string& target) {
    const fs::path t(target);
    TempName tn;
    tn.dir = t.parent_path().string();
    std::string name = t.filename().string();
    const std::string pid = std::to_string(::getpid());
    const std::size_t room = NAME_MAX - std::string_view(".tmp-").size() - pid.size();
    if (name.size() > room) {
        std::size_t cut = room;
        while (cut > 0 && (static_cast<unsigned char>(name[cut]) & 0xC0) == 0x80) --cut;
        name.resize(cut);
    }
    tn.prefix = name + ".tmp-";
    tn.path = (tn.dir.empty() ? "" : tn.dir + "/") + tn.prefix + pid;
    return tn;
}

// Temporary files of saves that never finished (their process no longer exists: killed,
// crashed, power lost) are removed before a new save so they do not pile up (each can be tens
// of MB). One whose process still runs, or might (kill says anything but ESRCH), is a save in
// progress and is left alone.
void remove_stale_temporaries(const TempName& tn) {
    const fs::path dir = tn.dir.empty() ? fs::path(".") : fs::path(tn.dir);
    std::error_code ec;
    for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
        const std::string name = it->path().filename().string();
        if (name.size() <= tn.prefix.size() || name.compare(0, tn.prefix.size(), tn.prefix) != 0)
            continue;
        long pid = 0;
        const char* first = name.data() + tn.prefix.size();
        const char* last = name.data() + name.size();
        const auto res = std::from_chars(first, last, pid);
        if (res.ec != std::errc() || res.ptr != last || pid <= 0 || pid == ::getpid() ||
            pid != static_cast<pid_t>(pid))
            continue;
        if (::kill(static_cast<pid_t>(pid), 0) == 0 || errno != ESRCH) continue;
        (void)::unlink(it->path().c_str());
    }
}

bool write_all(int fd, std::string_view bytes) {
    const char* p = bytes.data();
    std::size_t left = bytes.size();
    while (left > 0) {
        const ssize_t n = ::write(fd, p, left);
        if (n < 0) {
            if (errno == EINTR) continue;
            return false;
        }
        if (n == 0) {
            errno = EIO; // a regular file never accepts nothing; do not spin
            return false;
        }
        p += n;
        left -= static_cast<std::size_t>(n);
    }
    return true;
}

geom::Status write_standard_output(std::string_view bytes) {
    if (!write_all(STDOUT_FILENO, bytes)) return io_error("write", "standard output", errno);
    return geom::Ok{};
}

// "N" when `p` is "/dev/fd/N", "/proc/self/fd/N", "/proc/thread-self/fd/N" or
// "/proc/<this pid>/fd/N".
std::optional<int> descriptor_in(const std::string& p) {
    const std::string pid = "/proc/" + std::to_string(::getpid()) + "/fd/";
    for (const std::string& prefix : {std::string("/dev/fd/"), std::string("/proc/self/fd/"),
                                      std::string("/proc/thread-self/fd/"), pid}) {
        if (p.compare(0, prefix.size(), prefix) != 0) continue;
        int n = -1;
        const char* first = p.data() + prefix.size();
        const char* last = p.data() + p.size();
        const auto r = std::from_chars(first, last, n);
        if (r.ec == std::errc() && r.ptr == last && first != last && n >= 0) return n;
    }
    return std::nullopt;
}

// The descriptor of this process that `path` names through /dev/stdout, /dev/fd/N or
// /proc/self/fd/N (links followed one at a time, never through the descriptor's own link), or
// -1. Such a path is the stream itself: `render -o /dev/stdout >> log` appends to log, where
// renaming a new file over what the link points at would replace log.
int own_descriptor_named(const std::string& path) {
    std::string p = path;
    for (int hop = 0; hop < 40 && !p.empty(); ++hop) {
        if (const auto n = descriptor_in(p)) return ::fcntl(*n, F_GETFD) == -1 ? -1 : *n;
        struct stat st {};
        if (::lstat(p.c_str(), &st) != 0 || !S_ISLNK(st.st_mode)) return -1;
        std::string target(PATH_MAX, '\0');
        const ssize_t len = ::readlink(p.c_str(), target.data(), target.size());
        if (len <= 0 || static_cast<std::size_t>(len) >= target.size()) return -1;
        target.resize(static_cast<std::size_t>(len));
        if (target[0] != '/') target = (fs::path(p).parent_path() / target).string();
        p = target;
    }
    return -1;
}

geom::Status write_descriptor(int fd, std::string_view bytes, const std::string& path) {
    if (!write_all(fd, bytes)) return io_error("write", path, errno);
    return geom::Ok{};
}

// Creates the temporary file exclusively (never through a link planted under its name). One
// left by an earlier process with our pid (pids are reused) is ours to replace.
int create_temporary(const std::string& tmp) {
    constexpr int flags = O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC;
    int fd = ::open(tmp.c_str(), flags, 0666);
    if (fd < 0 && errno == EEXIST && ::unlink(tmp.c_str()) == 0)
        fd = ::open(tmp.c_str(), flags, 0666);
    return fd;
}

// The new file takes the old one's permissions, and its owner and group where the system
// allows (root, or a group the user is in); a failed chown is not an error.
geom::Status keep_mode_and_owner(int fd, const struct stat& old, const std::string& tmp) {
    if (::fchmod(fd, old.st_mode & 07777) != 0)
        return io_error("set the permissions of", tmp, errno);
    if (old.st_uid != ::geteuid() || old.st_gid != ::getegid()) {
        if (::fchown(fd, old.st_uid, old.st_gid) != 0)
            (void)::fchown(fd, static_cast<uid_t>(-1), old.st_gid);
        // chown may clear set-id bits; put the mode back.
        (void)::fchmod(fd, old.st_mode & 07777);
    }
    return geom::Ok{};
}

} // namespace

void make_file_size_limit_an_error() {
    ::signal(SIGXFSZ, SIG_IGN);
}

geom::Status check_output_path(const std::string& path) {
    if (path == "-" || own_descriptor_named(path) >= 0) return geom::Ok{};
    auto target = resolve_target(path);
    if (!target) return target.error();
    return geom::Ok{};
}

geom::Status check_output_is_not_input(const std::string& output,
                                       const std::vector<std::string>& inputs) {
    if (output == "-") return geom::Ok{};
    struct stat out {};
    if (::stat(output.c_str(), &out) != 0) return geom::Ok{}; // a new file clashes with nothing
    for (const std::string& input : inputs) {
        struct stat in {};
        if (input.empty() || input == "-" || ::stat(input.c_str(), &in) != 0) continue;
        if (in.st_dev == out.st_dev && in.st_ino == out.st_ino)
            return geom::make_error_nopath(geom::ErrorCode::internal,
                                           "refusing to write '" + output +
                                               "': it is the same file as the input '" + input +
                                               "', which would be lost");
    }
    return geom::Ok{};
}

geom::Status write_file_atomically(const std::string& path, std::string_view bytes) {
    make_file_size_limit_an_error();
    if (path == "-") return write_standard_output(bytes);
    if (const int fd = own_descriptor_named(path); fd >= 0)
        return write_descriptor(fd, bytes, path);
    auto resolved = resolve_target(path);
    if (!resolved) return resolved.error();
    const Target& target = *resolved;
    const TempName tmp = temp_name_for(target.path);
    remove_stale_temporaries(tmp);

    Fd fd(create_temporary(tmp.path));
    // Named after the file asked for: the temporary name would only puzzle (a missing
    // directory, no permission, a full disk are all about the target's directory).
    if (fd.get() < 0) return io_error("write", path, errno);
    auto fail = [&](const char* what, const std::string& name, int err) -> geom::Status {
        ::unlink(tmp.path.c_str());
        return io_error(what, name, err);
    };
    if (target.existing) {
        if (auto kept = keep_mode_and_owner(fd.get(), *target.existing, tmp.path); !kept) {
            ::unlink(tmp.path.c_str());
            return kept;
        }
    }
    if (!write_all(fd.get(), bytes)) return fail("write", path, errno);
    // The data must be on disk before the rename makes it the file.
    if (::fsync(fd.get()) != 0) return fail("write", path, errno);
    if (fd.close_checked() != 0) return fail("write", path, errno);
    if (::rename(tmp.path.c_str(), target.path.c_str()) != 0)
        return fail("replace", target.path, errno);
    // Make the rename itself durable (best effort: some file systems refuse to sync a
    // directory, and the file is complete either way).
    Fd dir(::open(tmp.dir.empty() ? "." : tmp.dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC));
    if (dir.get() >= 0) (void)::fsync(dir.get());
    return geom::Ok{};
}

} // namespace isoparm::scene
