#!/usr/bin/env node
// The browser build in a real browser: the built page (build-web/) served on 127.0.0.1 and
// loaded in Debian's headless Chromium (WebGL 2 through SwiftShader), driven through
// puppeteer-core as a person drives it. Every wait is on the application's state: the UI
// report the page exposes (Module.uiReport(), ui/ui_report.hpp), its idle flag, a file
// downloaded; never a fixed sleep.
//
//   node tests/web/web_test.js --web build-web --isoparm build/app/isoparm \
//        --compare build/tests/render/compare_png --assets assets --out DIR [--runs N]
//        [--only geom,picture,timings,drag,lesson,files]
//
// Checks, in order (each failure names what was expected and what was seen):
//  1. geom: isoparm-geom.js (geom-example.html) answers every request of assets/requests
//     byte for byte as `isoparm geom` with the baseline kernel (ISOPARM_SIMD=baseline), and a
//     text that is not JSON throws the command line's message.
//  2. picture: fig3b-weight-5 at 1024x768 matches `isoparm render --view workstation` of the
//     same scene (compare_png, tolerance stated below); ?stage=tracing puts the tracing
//     square on the stage.
//  3. drag: a control point dragged in the control-point panel's xy plane moves (Ctrl+S
//     downloads the scene: the point's x and y changed, z did not); the indicator dragged in
//     the tracing square moves to where it was dropped.
//  4. lesson: File > Open lesson... with 00-weights-and-knots, Next and the Right arrow step it;
//     P shows the stop in presentation mode and back.
//  5. files: File > Open... > From this computer... uploads a scene; an edit autosaved into
//     IndexedDB is offered back after a reload, and Restore brings it back.
// Timings (medians of --runs loads and drags) are printed as "figure: ..." lines and written
// to DIR/figures.json: time to first frame after navigation start, and a drag's frame work.
'use strict';

const fs = require('fs');
const http = require('http');
const path = require('path');
const { execFileSync } = require('child_process');

function parseArgs(argv) {
  const args = { runs: 5 };
  for (let k = 2; k < argv.length; k += 2) args[argv[k].replace(/^--/, '')] = argv[k + 1];
  args.runs = Number(args.runs);
  for (const need of ['web', 'isoparm', 'compare', 'assets', 'out'])
    if (!args[need]) throw new Error('missing --' + need);
  return args;
}

class Failure extends Error {}
function check(condition, message) {
  if (!condition) throw new Failure(message);
}
function median(values) {
  const v = [...values].sort((a, b) => a - b);
  return v.length ? (v.length % 2 ? v[(v.length - 1) / 2] : (v[v.length / 2 - 1] + v[v.length / 2]) / 2) : NaN;
}

// A static server for the build folder (.wasm as application/wasm, so it streams).
function serve(root) {
  const types = { '.html': 'text/html', '.js': 'text/javascript', '.wasm': 'application/wasm',
                  '.json': 'application/json', '.data': 'application/octet-stream' };
  const server = http.createServer((req, res) => {
    const name = decodeURIComponent(new URL(req.url, 'http://x').pathname);
    const file = path.join(root, path.normalize(name).replace(/^(\.\.[/\\])+/, ''));
    fs.readFile(file, (err, data) => {
      if (err) {
        res.writeHead(404);
        res.end();
        return;
      }
      res.writeHead(200, { 'Content-Type': types[path.extname(file)] || 'application/octet-stream' });
      res.end(data);
    });
  });
  return new Promise((resolve) => server.listen(0, '127.0.0.1', () => resolve(server)));
}

// The workstation page, driven through its UI report.
class Page {
  constructor(page, base, cdp) {
    this.page = page;
    this.base = base;
    this.cdp = cdp;
  }
  // A fresh visit: the last page left (its autosave on leaving done), then what it kept in the
  // browser (IndexedDB's recovery files, local storage's settings) cleared, so no check meets
  // an offer to restore another check's work.
  async open(query) {
    await this.page.goto('about:blank');
    await this.cdp.send('Storage.clearDataForOrigin',
                        { origin: this.base, storageTypes: 'indexeddb,local_storage' });
    await this.page.goto(this.base + '/index.html?report=1' + (query ? '&' + query : ''));
    // The workstation's 3D view, or the teaching view ?stage= put on the stage.
    await this.waitFor('the first frame', (r) => r.rects &&
                       (r.rects['panel/Drawing'] || Object.keys(r.rects).some((k) => k.startsWith('stage/'))));
    await this.idle();
  }
  report() {
    return this.page.evaluate(() => (window.Module && Module.uiReport ? Module.uiReport() : null));
  }
  // Polls the report until `test` holds (30 s at most), then returns it.
  async waitFor(what, test, timeout = 30000) {
    const end = Date.now() + timeout;
    let last = null;
    for (;;) {
      last = await this.report();
      if (last && test(last)) return last;
      if (Date.now() > end)
        throw new Failure('timed out waiting for ' + what + '; last report: ' +
                          JSON.stringify(last && { facts: last.facts, undo: last.undo, lesson: last.lesson,
                                                   indicator: last.indicator, selected: last.selected }));
      await this.page.evaluate(() => new Promise((r) => requestAnimationFrame(() => r())));
    }
  }
  // Until no frame is due: the picture shows everything that happened.
  async idle() {
    await this.page.waitForFunction(() => Module._isoparm_web_idle && Module._isoparm_web_idle() === 1,
                                    { timeout: 30000, polling: 'raf' });
  }
  async rect(name) {
    const r = await this.waitFor(name + ' on screen', (r) => r.rects && r.rects[name]);
    return r.rects[name];
  }
  // Clicks where `name` is once the page has settled (a popup lays itself out over its first
  // frames: a person clicks what they see, not where it flashed).
  async click(name, fx = 0.5, fy = 0.5) {
    await this.rect(name);
    await this.idle();
    const [x, y, w, h] = await this.rect(name);
    await this.page.mouse.click(x + w * fx, y + h * fy);
  }
  async menu(...labels) {
    for (const label of labels) await this.click('menu/' + label);
  }
  // A press, `steps` moves (one animation frame each, as a hand moves), a release.
  async drag(x, y, dx, dy, steps = 12) {
    const m = this.page.mouse;
    await m.move(x, y);
    await m.down();
    for (let k = 1; k <= steps; ++k) {
      await m.move(x + dx * k / steps, y + dy * k / steps);
      await this.page.evaluate(() => new Promise((r) => requestAnimationFrame(() => r())));
    }
    await m.up();
  }
  frames() {
    return this.page.evaluate(() => (Module.isoparmFrames || []).length);
  }
  // The work of each frame drawn since frame `first`, and the time from each to the next.
  framesFrom(first) {
    return this.page.evaluate((k) => {
      const ends = Module.isoparmFrameEnds.slice(k);
      return { work: Module.isoparmFrames.slice(k), gaps: ends.slice(1).map((t, i) => t - ends[i]) };
    }, first);
  }
}

async function waitForFile(file, timeout = 30000) {
  const end = Date.now() + timeout;
  while (!fs.existsSync(file) || fs.statSync(file).size === 0) {
    if (Date.now() > end) throw new Failure('no download ' + file);
    await new Promise((r) => setTimeout(r, 50));
  }
  return fs.readFileSync(file, 'utf8');
}

// 1. The geometry alone, against the command line.
async function geomModule(browser, base, args) {
  const page = await browser.newPage();
  await page.goto(base + '/geom-example.html');
  await page.waitForFunction(() => window.geom, { timeout: 30000 });
  const dir = path.join(args.assets, 'requests');
  let count = 0;
  for (const name of fs.readdirSync(dir).filter((n) => n.endsWith('.json')).sort()) {
    const text = fs.readFileSync(path.join(dir, name), 'utf8');
    const expected = execFileSync(args.isoparm, ['geom', path.join(dir, name)],
                                  { env: { ...process.env, ISOPARM_SIMD: 'baseline' } }).toString();
    const actual = await page.evaluate((t) => geom.request(t), text);
    check(actual === expected, 'geom ' + name + ': the page answered\n' + actual.slice(0, 300) +
          '\nthe command line\n' + expected.slice(0, 300));
    ++count;
  }
  const thrown = await page.evaluate(() => {
    try {
      geom.request('{nope');
      return null;
    } catch (e) {
      return e.message;
    }
  });
  check(thrown && thrown.includes('not JSON'), 'a text that is not JSON did not throw: ' + thrown);
  await page.close();
  console.log('ok geom: ' + count + ' requests answered as the command line answers them');
}

// 2. The page's picture against the headless renderer's.
const tolerance = { level: 48, fraction: 0.01 };
async function picture(p, args) {
  await p.open('scene=fig3b-weight-5');
  const shot = path.join(args.out, 'web-fig3b-workstation.png');
  await p.page.screenshot({ path: shot });
  const reference = path.join(args.out, 'render-fig3b-workstation.png');
  execFileSync(args.isoparm, ['render', path.join(args.assets, 'scenes', 'fig3b-weight-5.json'),
                              '-o', reference, '--size', '1024x768', '--view', 'workstation']);
  const diff = path.join(args.out, 'diff-fig3b-workstation.png');
  let out;
  try {
    out = execFileSync(args.compare, [reference, shot, '--tolerance', String(tolerance.level),
                                      '--max-fraction', String(tolerance.fraction), '--diff', diff],
                       { stdio: 'pipe' }).toString();
  } catch (e) {
    throw new Failure('the page does not look like isoparm render: ' + e.stdout + e.stderr +
                      ' (pictures: ' + shot + ', ' + reference + ', ' + diff + ')');
  }
  console.log('ok picture: ' + out.trim());
  // A teaching view on the stage, chosen by the page's address as `isoparm --stage` chooses it.
  await p.open('scene=fig3b-weight-5&stage=tracing');
  await p.rect('stage/tracing');
  await p.idle();
  await p.page.screenshot({ path: path.join(args.out, 'web-fig3b-stage-tracing.png') });
  console.log('ok stage: ?stage=tracing shows the tracing square on the stage');
}

// 3. A control point and the indicator, dragged.
async function drags(p, args, downloads, full = false) {
  await p.open('scene=fig3b-weight-5' + (full ? '&gestures=full' : ''));
  let r = await p.report();
  const [i, j] = r.point;
  check(i >= 0 && j >= 0, 'fig3b-weight-5 opens with no control point selected');
  const before = JSON.parse(fs.readFileSync(path.join(args.assets, 'scenes', 'fig3b-weight-5.json')));
  const p0 = before.objects[0].surface.points[i][j];
  const [x, y] = await p.rect('cp/disk0');
  const first = await p.frames();
  await p.drag(x, y, 30, -24, 16);
  r = await p.waitFor('the drag in the undo history', (r) => /move|drag|point/i.test(r.undo) && r.dirty);
  await p.idle();
  // The frames of the moves: the press's and the release's frames aside.
  const drawn = await p.framesFrom(first);
  const dragFrames = { work: drawn.work.slice(1, -1), gaps: drawn.gaps.slice(1, -1) };
  await p.page.screenshot({ path: path.join(args.out, 'web-after-drag.png') });
  // Ctrl+S: the scene is written in the page and downloaded.
  await p.page.keyboard.down('Control');
  await p.page.keyboard.press('s');
  await p.page.keyboard.up('Control');
  const saved = JSON.parse(await waitForFile(path.join(downloads, 'fig3b-weight-5.json')));
  const p1 = saved.objects[0].surface.points[i][j];
  check(p1[0] !== p0[0] && p1[1] !== p0[1], 'the dragged P' + i + j + ' did not move in x and y: ' +
        JSON.stringify(p0) + ' -> ' + JSON.stringify(p1));
  check(Math.abs(p1[2] - p0[2]) < 1e-9, 'an xy drag changed z: ' + JSON.stringify(p0) + ' -> ' +
        JSON.stringify(p1));
  console.log('ok drag: P' + i + j + ' ' + JSON.stringify(p0) + ' -> ' + JSON.stringify(p1) +
              ' (downloaded by Ctrl+S)');
  // The indicator: from where it is to a quarter of the square.
  const [sx, sy, sw, sh] = await p.rect('tracing/square');
  const [u0, v0] = r.indicator;
  const at = (u, v) => [sx + u * sw, sy + (1 - v) * sh]; // v grows upwards
  const [ax, ay] = at(u0, v0);
  const [bx, by] = at(0.25, 0.75);
  await p.drag(ax, ay, bx - ax, by - ay, 10);
  r = await p.waitFor('the indicator near (0.25, 0.75)', (r) =>
    Math.abs(r.indicator[0] - 0.25) < 0.03 && Math.abs(r.indicator[1] - 0.75) < 0.03);
  console.log('ok indicator: (' + u0 + ', ' + v0 + ') -> (' + r.indicator.map((t) => t.toFixed(3)) + ')');
  await p.idle();
  return dragFrames;
}

// 4. A lesson from its first stop to its third.
async function lesson(p, args) {
  await p.open('');
  await p.menu('File', 'Open lesson...');
  await p.waitFor('the name field to take the keyboard', (r) => r.typing);
  await p.page.keyboard.down('Control');
  await p.page.keyboard.press('a');
  await p.page.keyboard.up('Control');
  await p.page.keyboard.type('/isoparm/assets/lessons/00-weights-and-knots.json');
  await p.page.keyboard.press('Enter');
  let r = await p.waitFor('the lesson\'s first stop', (r) => r.lesson && r.lesson.next > 0);
  check(r.lesson.caption.includes('Fig. 3'), 'the first caption is ' + JSON.stringify(r.lesson.caption));
  await p.idle();
  await p.page.screenshot({ path: path.join(args.out, 'web-lesson-start.png') });
  await p.click('lesson/next');
  await p.waitFor('the second stop', (r) => r.undo.includes('w22 = 5'));
  await p.page.keyboard.press('ArrowRight');
  r = await p.waitFor('the third stop', (r) => r.undo.includes('w22 = 0.3'));
  check(r.lesson.caption.includes('0.3'), 'the third caption is ' + JSON.stringify(r.lesson.caption));
  await p.idle();
  await p.page.screenshot({ path: path.join(args.out, 'web-lesson-third-stop.png') });
  // The classroom's view of the same stop: P turns presentation mode on and off.
  await p.page.keyboard.press('p');
  await p.waitFor('presentation mode', (r) => r.presentation);
  await p.idle();
  await p.page.screenshot({ path: path.join(args.out, 'web-lesson-presentation.png') });
  await p.page.keyboard.press('p');
  await p.waitFor('presentation mode off', (r) => !r.presentation);
  console.log('ok lesson: 00-weights-and-knots stepped to its third stop, shown in presentation mode');
}

// 5. Upload, autosave into IndexedDB, restore after a reload.
async function files(p, args) {
  await p.open('autosave=1');
  await p.menu('File', 'Open...');
  const [chooser] = await Promise.all([p.page.waitForFileChooser(), p.click('file/upload')]);
  await chooser.accept([path.join(args.assets, 'scenes', 'fig8-revolution.json')]);
  let r = await p.waitFor('the uploaded vase', (r) => r.objects === 2 && r.rects['objects/vase']);
  console.log('ok upload: fig8-revolution.json opened from "this computer"');
  // An edit, autosaved into IndexedDB within a second (?autosave=1).
  await p.click('objects/shown/vase');
  await p.waitFor('the vase hidden', (r) => r.dirty);
  await p.page.waitForFunction(() => (Module.isoparmStored || 0) > 0, { timeout: 30000 });
  await p.page.reload(); // "leave the page with unsaved changes?" is answered yes
  r = await p.waitFor('the offer to restore', (r) => r.rects && r.rects['recovery/restore']);
  await p.click('recovery/restore');
  r = await p.waitFor('the restored edit', (r) => r.dirty && r.objects === 2 && /restore/i.test(r.undo));
  console.log('ok autosave: the edit came back from IndexedDB after a reload');
}

async function main() {
  const args = parseArgs(process.argv);
  fs.mkdirSync(args.out, { recursive: true });
  const downloads = path.join(args.out, 'downloads');
  fs.rmSync(downloads, { recursive: true, force: true });
  fs.mkdirSync(downloads, { recursive: true });
  const puppeteer = require('puppeteer-core');
  const server = await serve(args.web);
  const base = 'http://127.0.0.1:' + server.address().port;
  const browser = await puppeteer.launch({
    executablePath: args.chromium || '/usr/bin/chromium',
    headless: true,
    args: ['--no-sandbox', '--use-angle=swiftshader', '--enable-unsafe-swiftshader',
           '--window-size=1024,768', '--user-data-dir=' + path.join(args.out, 'profile')],
  });
  const figures = {};
  let page = null;
  const only = (name) => !args.only || args.only.split(',').includes(name);
  try {
    if (only('geom')) await geomModule(browser, base, args);
    page = await browser.newPage();
    await page.setViewport({ width: 1024, height: 768 });
    const errors = [];
    page.on('pageerror', (e) => errors.push(e.message));
    // Leaving a page with unsaved changes asks first (web_main.cpp): the test always leaves.
    page.on('dialog', (d) => d.accept());
    page.on('console', (m) => { if (m.type() === 'error') errors.push(m.text()); });
    page.on('requestfailed', (r) => errors.push('request failed: ' + r.url()));
    page.on('response', (r) => { if (r.status() >= 400) errors.push(r.status() + ' ' + r.url()); });
    const cdp = await page.createCDPSession();
    await cdp.send('Browser.setDownloadBehavior', { behavior: 'allow', downloadPath: downloads });
    const p = new Page(page, base, cdp);

    if (only('picture')) await picture(p, args);
    const firstFrames = [];
    for (let k = 0; k < args.runs && only('timings'); ++k) {
      await p.open('scene=fig3b-weight-5');
      firstFrames.push(await page.evaluate(() => Module.isoparmFirstFrame));
    }
    // Each drag twice, in turn: as the page draws it, and with ?gestures=full (every frame in
    // full, no kept frame: the page before its CPU-rasteriser measures), a paired figure.
    const dragFrames = { work: [], gaps: [] }, fullFrames = { work: [], gaps: [] };
    for (let k = 0; k < args.runs && only('drag'); ++k) {
      for (const [full, into] of [[false, dragFrames], [true, fullFrames]]) {
        for (const f of fs.readdirSync(downloads)) fs.rmSync(path.join(downloads, f));
        const d = await drags(p, args, downloads, full);
        into.work.push(...d.work);
        into.gaps.push(...d.gaps);
      }
    }
    if (only('lesson')) await lesson(p, args);
    if (only('files')) await files(p, args);
    check(errors.length === 0, 'the page reported errors: ' + errors.join('; '));
    figures.first_frame_ms = { median: median(firstFrames), runs: firstFrames };
    figures.drag_frame_ms = { median: median(dragFrames.work), frames: dragFrames.work.length };
    figures.drag_frame_interval_ms = { median: median(dragFrames.gaps), intervals: dragFrames.gaps.length };
    figures.drag_frame_ms_full = { median: median(fullFrames.work), frames: fullFrames.work.length };
    const wasm = fs.readFileSync(path.join(args.web, 'index.wasm'));
    figures.wasm_bytes = wasm.length;
    figures.wasm_gzip_bytes = require('zlib').gzipSync(wasm, { level: 9 }).length;
    fs.writeFileSync(path.join(args.out, 'figures.json'), JSON.stringify(figures, null, 1));
    console.log('figure: time to first frame after navigation start: median ' +
                figures.first_frame_ms.median.toFixed(0) + ' ms of ' + args.runs + ' loads (' +
                firstFrames.map((t) => t.toFixed(0)).join(', ') + ')');
    console.log('figure: frame work while dragging a control point: median ' +
                figures.drag_frame_ms.median.toFixed(1) + ' ms over ' + dragFrames.work.length +
                ' frames of ' + args.runs + ' drags; from one drawn frame to the next: median ' +
                figures.drag_frame_interval_ms.median.toFixed(1) + ' ms; with ?gestures=full: ' +
                figures.drag_frame_ms_full.median.toFixed(1) + ' ms over ' +
                fullFrames.work.length + ' frames');
    console.log('figure: index.wasm ' + figures.wasm_bytes + ' bytes, ' + figures.wasm_gzip_bytes +
                ' gzipped');
  } catch (e) {
    // What the page showed when it failed, beside the other pictures.
    if (page) await page.screenshot({ path: path.join(args.out, 'failure.png') }).catch(() => {});
    throw e;
  } finally {
    await browser.close();
    server.close();
  }
}

main().then(() => console.log('web test: passed'), (e) => {
  console.error('web test: FAILED: ' + (e instanceof Failure ? e.message : e.stack));
  process.exit(1);
});
