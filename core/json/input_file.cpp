// Input files that cannot block, abort or exhaust memory (see input_file.hpp).
#include "core/json/input_file.hpp"

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace isoparm::json_io {

namespace {

geom::Error io_error(const std::string& what, const std::string& path, int err) {
    return geom::make_error_nopath(geom::ErrorCode::internal,
                                   "cannot " + what + " '" + path + "': " + std::strerror(err));
}

std::string mib(std::uintmax_t bytes) {
    return std::to_string(bytes >> 20) + " MiB";
}

geom::Error too_large(const std::string& name, std::uintmax_t max_bytes) {
    return geom::make_error_nopath(geom::ErrorCode::limit,
                                   "'" + name + "' is larger than " + mib(max_bytes) +
                                       "; inputs may be at most " + mib(max_bytes));
}

std::int64_t nanoseconds(const struct timespec& t) {
    return static_cast<std::int64_t>(t.tv_sec) * 1000000000 + t.tv_nsec;
}

} // namespace

namespace {

// Appends what is left of `fd` to `text`, refusing to go past `max_bytes`.
geom::Status append_rest(int fd, const std::string& name, std::uintmax_t max_bytes,
                         std::string& text) {
    char buf[1 << 16];
    for (;;) {
        const ssize_t n = ::read(fd, buf, sizeof buf);
        if (n < 0) {
            if (errno == EINTR) continue;
            return io_error("read", name, errno);
        }
        if (n == 0) return geom::Ok{};
        if (text.size() + static_cast<std::size_t>(n) > max_bytes)
            return too_large(name, max_bytes);
        text.append(buf, static_cast<std::size_t>(n));
    }
}

// Closes a descriptor on every way out, exceptions (std::bad_alloc) included.
struct CloseOnExit {
    int fd;
    ~CloseOnExit() { ::close(fd); }
};

} // namespace

geom::Expected<std::string> read_descriptor(int fd, const std::string& name,
                                            std::uintmax_t max_bytes) {
    std::string text;
    if (auto read = append_rest(fd, name, max_bytes, text); !read) return read.error();
    return text;
}

geom::Expected<std::string> read_input_file(const std::string& path, std::uintmax_t max_bytes) {
    // O_NONBLOCK: opening a FIFO must not wait for a writer; regular files ignore it.
    const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_NOCTTY | O_CLOEXEC);
    if (fd < 0) return io_error("open", path, errno);
    const CloseOnExit closer{fd};
    struct stat st {};
    if (::fstat(fd, &st) != 0) return io_error("read", path, errno);
    if (!S_ISREG(st.st_mode))
        return geom::make_error_nopath(geom::ErrorCode::internal,
                                       "cannot read '" + path + "': it is " +
                                           file_kind_name(st.st_mode) + ", not a regular file");
    if (static_cast<std::uintmax_t>(st.st_size) > max_bytes)
        return geom::make_error_nopath(geom::ErrorCode::limit,
                                       "'" + path + "' is " +
                                           mib(static_cast<std::uintmax_t>(st.st_size)) +
                                           "; inputs may be at most " + mib(max_bytes));
    std::string text;
    text.reserve(static_cast<std::size_t>(st.st_size));
    if (auto read = append_rest(fd, path, max_bytes, text); !read) return read.error();
    return text;
}

std::optional<FileStamp> stamp_of(const std::string& path) {
    struct stat st {};
    if (path.empty() || ::stat(path.c_str(), &st) != 0) return std::nullopt;
    FileStamp s;
    s.device = st.st_dev;
    s.inode = st.st_ino;
    s.size = static_cast<std::uintmax_t>(st.st_size);
    s.modified_ns = nanoseconds(st.st_mtim);
    s.changed_ns = nanoseconds(st.st_ctim);
    return s;
}

bool changed_on_disk(const std::string& path, const std::optional<FileStamp>& known) {
    return stamp_of(path) != known;
}

const char* file_kind_name(unsigned mode) {
    if (S_ISDIR(mode)) return "a directory";
    if (S_ISFIFO(mode)) return "a FIFO";
    if (S_ISCHR(mode)) return "a character device";
    if (S_ISBLK(mode)) return "a block device";
    if (S_ISSOCK(mode)) return "a socket";
    return "not a regular file";
}

} // namespace isoparm::json_io
