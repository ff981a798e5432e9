// Runs before main (emcc --pre-js), in the module's scope: what the page keeps between visits
// is put back in the in-memory file system first (ui/platform/browser.cpp writes it out).
//
// - The settings (layout, recent files) from local storage into the settings file.
// - The recovery folder (autosaved unsaved work, core/scene/autosave.hpp) mounted on IndexedDB
//   and read back, so the start-up can offer to restore it; main waits for that.
// - ?report=1 in the page's address records the UI report (ui/ui_report.hpp: the named
//   rectangles of panels, menus and handles and facts of the document, rewritten after each
//   frame that changed them); Module.uiReport() returns it parsed, or null before the first
//   frame. The browser test (tests/web) waits on it instead of sleeping.
const isoparmReportPath = '/tmp/isoparm-ui-report.json';
Module['preRun'] = (Module['preRun'] || []).concat([function () {
  if (new URLSearchParams(location.search).get('report')) ENV['ISOPARM_UI_REPORT'] = isoparmReportPath;
  const home = ENV['HOME'] || '/home/web_user';
  try {
    const settings = localStorage.getItem('isoparm.settings');
    if (settings) {
      FS.mkdirTree(home + '/.config/isoparm');
      FS.writeFile(home + '/.config/isoparm/settings.json', settings);
    }
  } catch (e) {
    // No local storage (a private window's policy): default settings.
  }
  const recovery = home + '/.local/state/isoparm';
  FS.mkdirTree(recovery);
  if (typeof indexedDB === 'undefined') return;
  FS.mount(IDBFS, {}, recovery);
  addRunDependency('isoparm-recovery');
  FS.syncfs(true, function (error) {
    if (error) console.warn('isoparm: the stored recovery files could not be read: ' + error);
    removeRunDependency('isoparm-recovery');
  });
}]);
Module['uiReport'] = function () {
  try {
    return JSON.parse(FS.readFile(isoparmReportPath, { encoding: 'utf8' }));
  } catch (e) {
    return null;
  }
};

// The workstation's Ctrl shortcuts (save, open, undo, select all in a field, ...) are its own,
// not the browser's "save page" or "open file": the browser's default is stopped for them.
// Copy, cut and paste keep theirs (the paste event carries the text, web_main.cpp), and so
// do the keys a browser never gives a page (Ctrl+N, Ctrl+T, Ctrl+W) and reload.
window.addEventListener('keydown', function (e) {
  if (!(e.ctrlKey || e.metaKey)) return;
  const key = e.key.toLowerCase();
  if (key.length === 1 && !'cvxrntw'.includes(key)) e.preventDefault();
}, true);
