// Reading input files (scenes, requests) so that nothing given as input can block, abort or
// exhaust memory: a FIFO, a directory, a device or /proc/self/mem is a clean error.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "core/geom/status.hpp"

namespace isoparm::json_io {

// The most any input file or standard input may hold (scenes and `geom` requests alike).
// What a file that is not regular is, for messages: "a directory", "a FIFO", "a character
// device", "a block device", "a socket" (the mode as stat gives it).
const char* file_kind_name(unsigned mode);

inline constexpr std::uintmax_t max_input_bytes = std::uintmax_t{256} << 20;

// Reads the regular file `path` whole. It is opened with O_NONBLOCK (opening a FIFO never
// waits for a writer) and checked with fstat before any read: anything but a regular file is
// refused. Errors: `internal` naming the file and the reason (also a read error such as EIO
// from /proc/self/mem); `limit` when it holds more than `max_bytes` (also if it grows while
// being read).
geom::Expected<std::string> read_input_file(const std::string& path,
                                            std::uintmax_t max_bytes = max_input_bytes);

// Reads an already open descriptor (standard input: a pipe, a terminal or a file) to its end,
// refusing more than `max_bytes` (`limit`). `name` is what messages call it.
geom::Expected<std::string> read_descriptor(int fd, const std::string& name,
                                            std::uintmax_t max_bytes = max_input_bytes);

// What a file on disk was when it was loaded or last saved: enough to tell that someone else
// has written it since (two windows saving the same scene).
struct FileStamp {
    std::uintmax_t device = 0, inode = 0, size = 0;
    std::int64_t modified_ns = 0, changed_ns = 0;
    bool operator==(const FileStamp&) const = default;
};

// The stamp of the file at `path` (links followed), or nothing when it does not exist.
std::optional<FileStamp> stamp_of(const std::string& path);

// True when the file at `path` is no longer the one `known` describes: it was replaced,
// written, removed or created since. No known stamp and no file: unchanged.
bool changed_on_disk(const std::string& path, const std::optional<FileStamp>& known);

} // namespace isoparm::json_io
