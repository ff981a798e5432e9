// The files a user opens and saves, and the files that must outlive a session, reached one way
// on the desktop and another in a browser, behind one interface with two implementations:
// desktop.cpp (the program: paths on disk, which the file dialog lists and writes) and
// browser.cpp (the page: the browser's upload and download around the page's in-memory file
// system, local storage for the settings, IndexedDB for the recovery files). The build
// compiles one of them (ui/CMakeLists.txt); they also answer what the browser cannot do.
#pragma once

#include <optional>
#include <string>

namespace isoparm::ui::files {

// True in the browser: a file to open can come from the user's computer (an upload), and a
// file written for the user leaves the page as a download.
bool in_browser();

// What a file chosen for opening is for.
enum class Purpose { open_scene, open_lesson, import_file, load_points, open_exercise };

// The browser's file picker (`accept`: extensions as in ".json,.txt"). The file chosen is
// copied into the page's file system and comes back from take_upload() at a later frame; no
// file (the picker cancelled) never comes back. The desktop has none (its file dialog lists
// the disk): nothing happens there.
void request_upload(Purpose purpose, const std::string& accept);
struct Upload {
    Purpose purpose;
    std::string path; // in the page's file system, named as the user's file
};
std::optional<Upload> take_upload();

// A file the user asked for was written at `path` (Save, Export, a recording): the browser
// offers it as a download under the path's file name. The desktop has it on disk already.
void hand_over(const std::string& path);

// The settings file was written (ui/view/settings.hpp): the browser keeps it in local storage
// for the next visit. The desktop wrote it to disk already.
void keep_settings();

// A recovery file was written or removed (core/scene/autosave.hpp): the browser stores the
// recovery folder in IndexedDB, so a reload offers to restore. The desktop's are on disk.
void keep_recovery();

// A PNG on the clipboard (Ctrl+Shift+C): the desktop's through xclip or wl-copy (GLFW's
// clipboard holds text only), the browser's through its clipboard API. "" or why not.
std::string copy_picture(const std::string& png);

// What a menu item offers that the browser cannot do, for its greyed item's tooltip: why, in
// words, and what to do instead; "" where it can (always on the desktop).
enum class Feature {
    quit,      // a page cannot close its own tab
    animation, // GIF and MP4 need FFmpeg
};
std::string unavailable(Feature feature);

} // namespace isoparm::ui::files
