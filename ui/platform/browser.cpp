// The browser's files (see files.hpp): uploads copied into the page's in-memory file system,
// downloads made from it, the settings file mirrored in local storage and the recovery folder
// in IndexedDB (mounted and read back before main starts: app/web/web_pre.js).
#include "ui/platform/files.hpp"

#include <emscripten/emscripten.h>

#include <cstdlib>

#include "ui/view/settings.hpp"

namespace isoparm::ui::files {

namespace {

// JavaScript (not C++: clang-format would respace its operators).
// clang-format off
// The browser's file picker; the chosen file goes to /uploads/<its name> and into
// Module.isoparmUploads, and the page's loop is asked for a frame to take it.
EM_JS(void, pick_file, (int purpose, const char* accept), {
    const input = document.createElement('input');
    input.type = 'file';
    input.accept = UTF8ToString(accept);
    input.style.display = 'none';
    input.addEventListener(
        'change', function() {
            const file = input.files && input.files[0];
            input.remove();
            if (!file) return;
            file.arrayBuffer().then(function(buffer) {
                FS.mkdirTree('/uploads');
                const path = '/uploads/' + file.name.split('/').join('_');
                FS.writeFile(path, new Uint8Array(buffer));
                (Module.isoparmUploads = Module.isoparmUploads || []).push([ purpose, path ]);
                Module._isoparm_web_wake();
            });
        });
    document.body.appendChild(input);
    input.click();
});

// The next upload that arrived as "<purpose> <path>" (malloc'd), or null.
EM_JS(char*, next_upload, (), {
    const next = Module.isoparmUploads && Module.isoparmUploads.shift();
    if (!next) return 0;
    const text = next[0] + ' ' + next[1];
    const size = lengthBytesUTF8(text) + 1;
    const out = _malloc(size);
    stringToUTF8(text, out, size);
    return out;
});

// A download of the file at `path`, named as it is; its name goes to Module.isoparmDownloads
// (the browser test reads what was offered).
EM_JS(void, download_file, (const char* path), {
    const p = UTF8ToString(path);
    const name = p.substring(p.lastIndexOf('/') + 1);
    const blob = new Blob([FS.readFile(p)], {
        type:
            'application/octet-stream'
    });
    const link = document.createElement('a');
    link.href = URL.createObjectURL(blob);
    link.download = name;
    document.body.appendChild(link);
    link.click();
    link.remove();
    setTimeout(
        function() { URL.revokeObjectURL(link.href); }, 60000);
    (Module.isoparmDownloads = Module.isoparmDownloads || []).push(name);
});

// The clipboard takes the picture if the browser lets the page write images (Chromium does, on
// a click or key: the menu item or Ctrl+Shift+C); otherwise the status says nothing happened.
EM_JS(void, copy_png, (const char* data, int size), {
    const bytes = HEAPU8.slice(data, data + size);
    if (!navigator.clipboard || typeof ClipboardItem == 'undefined') {
        console.warn('isoparm: this browser does not let a page put pictures on the clipboard');
        return;
    }
    const item = new ClipboardItem({
        'image/png' : new Blob([bytes],
                               {
                                   type:
                                       'image/png'
                               })
    });
    navigator.clipboard.write([item]).catch(
        function(e) { console.warn('isoparm: the clipboard refused the picture: ' + e); });
});

EM_JS(void, store_settings_text, (const char* path), {
    try {
        localStorage.setItem('isoparm.settings',
                             FS.readFile(UTF8ToString(path), {encoding : 'utf8'}));
    } catch (e) {
        // Local storage off (a private window's policy): the settings last as long as the page.
    }
});

// IndexedDB gets the recovery folder's state; a write while one is running is done after it.
EM_JS(void, store_recovery_folder, (), {
    if (Module.isoparmSyncing) {
        Module.isoparmSyncAgain = true;
        return;
    }
    Module.isoparmSyncing = true;
    FS.syncfs(
        false, function done(error) {
            if (error) console.warn('isoparm: the recovery files were not stored: ' + error);
            if (Module.isoparmSyncAgain) {
                Module.isoparmSyncAgain = false;
                FS.syncfs(false, done);
                return;
            }
            Module.isoparmSyncing = false;
            Module.isoparmStored = (Module.isoparmStored || 0) + 1;
        });
});
// clang-format on

} // namespace

bool in_browser() {
    return true;
}

void request_upload(Purpose purpose, const std::string& accept) {
    pick_file(static_cast<int>(purpose), accept.c_str());
}

std::optional<Upload> take_upload() {
    char* text = next_upload();
    if (!text) return std::nullopt;
    const std::string s = text;
    std::free(text);
    const std::size_t space = s.find(' ');
    return Upload{static_cast<Purpose>(std::atoi(s.substr(0, space).c_str())), s.substr(space + 1)};
}

void hand_over(const std::string& path) {
    download_file(path.c_str());
}

void keep_settings() {
    if (const std::string path = settings_path(); !path.empty()) store_settings_text(path.c_str());
}

void keep_recovery() {
    store_recovery_folder();
}

std::string copy_picture(const std::string& png) {
    copy_png(png.data(), static_cast<int>(png.size())); // the browser answers later, if at all
    return "";
}

std::string unavailable(Feature feature) {
    switch (feature) {
    case Feature::quit:
        return "A page cannot close its own browser tab: close the tab instead (unsaved work is "
               "autosaved, and the page offers it back when it opens again).";
    case Feature::animation:
        return "Animations are encoded by FFmpeg, which the browser version does not have: the "
               "desktop program makes GIF and MP4 files (isoparm animate).";
    }
    return "";
}

} // namespace isoparm::ui::files
