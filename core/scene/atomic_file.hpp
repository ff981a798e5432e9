// The one way isoparm writes a file (scenes, autosave, settings, PNGs, every later exporter):
// a complete new file or the old one, never a mix, never a stray temporary file.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "core/geom/status.hpp"

namespace isoparm::scene {

// Writes `bytes` as the file `path`:
// - "-" is standard output (every write checked); so is a path that names one of this
//   process's descriptors (/dev/stdout, /dev/fd/N, /proc/self/fd/N, through links): the
//   stream is written as it was opened (`-o /dev/stdout >> log` appends to log; replacing the
//   file behind it would lose log).
// - Only regular files are written: a directory, FIFO, device or socket (also behind a symbolic
//   link) is refused, so `-o /dev/null` as root never turns /dev/null into a regular file.
// - A symbolic link is followed by the kernel, never by this code: the link is opened, so the
//   kernel's rules (protected_symlinks in sticky world-writable directories) decide, and then
//   the file the kernel opened is replaced. A link to nothing is refused.
// - The bytes go to "<name>.tmp-<pid>" beside the target (the name shortened so it fits in
//   NAME_MAX), created exclusively, with every write, fsync and close checked; only then is it
//   renamed over the target and the directory synced. A replaced file keeps its mode (and its
//   owner where the system allows).
// - A file-size limit (`ulimit -f`) is an error (EFBIG), not a SIGXFSZ that kills the program.
// On any failure: `internal`, one sentence naming the path and the system's reason; the old
// file is untouched and the temporary file is removed.
geom::Status write_file_atomically(const std::string& path, std::string_view bytes);

// Checks `path` can be an output before any work is spent on it: "-", a missing file, or a
// regular file (through a link the kernel lets this user follow). The same rules as above.
geom::Status check_output_path(const std::string& path);

// Refuses an output that is the same file as one of the inputs: compared by device and inode,
// so "scene.json", "./dir/../scene.json" and a link to it are all the same file. Inputs that
// do not exist are skipped; "-" never clashes.
geom::Status check_output_is_not_input(const std::string& output,
                                       const std::vector<std::string>& inputs);

// Turns SIGXFSZ off (a file-size limit then makes write() fail with EFBIG). Called by
// write_file_atomically; main calls it first too, so no write anywhere can be killed by it.
void make_file_size_limit_an_error();

} // namespace isoparm::scene
