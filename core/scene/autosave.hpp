// Autosave and crash recovery: where a document's recovery file lives, writing it atomically,
// finding it again at the next start and discarding it once the work is safe.
#pragma once

#include <chrono>
#include <optional>
#include <string>
#include <vector>

#include "core/doc/document.hpp"
#include "core/geom/status.hpp"

namespace isoparm::scene {

// Recovery files live in one per-user directory, never beside the scene: the scene's folder
// may be read-only, shared or synced, and a student should not find stray files next to
// their work. The directory is $XDG_STATE_HOME/isoparm when XDG_STATE_HOME is an absolute
// path, else $HOME/.local/state/isoparm (the XDG Base Directory default). No HOME either:
// `internal` error.
geom::Expected<std::string> recovery_directory();

// The recovery file of the scene at `for_path` ("" = a document never saved, "untitled"):
// <dir>/untitled.recovery.json, or <dir>/<name>-<hash>.recovery.json for a named scene,
// where <name> is the scene's file name (for people looking in the directory) and <hash> a
// 64-bit FNV-1a of its absolute, normalized path (so two "hill.json" in different folders
// never share a recovery file). The same file however it is named: relative or absolute,
// through "." and ".." (symbolic links are not resolved: the scene may not exist yet).
geom::Expected<std::string> recovery_path(const std::string& for_path);

// Writes `doc` as the recovery file of `for_path` with save_scene (temporary file, fsync,
// rename: a crash during an autosave leaves the previous recovery file intact), creating the
// directory (mode 0700) if needed. Meant for a timer (once a minute while the document has
// unsaved changes). Errors are `internal` with the file and the reason.
geom::Status write_recovery(const doc::Document& doc, const std::string& for_path);

struct RecoveryInfo {
    std::string path;                              // the recovery file (load it with load_scene)
    std::string origin;                            // the scene path it recovers ("" untitled)
    std::chrono::system_clock::time_point written; // when it was last written
    // The scene file's own modification time is later than the recovery file's: the user
    // saved after the last autosave (and discarding failed), so the recovery is likely stale.
    bool older_than_scene = false;
};

// The recovery file of `for_path`, if one exists (a regular file). The caller decides what
// to offer: "restore the unsaved changes from <written>?".
std::optional<RecoveryInfo> find_recovery(const std::string& for_path);

// The recovery files of the given scene paths ("" = untitled), each file once (two spellings
// of one scene name one file), newest first: what a start-up offers to restore. `origin` is the
// candidate as given. The recovery file names hash the path, so only paths the caller knows
// (the scene on the command line, the untitled one, the recent files) can be found.
std::vector<RecoveryInfo> find_recoveries(const std::vector<std::string>& candidates);

// `path` as recovery files name it: absolute and lexically normal ("" stays ""); falls back
// to `path` itself when it cannot be made absolute.
std::string normalized_scene_path(const std::string& path);

// Removes the recovery file of `for_path` (after a successful save, after the user declined
// to restore, or on a clean exit). No file is not an error; failing to remove one is
// `internal`.
geom::Status discard_recovery(const std::string& for_path);

} // namespace isoparm::scene
