#!/usr/bin/env python3
# The real workstation window in a private Xvfb, driven with xdotool as a person drives it:
# shared by the monkey test (random input) and the scenario tests (a teacher's workflows).
# The window tells where its panels, menus and handles are through ISOPARM_UI_REPORT
# (ui/ui_report.hpp), so a scenario clicks on "the curve designer's canvas", not on guessed
# pixels, and fails when a panel stops answering.
import contextlib
import json
import os
import shutil
import subprocess
import sys
import time


# Xvfb chooses a free display number and writes it to the pipe: no race with other X servers
# on the machine (xvfb-run -a can lose one). -noreset: the server would otherwise reset when
# one scenario's window closes, and refuse the next scenario's window while it does.
def start_xvfb(size="1600x1000"):
    read, write = os.pipe()
    proc = subprocess.Popen(["Xvfb", "-displayfd", str(write), "-screen", "0", size + "x24",
                             "-nolisten", "tcp", "-noreset"], pass_fds=(write,),
                            stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    os.close(write)
    number = b""
    with os.fdopen(read, "rb") as f:
        while not number.endswith(b"\n"):
            chunk = f.read(1)
            if not chunk:
                break
            number += chunk
    if not number.strip():
        print("gui: Xvfb did not start", file=sys.stderr)
        proc.kill()
        return None, None
    return proc, ":" + number.decode().strip()


@contextlib.contextmanager
def display(private, size="1600x1000"):
    """A display for the window: a private Xvfb of `size` when `private`, else $DISPLAY.
    Yields the display name, or None when there is none (the caller says so and stops)."""
    xvfb = None
    if private:
        xvfb, name = start_xvfb(size)
        if xvfb:
            os.environ["DISPLAY"] = name
    try:
        yield os.environ.get("DISPLAY") if (xvfb or not private) else None
    finally:
        if xvfb:
            xvfb.terminate()
            xvfb.wait(timeout=10)


def sanitizer_report(text):
    return any(s in text for s in ("AddressSanitizer", "LeakSanitizer", "runtime error:",
                                   "UndefinedBehaviorSanitizer"))


class Failure(Exception):
    pass


class Session:
    """One isoparm window on a copy of `scene` (or an untitled one), with private settings."""

    def __init__(self, isoparm, workdir, scene=None, extra_args=(), report=True):
        self.isoparm = isoparm
        self.work = workdir
        self.scene = None
        if scene:
            self.scene = os.path.join(workdir, os.path.basename(scene))
            shutil.copyfile(scene, self.scene)
        env = dict(os.environ)
        for var, sub in (("HOME", "home"), ("XDG_CONFIG_HOME", "config"),
                         ("XDG_STATE_HOME", "state")):
            os.makedirs(os.path.join(workdir, sub), exist_ok=True)
            env[var] = os.path.join(workdir, sub)
        self.report_path = os.path.join(workdir, "ui-report.json")
        if report:
            env["ISOPARM_UI_REPORT"] = self.report_path
        self.env = env
        self.stderr_path = os.path.join(workdir, "stderr.txt")
        self.stderr = open(self.stderr_path, "w")
        args = [isoparm] + ([self.scene] if self.scene else []) + list(extra_args)
        self.proc = subprocess.Popen(args, env=env, stdout=subprocess.DEVNULL,
                                     stderr=self.stderr)
        self.x0 = self.y0 = 0
        self.w, self.h = 1440, 900

    # --- the window -----------------------------------------------------------------------
    def xdo(self, *args):
        subprocess.run(["xdotool", *map(str, args)], check=False, env=self.env,
                       stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)

    def alive(self):
        return self.proc.poll() is None

    def find_window(self, timeout=60):
        deadline = time.time() + timeout
        while time.time() < deadline:
            if not self.alive():
                return False
            out = subprocess.run(["xdotool", "search", "--onlyvisible", "--name", "isoparm"],
                                 capture_output=True, text=True, env=self.env).stdout.split()
            if out:
                self.window = out[0]
                self.update_geometry()
                self.xdo("windowfocus", "--sync", self.window)
                time.sleep(0.2)
                # The first frames lay the window out; input waits for a layout that holds.
                with contextlib.suppress(Failure):
                    self.settle(timeout=10)
                return True
            time.sleep(0.3)
        return False

    def update_geometry(self):
        geo = subprocess.run(["xdotool", "getwindowgeometry", "--shell", self.window],
                             capture_output=True, text=True, env=self.env).stdout
        vals = dict(line.split("=", 1) for line in geo.split() if "=" in line)
        self.x0, self.y0 = int(vals.get("X", 0)), int(vals.get("Y", 0))
        self.w, self.h = int(vals.get("WIDTH", 1440)), int(vals.get("HEIGHT", 900))

    def screen_size(self):
        out = subprocess.run(["xdotool", "getdisplaygeometry"], capture_output=True, text=True,
                             env=self.env).stdout.split()
        return int(out[0]), int(out[1])

    def screenshot(self, path):
        # ImageMagick's import, where installed (the quick start does not need it).
        if shutil.which("import"):
            subprocess.run(["import", "-window", "root", path], check=False, env=self.env)

    # --- what the window reports ------------------------------------------------------------
    def report(self):
        try:
            with open(self.report_path) as f:
                return json.load(f)
        except (OSError, ValueError):
            return {}

    def nudge(self):
        """A frame is drawn on input only: a harmless motion inside the window asks for one
        (one pixel there and back, so that the pointer ends where it was put: a drag or a
        click after a wait starts on its pixel)."""
        self.xdo("mousemove_relative", "--", 1, 0, "mousemove_relative", "--", -1, 0)

    def frame(self):
        return self.report().get("frame")

    def frames_after(self, since, count=3, timeout=5):
        """Waits until `count` frames have begun after the frame `since`, read after some input
        was sent: the input queue gives ImGui a press, a release or a key per frame, so three
        frames have seen a click. A slow frame (ASan, a loaded machine) makes this wait longer,
        a fast one shorter, where a fixed pause was either too short or wasted. Never fails: a
        later wait_for names what is missing."""
        if since is None:
            time.sleep(0.3)
            return
        deadline = time.time() + timeout
        while time.time() < deadline and self.alive():
            f = self.frame()
            if f is not None and f >= since + count:
                return
            self.nudge()
            time.sleep(0.03)

    def wait_for(self, what, predicate, timeout=20):
        """Waits until predicate(report) is true; returns the report."""
        deadline = time.time() + timeout
        while time.time() < deadline:
            if not self.alive():
                raise Failure(f"the window died while waiting for {what}")
            r = self.report()
            if r and predicate(r):
                return r
            self.nudge()
            time.sleep(0.1)
        raise Failure(f"timed out waiting for {what}; last report: {json.dumps(self.report())[:2000]}")

    def settle(self, timeout=20):
        """Waits until two reports at least two frames apart show the same rectangles and
        font (a new font or mode lays the window out again over a frame or two, and a click
        aimed at the layout before it misses); returns the later report."""
        deadline = time.time() + timeout
        first = None
        while time.time() < deadline:
            if not self.alive():
                raise Failure("the window died while its layout settled")
            r = self.report()
            if r and "frame" in r:
                layout = (r.get("rects"), r.get("font_pixels"), r.get("window"))
                if first is None or layout != first[1]:
                    first = (r["frame"], layout)
                elif r["frame"] >= first[0] + 2:
                    return r
            self.nudge()
            time.sleep(0.1)
        raise Failure(f"the layout did not settle in {timeout} s")

    def rect(self, name, timeout=20):
        r = self.wait_for(f"'{name}' on screen", lambda r: name in r.get("rects", {}), timeout)
        return r["rects"][name]

    def rect_names(self, prefix):
        return [k for k in self.report().get("rects", {}) if k.startswith(prefix)]

    # --- input, in window pixels --------------------------------------------------------------
    def move(self, x, y):
        self.xdo("mousemove", int(self.x0 + x), int(self.y0 + y))
        self.frames_after(self.frame(), 2)

    def after_last_press(self):
        """Presses closer than ImGui's double-click time (0.30 s) would make a double click."""
        time.sleep(max(0.0, getattr(self, "_pressed_at", 0) + 0.4 - time.time()))

    def click(self, x, y, button=1, modifiers=()):
        self.move(x, y)
        self.after_last_press()
        for m in modifiers:
            self.xdo("keydown", m)
        self.xdo("mousedown", button)
        self._pressed_at = time.time()
        time.sleep(0.12)
        self.xdo("mouseup", button)
        for m in modifiers:
            self.xdo("keyup", m)
        self.frames_after(self.frame())

    def click_rect(self, rect, fx=0.5, fy=0.5):
        x, y, w, h = rect
        self.click(x + w * fx, y + h * fy)

    def click_named(self, name, fx=0.5, fy=0.5):
        self.click_rect(self.rect(name), fx, fy)

    def drag(self, x, y, dx, dy, steps=8):
        self.move(x, y)
        self.after_last_press()
        self.xdo("mousedown", 1)
        time.sleep(0.15)
        for k in range(1, steps + 1):
            self.xdo("mousemove", int(self.x0 + x + dx * k / steps),
                     int(self.y0 + y + dy * k / steps))
            time.sleep(0.06)
        time.sleep(0.15)
        self.xdo("mouseup", 1)
        self._pressed_at = time.time()
        self.frames_after(self.frame())

    def key(self, keys):
        self.xdo("key", "--clearmodifiers", keys)
        self.frames_after(self.frame())

    def menu(self, *path):
        """Opens the menu bar's path[0] and picks path[1] (and so on), as a person does."""
        self.click_named("menu/" + path[0])
        for label in path[1:]:
            self.click_named("menu/" + label)

    # --- the document, as saved ---------------------------------------------------------------
    def save(self):
        """Ctrl+S; returns the saved scene (JSON) once the file was rewritten."""
        before = os.stat(self.scene).st_mtime_ns
        self.key("ctrl+s")
        deadline = time.time() + 15
        while time.time() < deadline:
            if os.stat(self.scene).st_mtime_ns != before:
                with open(self.scene) as f:
                    return json.load(f)
            time.sleep(0.2)
        raise Failure("Ctrl+S did not rewrite the scene")

    def quit(self):
        if not self.alive():
            return self.proc.returncode
        self.key("ctrl+q")
        # The window closes, or (unsaved changes) asks first: a scenario's changes are not kept.
        deadline = time.time() + 3
        discard = None
        while time.time() < deadline and self.alive():
            discard = self.report().get("rects", {}).get("unsaved/discard")
            if discard:
                break
            time.sleep(0.1)
        if discard:
            # A new popup is sized over its first frames: click where it comes to rest.
            with contextlib.suppress(Failure):
                discard = self.settle(timeout=5)["rects"].get("unsaved/discard", discard)
            self.click_rect(discard)
        try:
            return self.proc.wait(timeout=15)
        except subprocess.TimeoutExpired:
            self.proc.terminate()
            return self.proc.wait(timeout=10)

    def close(self):
        status = self.quit()
        self.stderr.close()
        text = open(self.stderr_path, errors="replace").read()
        if sanitizer_report(text):
            raise Failure("sanitizer report:\n" + text)
        return status, text
