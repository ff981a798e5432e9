// Runs before main (emcc --pre-js), in the module's scope.
//
// ?report=1 in the page's address records the UI report (ui/ui_report.hpp: the named rectangles
// of panels, menus and handles, and facts of the document, rewritten after each frame that
// changed them) in the in-memory file system; Module.uiReport() returns it parsed, or null
// before the first frame. The browser test (tests/web) waits on it instead of sleeping.
const isoparmReportPath = '/tmp/isoparm-ui-report.json';
Module['preRun'] = (Module['preRun'] || []).concat([function () {
  if (new URLSearchParams(location.search).get('report')) ENV['ISOPARM_UI_REPORT'] = isoparmReportPath;
}]);
Module['uiReport'] = function () {
  try {
    return JSON.parse(FS.readFile(isoparmReportPath, { encoding: 'utf8' }));
  } catch (e) {
    return null;
  }
};
